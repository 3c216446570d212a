"""Sampled-data systems: a continuous plant under a discrete controller, exact clock
ticks, and the typed errors of discrete variables.

The reference for the loop is independent of the simulator: the DC motor (Egeland &
Gravdahl (3.29)-(3.31)) discretized exactly under a zero-order hold by
``scipy.signal.cont2discrete(..., method="zoh")``, the loop closed by the PI's
difference equation iterated in numpy.  The simulation integrates the motor with the
BDF between the ticks, so the two agree to the integrator's tolerance.
"""
import numpy as np
import pytest
from scipy.signal import cont2discrete

import acausal as ac
from acausal.compiler.frontend.sampled import DiscreteVariableError
from acausal.library.blocks import Constant
from acausal.library.blocks.discrete import Sampler
from acausal.library.electromechanical.examples.sampled_speed_control import (
    J, K, L, R, W_REF, SampledSpeedLoop, Ti, h, k_m)


def exact_loop(n, y_max=np.inf):
    """Speed at t_k = k h, k = 0..n: x_k+1 = Ad x_k + Bd u_k (exact under the hold),
    u_k from the PI's difference equations on e_k = w_ref - w_k."""
    A = np.array([[-R / L, -k_m / L], [k_m / J, 0.0]])      # x = (i, w)
    B = np.array([[1.0 / L], [0.0]])
    Ad, Bd, *_ = cont2discrete((A, B, np.eye(2), np.zeros((2, 1))), h, method="zoh")
    x, I, w, u = np.zeros(2), 0.0, [], []
    for _ in range(n + 1):
        w.append(x[1])
        e = W_REF - x[1]
        v = K * e + I
        y = min(max(v, -y_max), y_max)
        I += K * h / Ti * e + h / Ti * (y - v)               # Tt = Ti
        u.append(y)
        x = Ad @ x + Bd[:, 0] * y
    return np.array(w), np.array(u)


@pytest.fixture(scope="module")
def loops():
    return {b: ac.compile(SampledSpeedLoop(), backend=b) for b in ("numpy", "c")}


N = round(SampledSpeedLoop.stop_time / h)
TICKS = h * np.arange(N + 1)


@pytest.mark.parametrize("y_max", [1e3, 1.0])
def test_dc_motor_speed_loop_matches_the_exact_discretized_loop(loops, y_max):
    """At every sample instant, relative to the signals' range.  The limit 1e3 V is never
    reached; 1 V saturates the controller for the first ticks (k e = 5 V at the start,
    the steady state needs k_m w_ref = 0.5 V), so the anti-windup recovery is part of
    the comparison."""
    w_ref, u_ref = exact_loop(N, y_max)
    runs = {}
    for backend, compiled in loops.items():
        # the tick at t_end would not be taken (a run ends before an event at t_end)
        res = ac.simulate(compiled, t_end=TICKS[-1] + h / 2, t_eval=TICKS, rtol=1e-9,
                          atol=1e-12, parameters={"pi.yMax": y_max, "pi.yMin": -y_max})
        assert res.success, res.message
        w = res["motor.rotor.w"]
        assert np.max(np.abs(w - w_ref)) <= 2e-8 * np.max(np.abs(w_ref))
        assert np.max(np.abs(res["zoh.y.signal"] - u_ref)) <= 2e-8 * np.max(np.abs(u_ref))
        runs[backend] = w
    saturated = np.count_nonzero(u_ref == y_max)
    assert (saturated > 10 and u_ref[-1] < y_max) if y_max == 1.0 else saturated == 0
    # the two backends print the same operations: they agree far below the tolerance
    assert np.max(np.abs(runs["c"] - runs["numpy"])) <= 1e-12 * np.max(np.abs(w_ref))


