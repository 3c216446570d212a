"""Events in models: when/reinit, if-expressions, chattering, steady-state initialization."""
import numpy as np
import sympy as sp
import pytest

import acausal as ac
from acausal.library import rotational as rot
from acausal.library.electrical import Capacitor, Ground, Resistor, StepVoltage

G, E = 9.81, 0.8


class BouncingBall(ac.Component):
    """h'' = -g; when h < 0: v := -e pre(v)."""

    g = ac.Parameter(G)
    e = ac.Parameter(E)
    h = ac.Variable(start=1.0, fixed=True, unit="m")
    v = ac.Variable(start=0.0, fixed=True, unit="m/s")

    def equations(self):
        return [ac.Eq(ac.der(self.h), self.v), ac.Eq(ac.der(self.v), -self.g),
                ac.when(self.h < 0, ac.reinit(self.v, -self.e * ac.pre(self.v)))]


def _bounce_times(n, h0=1.0):
    """Closed form: t1 = sqrt(2 h0 / g), then flights of 2 e^k v1 / g."""
    t1 = np.sqrt(2 * h0 / G)
    v1 = G * t1
    return t1 + np.concatenate([[0.0], np.cumsum(2 * E ** np.arange(1, n) * v1 / G)])


def test_bouncing_ball_bounce_times_match_closed_form():
    res = ac.simulate(BouncingBall(), t_end=3.0, rtol=1e-8, atol=1e-10)
    exact = _bounce_times(6)
    assert len(res.events) == 6
    assert np.max(np.abs(np.array(res.events) - exact)) < 1e-8
    # between bounces the height stays non-negative (to the location tolerance)
    assert res["h"].min() > -1e-8


def test_bouncing_ball_chattering_is_detected_and_partial_result_returned():
    accumulation = _bounce_times(1)[0] * (1 + 2 * E / (1 - E))
    with pytest.warns(RuntimeWarning, match="chattering"):
        res = ac.simulate(BouncingBall(), t_end=10.0, rtol=1e-8, atol=1e-10)
    assert not res.success and "accumulate" in res.message
    assert f"{accumulation:.3f}"[:4] in res.message
    assert accumulation - 0.5 < res.t[-1] < accumulation


def test_a_sliding_mode_is_refused_naming_its_relation():
    """der(x) = -1 above x = 0.5 and +1 below: both sides push x onto 0.5 (a sliding
    mode, reached at t = 0.5 from x(0) = 1).  The run stops there, and the message
    names the relation that switches, in the model's words."""
    class Relay(ac.Component):
        x = ac.Variable(start=1.0, fixed=True)

        def equations(self):
            return [ac.Eq(ac.der(self.x), ac.if_else(self.x > 0.5, -1.0, 1.0))]

    class Loop(ac.Component):
        relay = Relay()

    with pytest.warns(RuntimeWarning, match="chattering"):
        res = ac.simulate(Loop(), t_end=2.0, rtol=1e-8, atol=1e-10)
    assert not res.success and abs(res.t[-1] - 0.5) < 1e-6
    assert "relations switching: relay.x > 0.5" in res.message


def test_reinit_of_a_non_state_is_an_error_naming_it():
    class Bad(ac.Component):
        x = ac.Variable(start=0.0, fixed=True)
        y = ac.Variable()

        def equations(self):
            return [ac.Eq(ac.der(self.x), 1.0), ac.Eq(self.y, 2 * self.x),
                    ac.when(self.x > 1, ac.reinit(self.y, 0.0))]

    with pytest.raises(ac.ModelError, match=r"reinit\(y.*not a state"):
        ac.compile(Bad())


class GearedReinit(ac.Component):
    """A 2 N·m torque on a motor inertia (0.01 kg m2), an ideal gear n = 4 and a load
    inertia (0.5 kg m2), from rest; at t = 0.5 s the load speed is reset to 0.  The
    structural state choice would put the states on the motor side; a variable that a
    when-clause re-initializes is made a state instead."""

    torque = rot.ConstantTorque(tau_constant=2.0)
    motor = rot.Inertia(J=0.01)
    gear = rot.IdealGear(ratio=4.0)
    load = rot.Inertia(J=0.5)

    def equations(self):
        return [ac.connect(self.torque.flange, self.motor.flange_a),
                ac.connect(self.motor.flange_b, self.gear.flange_a),
                ac.connect(self.gear.flange_b, self.load.flange_a),
                ac.when(ac.time > 0.5, ac.reinit(self.load.w, 0.0))]


