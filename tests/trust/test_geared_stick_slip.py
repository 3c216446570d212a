"""Stick-slip behind a gear: a DC motor with a PID positions a load through an ideal gear
against Karnopp friction with F_s = F_c (Coulomb friction that sticks).

Drive data (Egeland & Gravdahl 3.3, the library's example motor): R = 1 Ohm,
L = 1 mH, k = 0.05 N m/A, J_m = 1e-4 kg m2; gear n = 10 (motor turns n times the
load), load J_L = 0.01 kg m2, so J_eff = J_L + n^2 J_m = 0.02 kg m2 on the load shaft;
``KarnoppFriction`` F_c = F_s = 0.2 N m from the housing (flange_a) to the load
(flange_b), band dv = 1e-9 rad/s.  PID on the load angle: k_p = 20 V/rad, T_i = 0.5 s,
T_d = 0.05 s, N_d = 10, output limited to +-24 V (an amplifier).

The physics every run must show:

(a) friction never delivers power: tau w >= 0 for the friction element;
(b) while the torque the rest of the system applies to the load is at most F_s in
    magnitude, a load at rest stays at rest (w = 0);
(c) coasting with no drive from w_0 = -1 or +1 rad/s: the kinetic energy never
    increases, and the load stops at t_stop = J_eff |w_0| / F_c = 0.1 s and stays;
(d) a ramp set point runs to the end.

Every model is declared twice, the friction element before the load and after it: the
order of declarations must not change the answer.

References: the closed form for (c); for the driven runs a mode-by-mode integration
of the hand-written equations by solve_ivp with events (``_stick_slip_reference``).
The energy audit of a friction run must book the friction as dissipation (>= 0), not
as a source.
"""
import numpy as np
import pytest

import acausal as ac
from acausal.library import electrical as el
from acausal.library import rotational as rot
from acausal.library.blocks import PID, Feedback, Ramp, Step
from acausal.library.electromechanical import DCMotor
from acausal.library.friction.rotational import KarnoppFriction

from ._stick_slip_reference import Drive, simulate_drive

D = Drive()
T_STOP = D.J_eff * 1.0 / D.F_c


def _model(name, parts, connections, order):
    """A Component class with the given parts declared in ``order`` ("friction first"
    or "load first"): the answer must not depend on the order of declarations."""
    names = list(parts)
    if order == "friction first":
        names.sort(key=lambda k: k != "friction")
    else:
        names.sort(key=lambda k: k != "load")
    namespace = {k: parts[k]() for k in names}
    namespace["equations"] = lambda self: connections(self)
    namespace["__doc__"] = f"{name} ({order})"
    return type(name, (ac.Component,), namespace)


def coasting_gear_train(order):
    """Motor rotor (unpowered) - ideal gear - load on Karnopp friction."""
    parts = {"motor": lambda: rot.Inertia(J=D.J_m),
             "gear": lambda: rot.IdealGear(ratio=D.n),
             "load": lambda: rot.Inertia(J=D.J_L, phi={"start": 0.0, "fixed": True},
                                         w={"start": -1.0, "fixed": True}),
             "friction": lambda: KarnoppFriction(F_c=D.F_c, F_s=D.F_c, dv=1e-9),
             "housing": rot.Fixed}

    def connections(m):
        return [ac.connect(m.motor.flange_b, m.gear.flange_a),
                ac.connect(m.gear.flange_b, m.load.flange_a),
                ac.connect(m.load.flange_b, m.friction.flange_b),
                ac.connect(m.friction.flange_a, m.housing.flange)]
    return _model("CoastingGearTrain", parts, connections, order)


def coasting_inertia(order):
    """The same train reflected to the load shaft: one inertia J_eff."""
    parts = {"load": lambda: rot.Inertia(J=D.J_eff, phi={"start": 0.0, "fixed": True},
                                         w={"start": -1.0, "fixed": True}),
             "friction": lambda: KarnoppFriction(F_c=D.F_c, F_s=D.F_c, dv=1e-9),
             "housing": rot.Fixed}

    def connections(m):
        return [ac.connect(m.load.flange_b, m.friction.flange_b),
                ac.connect(m.friction.flange_a, m.housing.flange)]
    return _model("CoastingInertia", parts, connections, order)


def positioner(order, set_point):
    """PID on the load angle - amplifier - DC motor - gear - load on Karnopp friction."""
    parts = {"set_point": set_point,
             "error": Feedback,
             "pid": lambda: PID(k=D.k_p, Ti=D.T_i, Td=D.T_d, Nd=D.N_d, yMax=D.u_max,
                                yMin=-D.u_max),
             "amplifier": el.SignalVoltage,
             "ground": el.Ground,
             "motor": lambda: DCMotor(R=D.R, L=D.L, k=D.k, J=D.J_m),
             "gear": lambda: rot.IdealGear(ratio=D.n),
             "load": lambda: rot.Inertia(J=D.J_L, phi={"start": 0.0, "fixed": True},
                                         w={"start": 0.0, "fixed": True}),
             "friction": lambda: KarnoppFriction(F_c=D.F_c, F_s=D.F_c, dv=1e-9),
             "housing": rot.Fixed,
             "angle": rot.AngleSensor}

    def connections(m):
        return [ac.connect(m.set_point.y, m.error.u1),
                ac.connect(m.angle.phi, m.error.u2),
                ac.connect(m.error.y, m.pid.u),
                ac.connect(m.pid.y, m.amplifier.v),
                ac.connect(m.amplifier.p, m.motor.p),
                ac.connect(m.amplifier.n, m.motor.n, m.ground.p),
                ac.connect(m.motor.flange, m.gear.flange_a),
                ac.connect(m.gear.flange_b, m.load.flange_a, m.angle.flange),
                ac.connect(m.load.flange_b, m.friction.flange_b),
                ac.connect(m.friction.flange_a, m.housing.flange)]
    return _model("GearedPositioner", parts, connections, order)