class Ticker(ac.Component):
    """A slow state and a sampler with a period that is not a binary fraction."""

    x = ac.Variable(start=1.0)
    c = Constant(k=2.0)
    smp = Sampler(samplePeriod=0.1, startTime=0.03)

    def equations(self):
        return [ac.Eq(ac.der(self.x), -0.1 * self.x), ac.connect(self.c.y, self.smp.u)]


class StatelessTicker(ac.Component):
    c = Constant(k=2.0)
    smp = Sampler(samplePeriod=0.1, startTime=0.03)

    def equations(self):
        return [ac.connect(self.c.y, self.smp.u)]


def _ticks_of(res):
    return np.array([float(e) for e in res.events if e.kind == "when"])


@pytest.mark.parametrize("backend", ["numpy", "c"])
def test_clock_ticks_land_on_start_plus_k_period_over_many_periods(backend):
    """The integrator lands on every tick (a state between them, 100 periods); without
    states the run goes from tick to tick, here over 2000 periods."""
    res = ac.simulate(Ticker(), t_end=10.0, rtol=1e-6, backend=backend)
    assert res.success, res.message
    t = _ticks_of(res)
    assert t.size == 100                      # 0.03, 0.13, ..., 9.93
    assert np.all(np.abs(t - (0.03 + 0.1 * np.arange(t.size))) <= 1e-12 * t)
    assert abs(res["x"][-1] - np.exp(-1.0)) <= 1e-5 * np.exp(-1.0)
    t = _ticks_of(ac.simulate(StatelessTicker(), t_end=200.0, backend=backend))
    assert t.size == 2000
    assert np.all(np.abs(t - (0.03 + 0.1 * np.arange(t.size))) <= 1e-12 * t)


# -- bad input: typed errors naming the component and the variable ------------------------
class _Base(ac.Component):
    x = ac.Variable(start=0.0)
    d = ac.Variable(discrete=True, start=0.0)
    T = ac.Parameter(0.1)


def _model(eqs):
    class Bad(_Base):
        def equations(self):
            return [ac.Eq(ac.der(self.x), 1.0)] + eqs(self)
    return Bad()


def test_assigning_a_continuous_variable_is_an_error():
    m = _model(lambda s: [ac.when(ac.sample(0, s.T), ac.assign(s.x, 1.0),
                                  ac.assign(s.d, 1.0))])
    with pytest.raises(DiscreteVariableError, match=r"assign\(x, .*'x' of \(model\) .*not a "
                                                    r"discrete variable"):
        ac.compile(m)


def test_assigning_a_discrete_variable_twice_is_an_error():
    m = _model(lambda s: [ac.when(ac.sample(0, s.T), ac.assign(s.d, 1.0)),
                          ac.when(s.x > 1, ac.assign(s.d, 2.0))])
    with pytest.raises(DiscreteVariableError, match=r"'d' .* assigned twice"):
        ac.compile(m)


def test_a_discrete_variable_no_clause_assigns_is_an_error():
    m = _model(lambda s: [ac.Eq(s.d, s.x)])
    with pytest.raises(DiscreteVariableError, match=r"'d' of \(model\) .*declared discrete, "
                                                    r"but no when-clause assigns it"):
        ac.compile(m)


def test_a_discrete_variable_also_determined_by_an_equation_is_an_error():
    m = _model(lambda s: [ac.when(ac.sample(0, s.T), ac.assign(s.d, s.x)),
                          ac.Eq(s.d, 2 * s.x)])
    with pytest.raises(DiscreteVariableError, match=r"'d' .* an equation outside the "
                                                    r"when-clause determines it"):
        ac.compile(m)


def test_assignments_that_read_each_other_at_one_instant_are_a_loop():
    class Loop(ac.Component):
        x = ac.Variable(start=0.0)
        a = ac.Variable(discrete=True)
        b = ac.Variable(discrete=True)

        def equations(self):
            return [ac.Eq(ac.der(self.x), 1.0),
                    ac.when(ac.sample(0, 0.1), ac.assign(self.a, self.b + 1)),
                    ac.when(ac.sample(0, 0.1), ac.assign(self.b, self.a + self.x))]

    with pytest.raises(DiscreteVariableError, match=r"algebraic loop \((a -> b -> a|b -> a "
                                                    r"-> b)\).*pre\(\)"):
        ac.compile(Loop())