def test_reinit_behind_a_gear_makes_the_load_speed_a_state():
    """Load acceleration n tau / (J_load + n^2 J_motor) = 12.12 rad/s2 before and after
    the reset, so w_load(1) = 12.12 * 0.5 and w_motor = n w_load."""
    assert "load.w" in ac.compile(GearedReinit()).report.states
    res = ac.simulate(GearedReinit(), t_end=1.0, rtol=1e-8)
    assert res.success and np.allclose(res.events, [0.5])
    a = 4.0 * 2.0 / (0.5 + 16 * 0.01)
    assert abs(res["load.w"][-1] - 0.5 * a) < 1e-6 * 0.5 * a
    assert abs(res["motor.w"][-1] - 4 * 0.5 * a) < 1e-6 * 2 * a
    assert np.max(np.abs(res["motor.w"] - 4 * res["load.w"])) < 1e-9 * 4 * a


class DelayedStep(ac.Component):
    """RC circuit switched on at t = 0.05 s (an if-expression in time)."""

    src = StepVoltage(V=2.0, startTime=0.05)
    R1 = Resistor(R=1e3)
    C1 = Capacitor(C=1e-5)
    gnd = Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.R1.p), ac.connect(self.R1.n, self.C1.p),
                ac.connect(self.C1.n, self.src.n, self.gnd.p)]


def test_step_source_event_is_located_and_response_exact():
    t = np.linspace(0, 0.1, 201)
    res = ac.simulate(DelayedStep(), t_end=0.1, rtol=1e-8, t_eval=t)
    assert any(abs(te - 0.05) < 1e-9 * 0.1 for te in res.events)    # of t_end; exact
    exact = np.where(t >= 0.05, 2.0 * (1 - np.exp(-(t - 0.05) / 1e-2)), 0.0)
    assert np.max(np.abs(res["C1.v"] - exact)) < 1e-5 * 2.0


class JumpThenSwitch(ac.Component):
    """u jumps at t = 0.5; der(x) switches on u > 0, a relation that never crossed zero."""

    x = ac.Variable(start=0.0, fixed=True)
    u = ac.Variable()

    def equations(self):
        return [ac.Eq(self.u, ac.if_else(ac.time >= 0.5, 1.0, 0.0)),
                ac.Eq(ac.der(self.x), ac.if_else(self.u > 0, 1.0, 0.0))]


def test_relation_on_a_variable_that_jumps_at_an_event():
    res = ac.simulate(JumpThenSwitch(), t_end=1.0, rtol=1e-8)
    assert res["x"][-1] == pytest.approx(0.5, abs=1e-9)


class ChainedRelations(ac.Component):
    """z depends on a relation of y, which depends on a relation of time."""

    y = ac.Variable()
    z = ac.Variable()
    w = ac.Variable(start=0.0, fixed=True)

    def equations(self):
        return [ac.Eq(self.y, ac.if_else(ac.time > 0.5, 2, 0)),
                ac.Eq(self.z, ac.if_else(self.y > 1, 1, 0)),
                ac.Eq(ac.der(self.w), self.z)]


def test_output_points_see_consistent_modes():
    res = ac.simulate(ChainedRelations(), t_end=1.0, t_eval=[0, 0.25, 0.75, 1.0])
    assert list(res["z"]) == [0, 0, 1, 1]     # exact: a branch's value, not solved for
    assert res["w"][-1] == pytest.approx(0.5, abs=1e-9)


class SqrtUntilFull(ac.Component):
    """p' = sqrt(1 - p) while p < 1: the dense output overshoots p = 1 when locating
    the event, where sqrt(1 - p) is undefined; that must not abort the run."""

    p = ac.Variable(start=0.0, fixed=True)

    def equations(self):
        return [ac.Eq(ac.der(self.p), ac.if_else(self.p < 1, sp.sqrt(1 - self.p), 0))]


def test_function_outside_its_domain_is_not_a_crash():
    res = ac.simulate(SqrtUntilFull(), t_end=3.0, rtol=1e-8, t_eval=[0.0, 1.0, 3.0])
    # p = 1 - (1 - t/2)^2 until t = 2, then p = 1
    assert res.success and res["p"][1] == pytest.approx(0.75, rel=1e-6)
    assert res["p"][-1] == pytest.approx(1.0, abs=1e-9)


class Kinks(ac.Component):
    """x' = 1; y' = |x - 0.4|; z' = max(0, time - 0.3) (Modelica: abs and max make events)."""

    x = ac.Variable(start=0.0, fixed=True)
    y = ac.Variable(start=0.0, fixed=True)
    z = ac.Variable(start=0.0, fixed=True)
    q = ac.Variable(start=0.0, fixed=True)

    def equations(self):
        return [ac.Eq(ac.der(self.x), 1.0),
                ac.Eq(ac.der(self.y), sp.Abs(self.x - 0.4)),
                ac.Eq(ac.der(self.z), sp.Max(0, ac.time - 0.3)),
                ac.Eq(ac.der(self.q), ac.no_event(sp.Abs(self.x - 0.7)))]


