"""The MSL's Integer ``mode`` and Boolean ``free``, ``startForward``, ``startBackward`` and
``locked`` of the friction elements (Modelica.Mechanics.*.Interfaces.PartialFriction),
against a closed form: a mass on a brake, pushed by a ramp force F = k t.

Stuck (mode Stuck, locked) while k t <= f0_max = peak mu cgeo fn; it breaks away at
t* = f0_max / k (startForward at that instant, mode still Stuck), then slides forwards
(mode Forward) with the constant friction f0 = mu cgeo fn:

    m v(t) = k (t^2 - t*^2) / 2 - f0 (t - t*)          t >= t*
"""
import numpy as np
import pytest

import acausal as ac
from acausal.library import translational as tr
from acausal.library.blocks import Constant, Ramp

M, K, MU, FN, PEAK = 2.0, 10.0, 0.5, 4.0, 1.5
F0 = MU * FN                       # sliding friction, cgeo = 1
F0_MAX = PEAK * F0                 # most held at rest
T_BREAK = F0_MAX / K


class PushedBrake(ac.Component):
    """A mass on a translational brake, pushed by F = direction k t (the force is k
    times a unit ramp)."""

    direction = ac.Parameter(1.0, description="+1 push forwards, -1 backwards")
    k = ac.Parameter(K, unit="N", description="force per unit of the ramp")
    mass = tr.Mass(m=M, s={"start": 0.0, "fixed": True}, v={"start": 0.0, "fixed": True})
    brake = tr.Brake(fn_max=FN, peak=PEAK, mu_pos=[[0.0, MU]])
    force = tr.Force()
    ramp = Ramp(height=ac.ref("direction"), duration=1.0)
    pressed = Constant(k=1.0)

    def equations(self):
        return [ac.connect(self.force.flange, self.mass.flange_a),
                ac.connect(self.mass.flange_b, self.brake.flange_a),
                ac.Eq(self.force.f, self.k * self.ramp.y),
                ac.connect(self.pressed.y, self.brake.f_normalized)]


def _run(direction):
    model = PushedBrake(direction=direction)
    return ac.simulate(model, t_end=1.0, rtol=1e-8, t_eval=np.linspace(0.0, 1.0, 401))


@pytest.mark.parametrize("direction", [1.0, -1.0])
def test_mode_follows_stick_break_away_and_slide(direction):
    res = _run(direction)
    assert res.success
    t, v = res.t, res["mass.v"]
    mode, locked = res["brake.mode"], res["brake.locked"]
    assert mode.dtype.kind == "i" and locked.dtype == bool
    away = np.abs(t - T_BREAK) > 5e-3
    before, after = away & (t < T_BREAK), away & (t > T_BREAK)
    sliding = 1 if direction > 0 else -1
    assert np.all(mode[before] == 0) and np.all(locked[before])
    assert np.all(mode[after] == sliding) and not np.any(locked[after])
    assert not np.any(res["brake.free"])
    # startForward/startBackward hold only at the break-away instant itself
    assert not np.any(res["brake.startForward"][away])
    assert not np.any(res["brake.startBackward"][away])
    # the break-away is an event at t* and the motion is the closed form
    assert min(abs(float(e) - T_BREAK) for e in res.events) < 1e-8
    ts = np.maximum(t - T_BREAK, 0.0)
    exact = direction * (K * ts * (ts + 2 * T_BREAK) / 2 - F0 * ts) / M
    assert np.max(np.abs(v - exact)) <= 1e-6 * np.max(np.abs(exact))


def test_start_forward_is_the_break_away_mode():
    """At the break-away event, the iteration passes through startForward (a = sa -
    f0_max, w = 0) before w > 0 makes the mode Forward: the event's record says so."""
    res = _run(1.0)
    event = min(res.events, key=lambda e: abs(float(e) - T_BREAK))
    assert abs(float(event) - T_BREAK) < 1e-8
    after = res["brake.mode"][res.t > T_BREAK + 5e-3]
    assert np.all(after == 1)


def test_a_brake_without_normal_force_is_free():
    model = PushedBrake(pressed={"k": 0.0})
    res = ac.simulate(model, t_end=0.5, rtol=1e-8, t_eval=np.linspace(0.0, 0.5, 51))
    assert res.success
    assert np.all(res["brake.free"]) and np.all(res["brake.mode"] == 2)
    assert not np.any(res["brake.locked"] | res["brake.startForward"])
    # free: m v = k t^2 / 2
    exact = K * res.t**2 / 2 / M
    assert np.max(np.abs(res["mass.v"] - exact)) <= 1e-6 * np.max(exact)