def test_a_self_reference_without_pre_is_a_loop_and_with_pre_a_counter():
    m = _model(lambda s: [ac.when(ac.sample(0, s.T), ac.assign(s.d, s.d + 1))])
    with pytest.raises(DiscreteVariableError, match=r"algebraic loop \(d -> d\)"):
        ac.compile(m)
    m = _model(lambda s: [ac.when(ac.sample(0, s.T), ac.assign(s.d, ac.pre(s.d) + 1))])
    res = ac.simulate(m, t_end=1.0, t_eval=[0.0, 0.05, 0.5, 0.95])
    assert list(res["d"]) == [1.0, 1.0, 6.0, 10.0]   # ticks at 0, 0.1, ..., 0.9


def test_reinit_of_a_discrete_variable_and_assign_of_a_parameter_are_errors():
    m = _model(lambda s: [ac.when(s.x > 1, ac.reinit(s.d, 0.0))])
    with pytest.raises(DiscreteVariableError, match=r"reinit\(d, .*discrete variable"):
        ac.compile(m)
    m = _model(lambda s: [ac.when(ac.sample(0, s.T), ac.assign(s.T, 1.0),
                                  ac.assign(s.d, 1.0))])
    with pytest.raises(DiscreteVariableError, match=r"assign\(T, .*T is a parameter"):
        ac.compile(m)


def test_bad_clocks_are_errors():
    with pytest.raises(ac.InvalidEquation, match="period .* must be positive"):
        ac.sample(0.0, -1.0)
    with pytest.raises(ac.InvalidEquation, match="sample"):
        ac.if_else(ac.sample(0.0, 1.0), 1.0, 0.0)
    with pytest.raises(ac.InvalidValue, match=r"smp.*positive period"):
        ac.simulate(Ticker(smp={"samplePeriod": 0.0}), t_end=1.0)
    with pytest.raises(ac.InvalidValue, match="below its minimum"):
        ac.simulate(Ticker(smp={"samplePeriod": -0.1}), t_end=1.0)


def test_an_assignment_that_makes_another_condition_true_fires_it_at_the_same_instant():
    """The counter reaches 3 at the tick t = 0.2 (ticks at 0, 0.1, 0.2): the clause on
    n > 2.5 fires at that instant, in the next round of the event iteration."""

    class Counter(ac.Component):
        x = ac.Variable(start=0.0)
        n = ac.Variable(discrete=True)
        t_hit = ac.Variable(discrete=True, start=-1.0)

        def equations(self):
            return [ac.Eq(ac.der(self.x), 1.0),
                    ac.when(ac.sample(0, 0.1), ac.assign(self.n, ac.pre(self.n) + 1)),
                    ac.when(self.n > 2.5, ac.assign(self.t_hit, ac.time),
                            ac.reinit(self.x, 10.0))]

    res = ac.simulate(Counter(), t_end=0.5, t_eval=[0.0, 0.15, 0.2, 0.25, 0.45])
    assert list(res["n"]) == [1.0, 2.0, 3.0, 3.0, 5.0]
    assert list(res["t_hit"]) == [-1.0, -1.0, 0.2, 0.2, 0.2]
    assert np.allclose(res["x"], [0.0, 0.15, 10.0, 10.05, 10.25], rtol=1e-9, atol=0)


def test_a_clock_on_a_variable_is_an_error():
    m = _model(lambda s: [ac.when(ac.sample(0, 0.1 + s.x), ac.assign(s.d, 1.0))])
    with pytest.raises(DiscreteVariableError, match=r"sample\(\) are numbers or parameters, "
                                                    r"not variables \(x\)"):
        ac.compile(m)