def test_abs_and_max_kinks_are_events_and_no_event_suppresses_them():
    res = ac.simulate(Kinks(), t_end=1.0, rtol=1e-10, atol=1e-12, t_eval=[0.0, 1.0])
    events = np.array(res.events)
    t_end = 1.0                                     # event times judged on the run's span
    assert np.min(np.abs(events - 0.4)) < 1e-10 * t_end         # a state event, located
    assert np.min(np.abs(events - 0.3)) < 1e-12 * t_end         # a time event: exact
    assert np.min(np.abs(events - 0.7)) > 1e-3                   # no event under no_event
    assert res["y"][-1] == pytest.approx(0.4**2 / 2 + 0.6**2 / 2, abs=1e-9)
    assert res["z"][-1] == pytest.approx(0.7**2 / 2, abs=1e-9)
    assert res["q"][-1] == pytest.approx(0.7**2 / 2 + 0.3**2 / 2, abs=1e-6)


def test_no_event_keeps_if_expressions_from_making_events():
    class Ramp(ac.Component):
        x = ac.Variable(start=0.0, fixed=True)
        y = ac.Variable()
        w = ac.Variable(start=0.0, fixed=True)

        def equations(self):
            return [ac.Eq(ac.der(self.x), 1.0),
                    ac.Eq(self.y, ac.no_event(ac.if_else(self.x > 0.5, 1.0, 0.0))),
                    ac.Eq(ac.der(self.w), self.y)]

    compiled = ac.compile(Ramp())
    assert compiled.n_roots == 0
    res = ac.simulate(compiled, t_end=1.0, rtol=1e-8, t_eval=[0.25, 1.0])
    assert list(res["y"]) == [0.0, 1.0] and res.events == []   # branch values: exact
    assert res["w"][-1] == pytest.approx(0.5, abs=1e-3)   # integrated across the jump


class ThresholdUnderNoEvent(ac.Component):
    """y = if x > no_event(|1 - time|) then -1 else 1 with x = time: the relation is an
    event (x crosses its threshold at t = 0.5), its threshold's kink at t = 1 is not."""

    x = ac.Variable(start=0.0, fixed=True)
    y = ac.Variable()
    w = ac.Variable(start=0.0, fixed=True)

    def equations(self):
        return [ac.Eq(ac.der(self.x), 1.0),
                ac.Eq(self.y, ac.if_else(self.x > ac.no_event(sp.Abs(1 - ac.time)), -1, 1)),
                ac.Eq(ac.der(self.w), ac.no_event(sp.Abs(1 - ac.time)))]


def test_a_relation_with_no_event_in_its_operand_is_an_event():
    compiled = ac.compile(ThresholdUnderNoEvent())
    assert compiled.n_roots == 1                 # x > ..., not the kink of the abs
    t = np.array([0.25, 0.49, 0.51, 1.5])
    res = ac.simulate(compiled, t_end=1.5, rtol=1e-10, atol=1e-12, t_eval=t)
    assert list(res["y"]) == [1.0, 1.0, -1.0, -1.0]
    events = np.array(res.events)
    assert len(events) == 1 and abs(events[0] - 0.5) < 1e-9
    # w' = |1 - t| integrated straight across its kink: 1/2 + 1/8
    assert res["w"][-1] == pytest.approx(0.625, abs=1e-6)


class ParametersUnderNoEvent(ac.Component):
    """no_event of parameters alone (a value and an equation): x' = |k|, c = |k|."""

    k = ac.Parameter(-2.0)
    c = ac.Parameter(lambda s: ac.no_event(sp.Abs(s.k)))
    x = ac.Variable(start=0.0, fixed=True)
    v = ac.Variable()

    def equations(self):
        return [ac.Eq(ac.der(self.x), ac.no_event(sp.Abs(self.k))), ac.Eq(self.v, self.c)]


def test_no_event_of_parameters_alone_is_their_value():
    res = ac.simulate(ParametersUnderNoEvent(), t_end=1.0, rtol=1e-9, t_eval=[0.0, 1.0])
    assert res["x"][-1] == pytest.approx(2.0, rel=1e-9)
    assert list(res["v"]) == [2.0, 2.0]
    res = ac.simulate(ParametersUnderNoEvent(), t_end=1.0, rtol=1e-9, t_eval=[0.0, 1.0],
                      parameters={"k": 3.0})
    assert res["x"][-1] == pytest.approx(3.0, rel=1e-9)


class ZeroUnderNoEvent(ac.Component):
    """x = no_event(k y) with k = 0 a constant: x is the structural zero."""

    k = 0
    x = ac.Variable()
    y = ac.Variable(start=1.0, fixed=True)

    def equations(self):
        return [ac.Eq(ac.der(self.y), -self.y), ac.Eq(self.x, ac.no_event(self.k * self.y))]