class _TornBoolean(ac.Component):
    """A Boolean that reads an unknown of an implicit equation (y^3 + y = x, y solved by
    Newton) which itself reads no Boolean: no loop among the discrete variables."""

    x = ac.Variable(start=0.0, fixed=True)
    y = ac.Variable(start=0.0)
    high = ac.Variable(type=bool)

    def equations(self):
        return [ac.Eq(ac.der(self.x), 1.0),
                ac.Eq(self.y**3 + self.y, self.x),
                ac.Eq(self.high, self.y > 1.0)]


def test_a_boolean_may_read_an_unknown_of_an_implicit_equation():
    res = ac.simulate(_TornBoolean(), t_end=3.0, rtol=1e-8, t_eval=np.linspace(0, 3, 31))
    assert res.success
    # y = 1 where x = t = 2
    assert min(abs(float(e) - 2.0) for e in res.events) < 1e-7
    assert np.array_equal(res["high"], res.t > 2.0)



class _TwoBearings(ac.Component):
    """A constant torque of 5 N.m on an inertia at rest held by two bearings (1 and 2
    N.m): with both locked at t0 their locking torques are determined only in sum (a
    singular, consistent system); the sum, 5 N.m, is more than both hold together."""

    from acausal.library.rotational import BearingFriction, ConstantTorque, Fixed, Inertia

    src = ConstantTorque(tau_constant=5.0)
    J = Inertia(J=2.0, phi={"fixed": True, "start": 0.0}, w={"fixed": True, "start": 0.0})
    b1 = BearingFriction(tau_pos=[[0, 1.0]], useSupport=True)
    b2 = BearingFriction(tau_pos=[[0, 2.0]], useSupport=True)
    fixed = Fixed()

    def equations(self):
        return [ac.connect(self.src.flange, self.J.flange_a),
                ac.connect(self.J.flange_b, self.b1.flange_a, self.b2.flange_a),
                ac.connect(self.b1.support, self.fixed.flange, self.b2.support)]


def test_two_elements_locked_on_one_motion_initialize_and_break_away():
    """Both bearings start locked (w = 0): the split of the 5 N.m between them is
    indeterminate, yet any split exceeds what one of them holds, so both break away at
    t0 and slide: J der(w) = 5 - 1 - 2, w = t (closed form)."""
    res = ac.simulate(_TwoBearings(), t_end=1.0, rtol=1e-8, t_eval=np.linspace(0, 1, 11))
    assert res.success
    assert np.max(np.abs(res["J.w"] - res.t)) <= 1e-6
    assert np.all(res["b1.mode"][1:] == 1) and np.all(res["b2.mode"][1:] == 1)
    assert np.allclose(res["b1.tau"][1:], 1.0) and np.allclose(res["b2.tau"][1:], 2.0)


class _TwoBearingsStopping(ac.Component):
    """An inertia J = 2 kg.m2 turning at 3 rad/s against a constant torque of -1.5 N.m,
    held by two bearings (1 and 2 N.m): it slides to rest, J w' = -1.5 - 1 - 2, and then
    both bearings lock on its one motion and share the 1.5 N.m they hold together (3 N.m
    at most), a split the equations leave indeterminate while they stay locked."""

    from acausal.library.rotational import BearingFriction, ConstantTorque, Fixed, Inertia

    src = ConstantTorque(tau_constant=-1.5)
    J = Inertia(J=2.0, phi={"fixed": True, "start": 0.0}, w={"fixed": True, "start": 3.0})
    b1 = BearingFriction(tau_pos=[[0, 1.0]], useSupport=True)
    b2 = BearingFriction(tau_pos=[[0, 2.0]], useSupport=True)
    fixed = Fixed()

    def equations(self):
        return [ac.connect(self.src.flange, self.J.flange_a),
                ac.connect(self.J.flange_b, self.b1.flange_a, self.b2.flange_a),
                ac.connect(self.b1.support, self.fixed.flange, self.b2.support)]