ORDERS = ("friction first", "load first")


def _friction_power_ok(res):
    power = res["friction.tau"] * res["friction.w"]
    scale = D.F_c * max(np.max(np.abs(res["friction.w"])), 1e-300)
    return np.min(power) >= -1e-9 * scale, np.min(power)


# -- coasting ---------------------------------------------------------------------------------
COASTING = {"geared": coasting_gear_train, "single inertia": coasting_inertia}


@pytest.fixture(scope="module",
                params=[(m, o, w0) for m in sorted(COASTING) for o in ORDERS for w0 in (-1.0, 1.0)],
                ids=lambda p: f"{p[0]}, {p[1]}, w0={p[2]:+g}")
def coasting(request):
    name, order, w0 = request.param
    model = COASTING[name](order)(load={"w": {"start": w0, "fixed": True}})
    t = np.linspace(0.0, 2 * T_STOP, 400)         # no output point at the stop itself
    return w0, model, ac.simulate(model, t_end=2 * T_STOP, rtol=1e-8, t_eval=t)


def test_coasting_runs_to_the_end(coasting):
    _, _, res = coasting
    assert res.success, res.message
    assert res.t[-1] == pytest.approx(2 * T_STOP)


def test_coasting_kinetic_energy_never_increases(coasting):
    w0, _, res = coasting
    kinetic = 0.5 * D.J_eff * res["load.w"] ** 2
    assert kinetic[0] == pytest.approx(0.5 * D.J_eff * w0**2, rel=1e-12)
    assert np.max(np.diff(kinetic)) <= 1e-9 * kinetic[0]


def test_coasting_stops_when_the_closed_form_says_and_stays(coasting):
    w0, _, res = coasting
    assert res.success, res.message
    t, w = res.t, res["load.w"]
    sliding = t < T_STOP - 1e-6
    exact = w0 - np.sign(w0) * D.F_c / D.J_eff * t[sliding]
    assert np.max(np.abs(w[sliding] - exact)) < 1e-6 * abs(w0)
    assert np.max(np.abs(w[t > T_STOP + 1e-6])) <= 1e-9 * abs(w0)
    assert res["load.phi"][-1] == pytest.approx(0.5 * w0 * T_STOP, rel=1e-6)


def test_coasting_friction_never_delivers_power(coasting):
    _, _, res = coasting
    ok, worst = _friction_power_ok(res)
    assert ok, f"friction power down to {worst:.3g} W"


def test_energy_audit_books_friction_as_dissipation(coasting):
    """The audit (``EnergyBalance.dissipated`` / ``.sources``, keyed by component path)
    must list the friction element among the dissipative ones, with a power >= 0 that is
    its tau w, and the balance must close."""
    _, model, res = coasting
    assert res.success, res.message
    audit = ac.energy_balance(res, model)
    assert "friction" in audit.dissipated and "friction" not in audit.sources
    p = np.asarray(audit.dissipated["friction"])
    scale = D.F_c * np.max(np.abs(res["friction.w"]))
    assert np.min(p) >= -1e-9 * scale
    assert np.max(np.abs(p - res["friction.tau"] * res["friction.w"])) < 1e-6 * scale
    assert np.max(np.abs(audit.residual)) < 1e-6 * scale


# -- driven -----------------------------------------------------------------------------------
DRIVEN = {"step": (lambda: Step(height=1.0), lambda t: 1.0, ()),
          "ramp": (lambda: Ramp(height=1.0, duration=1.0), lambda t: min(t, 1.0), (1.0,))}
T_DRIVE = 3.0


@pytest.fixture(scope="module", params=[(k, o) for k in sorted(DRIVEN) for o in ORDERS],
                ids=lambda p: f"{p[0]}, {p[1]}")
def driven(request):
    kind, order = request.param
    set_point, r, breaks = DRIVEN[kind]
    t = np.linspace(0.0, T_DRIVE, 3001)
    ref, changes = simulate_drive(D, r, t, breaks=breaks)
    model = positioner(order, set_point)()
    return ac.simulate(model, t_end=T_DRIVE, rtol=1e-8, t_eval=t), ref, changes


def test_driven_run_reaches_the_end(driven):
    res, _, _ = driven
    assert res.success, res.message
    assert res.t[-1] == pytest.approx(T_DRIVE)


def test_driven_run_matches_the_mode_by_mode_reference(driven):
    res, ref, _ = driven
    assert res.success, res.message
    assert np.max(np.abs(res["load.phi"] - ref["phi"])) < 1e-5
    assert np.max(np.abs(res["load.w"] - ref["w"])) < 1e-4 * np.max(np.abs(ref["w"]))
    assert np.max(np.abs(res["motor.La.i"] - ref["i"])) < 1e-4 * np.max(np.abs(ref["i"]))


def test_driven_load_sticks_while_the_applied_torque_is_below_F_s(driven):
    res, ref, changes = driven
    assert res.success, res.message
    assert any(what == "w = 0" for _, what in changes)          # there is a stop
    near_change = np.zeros(len(res.t), dtype=bool)
    for tc, _ in changes:
        near_change |= np.abs(res.t - tc) < 1e-3
    stuck = ref["stuck"] & ~near_change
    assert stuck.any()
    assert np.max(np.abs(ref["T_a"][stuck])) <= D.F_c
    assert np.max(np.abs(res["load.w"][stuck])) <= 1e-9 * np.max(np.abs(ref["w"]))


def test_driven_friction_never_delivers_power(driven):
    res, _, _ = driven
    ok, worst = _friction_power_ok(res)
    assert ok, f"friction power down to {worst:.3g} W"