def test_no_event_of_a_structural_zero_is_zero():
    res = ac.simulate(ZeroUnderNoEvent(), t_end=1.0, rtol=1e-9, t_eval=[0.0, 1.0])
    assert list(res["x"]) == [0.0, 0.0]
    assert res["y"][-1] == pytest.approx(np.exp(-1.0), rel=1e-8)


class GuardedDivision(ac.Component):
    """v = if x < 1e-15 then 1e-15 else x; y = 1/v, with x = 0 held (x' = 0) until a
    clause restarts another state at t = 0.5: x sits at round-off distance from the
    threshold but does not cross it, so the relation holds (0 < 1e-15) and y = 1e15."""

    x = ac.Variable(start=0.0, fixed=True)
    s = ac.Variable(start=0.0, fixed=True)
    v = ac.Variable()
    y = ac.Variable()

    def equations(self):
        return [ac.Eq(ac.der(self.x), 0), ac.Eq(ac.der(self.s), 1),
                ac.Eq(self.v, ac.if_else(self.x < 1e-15, 1e-15, self.x)),
                ac.Eq(self.y, 1 / self.v),
                ac.when(self.s > 0.5, ac.reinit(self.s, 0))]


def test_a_relation_near_its_threshold_takes_the_side_its_value_says():
    res = ac.simulate(GuardedDivision(), t_end=1.0, rtol=1e-8, t_eval=[0.0, 0.25, 0.75, 1.0])
    assert res.success and len(res.events) == 1
    assert list(res["v"]) == [1e-15] * 4
    assert list(res["y"]) == pytest.approx([1e15] * 4, rel=1e-15)


class RestingAtZero(ac.Component):
    """v + v^3 = 1e-20 (-1 if v > 0, else 1), v solved by Newton at initialization: a
    stuck friction element's speed, zero but for round-off.  Each side of the relation
    puts the solution a hair on the other side, both within the relation's zero band,
    so either value is consistent: the relation keeps the value it was solved with (v
    > 0 false at the start value 0) and v = 1e-20, instead of the two alternating."""

    x = ac.Variable(start=1.0, fixed=True)
    v = ac.Variable(start=0.0)

    def equations(self):
        return [ac.Eq(ac.der(self.x), -self.x),
                ac.Eq(self.v + self.v ** 3, 1e-20 * ac.if_else(self.v > 0, -1.0, 1.0))]


def test_a_relation_solved_to_round_off_of_its_threshold_keeps_its_value_at_initialization():
    res = ac.simulate(RestingAtZero(), t_end=1.0, rtol=1e-8, t_eval=[0.0, 0.5, 1.0])
    assert res.success
    assert list(res["v"]) == pytest.approx([1e-20] * 3, rel=1e-12)
    assert list(res["x"]) == pytest.approx(np.exp(-np.array([0.0, 0.5, 1.0])), rel=1e-6)


class TwoFloorsOfOneRamp(ac.Component):
    """y = floor(x) + floor(2 x), x = time: floor(2 x) steps at 0.5, 1, 1.5 and floor(x)
    at 1 too, so the run has three event instants, one of them two items at once."""

    x = ac.Variable(start=0.0, fixed=True)
    y = ac.Variable()

    def equations(self):
        return [ac.Eq(ac.der(self.x), 1), ac.Eq(self.y, sp.floor(self.x) + sp.floor(2 * self.x))]


def test_items_crossing_at_one_instant_make_one_event():
    t = np.array([0.25, 0.75, 1.25, 1.75])
    res = ac.simulate(TwoFloorsOfOneRamp(), t_end=1.8, rtol=1e-8, t_eval=t)
    events = np.array(res.events)
    assert len(events) == 3 and np.max(np.abs(events - [0.5, 1.0, 1.5])) < 1e-8
    assert list(res["y"]) == [0, 1, 3, 4]


class SawOfAnAlias(ac.Component):
    """y = mod(u, 1) with u = x an alias of the state x' = 1: the frozen floor value reads
    x once alias elimination has removed u; y is the sawtooth mod(t, 1)."""

    x = ac.Variable(start=0.0, fixed=True)
    u = ac.Variable()
    y = ac.Variable()

    def equations(self):
        return [ac.Eq(ac.der(self.x), 1.0), ac.Eq(self.u, self.x),
                ac.Eq(self.y, sp.Mod(self.u, 1.0))]


def test_a_floor_of_an_eliminated_alias_reads_its_representative():
    res = ac.simulate(SawOfAnAlias(), t_end=2.5, rtol=1e-8)
    assert res.success
    assert np.max(np.abs(np.array(res.events) - [1.0, 2.0])) < 1e-6
    inside = np.abs(np.mod(res.t, 1.0) - 0.5) < 0.49      # away from the jumps
    assert np.max(np.abs(res["y"][inside] - np.mod(res.t[inside], 1.0))) < 1e-9