@pytest.mark.parametrize("loop", ["python", "auto"])
def test_two_elements_locked_on_one_motion_during_integration(loop):
    """Closed form: w = 3 - 2.25 t and phi = 3 t - 1.125 t^2 until t1 = 4/3 s, then at
    rest at phi = 2 rad; the iteration matrix is rank-deficient while both are locked,
    the locking torques sum to the 1.5 N.m they hold, and each stays within its own
    limit (the minimum-norm split)."""
    t = np.linspace(0.0, 3.0, 31)
    res = ac.simulate(_TwoBearingsStopping(), t_end=3.0, rtol=1e-8, t_eval=t,
                      step_loop=loop)
    assert res.success
    t1 = 4.0 / 3.0
    w = np.where(t < t1, 3.0 - 2.25 * t, 0.0)
    phi = np.where(t < t1, 3.0 * t - 1.125 * t ** 2, 2.0)
    assert np.max(np.abs(res["J.w"] - w)) <= 1e-6 * 3.0
    assert np.max(np.abs(res["J.phi"] - phi)) <= 1e-6 * 2.0
    after = t > t1 + 1e-3
    assert np.all(res["b1.mode"][after] == 0) and np.all(res["b2.mode"][after] == 0)
    held = res["b1.tau"][after] + res["b2.tau"][after]
    assert np.allclose(held, held[0]) and abs(abs(held[0]) - 1.5) <= 1e-9
    assert np.all(np.abs(res["b1.tau"][after]) <= 1.0)
    assert np.all(np.abs(res["b2.tau"][after]) <= 2.0)


class _TwoBearingsRamped(ac.Component):
    """An inertia J = 2 kg.m2 at rest held by two bearings (1 and 2 N.m, the same at
    rest and sliding) and driven by a ramp torque k t, k = 10 N.m/s."""

    from acausal.library.blocks import Ramp
    from acausal.library.rotational import BearingFriction, Fixed, Inertia, Torque

    src = Torque()
    ramp = Ramp(height=10.0, duration=1.0)
    J = Inertia(J=2.0, phi={"fixed": True, "start": 0.0}, w={"fixed": True, "start": 0.0})
    b1 = BearingFriction(tau_pos=[[0, 1.0]], useSupport=True)
    b2 = BearingFriction(tau_pos=[[0, 2.0]], useSupport=True)
    fixed = Fixed()

    def equations(self):
        return [ac.connect(self.ramp.y, self.src.tau),
                ac.connect(self.src.flange, self.J.flange_a),
                ac.connect(self.J.flange_b, self.b1.flange_a, self.b2.flange_a),
                ac.connect(self.b1.support, self.fixed.flange, self.b2.support)]


@pytest.mark.parametrize("loop", ["python", "auto"])
def test_two_stuck_elements_on_one_motion_break_away_together(loop):
    """Closed form (Coulomb friction as a complementarity problem): the shaft stays at
    rest while some split of k t holds each bearing within its limit, k t <= 1 + 2, so
    it breaks away at t* = 3/k = 0.3 s, and then both bearings slide (they share the
    motion): J w = k (t^2 - t*^2)/2 - 3 (t - t*).  Before t* the split between them is
    indeterminate; their torques sum to k t, each within its own limit, also at the
    requested times that the step ending at the break-away event spans (they are
    solved in the modes before the event)."""
    k, ts = 10.0, 0.3
    t = np.linspace(0.0, 1.0, 201)
    res = ac.simulate(_TwoBearingsRamped(), t_end=1.0, rtol=1e-8, t_eval=t, step_loop=loop)
    assert res.success
    w = np.where(t > ts, (k * (t ** 2 - ts ** 2) / 2 - 3.0 * (t - ts)) / 2.0, 0.0)
    assert np.max(np.abs(res["J.w"] - w)) <= 1e-6 * np.max(w)
    assert min(abs(float(e) - ts) for e in res.events) <= 1e-7
    rest, slide = t < ts - 1e-3, t > ts + 1e-3
    for b, limit in (("b1", 1.0), ("b2", 2.0)):
        assert np.all(res[f"{b}.mode"][rest] == 0) and np.all(res[f"{b}.mode"][slide] == 1)
        assert np.all(np.abs(res[f"{b}.tau"][rest]) <= limit * (1 + 1e-9))
        assert np.allclose(res[f"{b}.tau"][slide], limit, rtol=1e-9)
    held = res["b1.tau"][rest] + res["b2.tau"][rest]
    assert np.max(np.abs(held - k * t[rest])) <= 1e-9 * 3.0
