"""Models written from outside the repository -- Modelica Standard Library examples, DAE
test-set problems, textbook systems (``_outsider_circuits``, ``_outsider_systems``) --
each against an independent reference:

* hand-written equations of the same system under solve_ivp (DOP853, or Radau where
  stiff, rtol 1e-10..1e-12), an implicit node equation solved by brentq where the
  circuit has one;
* Lagrange's equation of a one-degree-of-freedom mechanism, derived by sympy;
* closed forms (exponential decay, constant acceleration, an integrated sine, the
  step response of a transfer function by scipy.signal);
* published reference values: the Test Set for IVP Solvers (F. Mazzia, C. Magherini,
  Bari, release 2.4, 2008: problems "transamp", "chemakzo" and "hires", reference
  solutions computed with RADAU5/MEBDFI at tight tolerance).

Errors are measured relative to the signal's largest magnitude.  The user's operations
on them are checked too: a parameter changed after compilation, a start in steady state
by initial equations, ``steady_state`` and ``linearize`` against hand-derived values, and
the C backend.
"""
import numpy as np
import pytest
from scipy import signal
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

import acausal as ac

from . import _outsider_circuits as oc
from . import _outsider_systems as osy


def _rel(a, b):
    return float(np.max(np.abs(np.asarray(a) - np.asarray(b))) / np.max(np.abs(b)))


def _ivp(f, t, y0, method="DOP853", rtol=1e-12, atol=1e-14, **kw):
    return solve_ivp(f, (0.0, t[-1]), y0, method=method, rtol=rtol, atol=atol, t_eval=t, **kw).y


# -- references ----------------------------------------------------------------------------
def _chua_rhs(G=0.565, C1=10.0):
    Ga, Gb, Ve, Ro, L, C2 = -0.757576, -0.409091, 1.0, 12.5e-3, 18.0, 100.0

    def f(_, z):
        iL, v1, v2 = z
        inr = (Gb * (v1 + Ve) - Ga * Ve if v1 < -Ve
               else Gb * (v1 - Ve) + Ga * Ve if v1 > Ve else Ga * v1)
        iG = (v2 - v1) * G
        return [(v2 - Ro * iL) / L, (iG - inr) / C1, (-iL - iG) / C2]
    return f


def chua(t, **kw):
    return _ivp(_chua_rhs(**kw), t, [0.0, 4.0, 0.0])[1]


def cauer(t):
    c1, c2, c3, c4, c5 = oc.CAUER_C
    l1, l2 = oc.CAUER_L
    M = np.array([[c1 + c2, -c2, 0], [-c2, c2 + c3 + c4, -c4], [0, -c4, c4 + c5]])

    def f(_, z):
        v1, v2, v3, i1, i2 = z
        dv = np.linalg.solve(M, [1.0 - v1 - i1, i1 - i2, i2 - v3])
        return [*dv, (v1 - v2) / l1, (v2 - v3) / l2]
    after = solve_ivp(f, (1.0, t[-1]), np.zeros(5), method="DOP853", rtol=1e-12, atol=1e-13,
                      dense_output=True)
    return np.where(t >= 1.0, after.sol(np.maximum(t, 1.0))[2], 0.0)


def _diode(v, Ids=1e-6, Vt=0.04, Maxexp=15.0, R=1e8):
    x = v / Vt
    law = np.exp(Maxexp) * (1 + x - Maxexp) if x > Maxexp else np.exp(x)
    return Ids * (law - 1) + v / R


def half_wave(t):
    def f(tt, z):
        vs = 10 * np.sin(2 * np.pi * 50 * tt)
        vd = brentq(lambda v: _diode(v) - (vs - z[0] - v) / 10.0, -100, 100, xtol=1e-15)
        return [((vs - z[0] - vd) / 10.0 - z[0] / 1000.0) / 1e-4]
    return _ivp(f, t, [0.0], method="Radau", rtol=1e-10, atol=1e-12, max_step=1e-4)[0]


def _ideal_diode_current(v, Ron, Goff, Vknee, R=1e-3):
    s_on = (v - Vknee - R * Goff * Vknee) / (Ron + R)
    if s_on >= 0:
        return s_on + Goff * Vknee
    return Goff * (v - Vknee - R * Goff * Vknee) / (1 + R * Goff) + Goff * Vknee


def ideal_diode(k):
    def ref(t):
        return np.array([_ideal_diode_current(10 * np.sin(2 * np.pi * tt + 0.3),
                                              *oc.IDEAL_DIODES[k]) for tt in t])
    return ref


def heated_resistor(t):
    def f(tt, z):
        R = 10 * (1 + 4e-3 * (z[0] - 300))
        return [((10 * np.sin(2 * np.pi * 5 * tt)) ** 2 / R - 0.5 * (z[0] - 300)) / 2.0]
    return _ivp(f, t, [300.0])[0]


def bridge(t):
    b = oc.BRIDGE
    vp_amp = b["VAC"] * np.sqrt(2 / 3)

    def dcur(v):
        return b["Goff"] * v if v < b["Vknee"] else \
            (v - b["Vknee"]) / b["Ron"] + b["Goff"] * b["Vknee"]

    def f(tt, z):
        *iL, vp, vn = z
        va = [brentq(lambda v: dcur(v - vp) - dcur(vn - v) - i, -2000, 2000, xtol=1e-13)
              for i in iL]
        vs = [vp_amp * np.sin(2 * np.pi * b["f"] * tt + ph)
              for ph in (0.0, -2 * np.pi / 3, 2 * np.pi / 3)]
        i_load = (vp - vn) / b["RL"]
        return [*((s - a) / b["LAC"] for s, a in zip(vs, va)),
                (sum(dcur(a - vp) for a in va) - i_load) / b["CDC"],
                (i_load - sum(dcur(vn - a) for a in va)) / b["CDC"]]
    y = _ivp(f, t, np.zeros(5), method="Radau", rtol=1e-10, atol=1e-8, max_step=2e-5)
    return y[3] - y[4]


def first(t, c=1e4, d=10.0):
    J_eff = 2.0 + 0.1 * 10.0 ** 2         # the motor inertia seen through the gear

    def f(tt, z):
        p2, w2, p3, w3 = z
        tau_spring = c * (p3 - p2)
        return [w2, (10 * 10 * np.sin(2 * np.pi * 5 * tt) + tau_spring - d * w2) / J_eff,
                w3, -tau_spring / 2.0]
    return _ivp(f, t, np.zeros(4))[3]


def initial_conditions(k):
    def ref(t):
        def f(_, z):
            x1, v1, x2, v2 = z
            f1 = 1e3 * ((x1 + 1.0) - 1.0)
            f2 = 111.0 * ((x2 - x1) - 1.0) + (v2 - v1)
            return [v1, -f1 + f2, v2, -f2]
        return _ivp(f, t, [-0.5, 0.0, 0.5, 0.0])[2 * k]
    return ref


def spring_damper_stop(t):
    return _ivp(lambda _, z: [z[1], (4.5 - z[0] - 1.0) - 25 * z[1]], t, [3.0, 10.0],
                method="Radau")[0]


def _motor_rhs(tt, z):
    m, tab = osy.MOTOR, osy.MOTOR_LOSSES
    Tw, Tc = z
    qw, qc = np.interp(tt, tab[:, 0], tab[:, 1]), np.interp(tt, tab[:, 0], tab[:, 2])
    flow = m["Gwc"] * (Tw - Tc)
    return [(qw - flow) / m["Cw"], (qc + flow - m["Gc"] * (Tc - m["T_amb"])) / m["Cc"]]


def motor(k):
    def ref(t):
        return _ivp(_motor_rhs, t, [osy.MOTOR["T_amb"]] * 2, rtol=1e-12, atol=1e-12,
                    max_step=1.0)[k]
    return ref


def speed_control(t):
    p = osy.PID

    def f(tt, z):
        w, xi, xd = z
        u = (1.0 if tt >= p["t_step"] else 0.0) - w
        v = p["k"] * u + xi + p["k"] * p["Nd"] * (u - xd)
        y = min(max(v, -p["yMax"]), p["yMax"])
        return [(y - p["d"] * w) / p["J"], p["k"] / p["Ti"] * u + (y - v) / p["Tt"],
                (u - xd) * p["Nd"] / p["Td"]]
    s = solve_ivp(f, (p["t_step"], t[-1]), [0.0, 0.0, 0.0], method="Radau", rtol=1e-11,
                  atol=1e-13, dense_output=True)
    return np.where(t < p["t_step"], 0.0, s.sol(np.maximum(t, p["t_step"]))[0])


def critical_filter(t):
    return signal.step(signal.lti([1.0], list(osy.FILTER_DEN)), T=t)[1]


def pendulum(t):
    return np.sin(_ivp(lambda _, z: [z[1], -9.81 * np.sin(z[0])], t, [0.5, 0.0])[0])


def robertson(k):
    def ref(t):
        def f(_, y):
            return [-0.04 * y[0] + 1e4 * y[1] * y[2],
                    0.04 * y[0] - 1e4 * y[1] * y[2] - 3e7 * y[1] ** 2, 3e7 * y[1] ** 2]
        return _ivp(f, t, [1.0, 0.0, 0.0], method="Radau", rtol=1e-12, atol=1e-16)[k]
    return ref


def slider_crank(t):
    """Lagrange's equation in the crank angle theta (the rod angle psi from
    l sin(psi) = -r sin(theta)): M(theta) theta'' + M'(theta) theta'^2 / 2 + V'(theta) = tau,
    M = J_hub + m_rod |dG/dtheta|^2 + J_rod psi'(theta)^2 + m_slider (dx_s/dtheta)^2."""
    import sympy as sp
    c = osy.CRANK
    th, thd = sp.symbols("theta thetadot")
    psi = -sp.asin(c["r"] * sp.sin(th) / c["l"])
    xg = c["r"] * sp.cos(th) + c["l"] / 2 * sp.cos(psi)
    yg = c["r"] * sp.sin(th) + c["l"] / 2 * sp.sin(psi)
    xs = c["r"] * sp.cos(th) + c["l"] * sp.cos(psi)
    d = lambda e: sp.diff(e, th)  # noqa: E731
    M = (c["J_hub"] + c["m_rod"] * (d(xg) ** 2 + d(yg) ** 2)
         + c["m_rod"] * c["l"] ** 2 / 12 * d(psi) ** 2 + c["m_slider"] * d(xs) ** 2)
    acc = sp.lambdify((th, thd), (c["tau"] - d(M) * thd ** 2 / 2 - c["m_rod"] * c["g"] * d(yg))
                      / M, "numpy")
    theta = _ivp(lambda _, z: [z[1], acc(z[0], z[1])], t, [c["theta0"], 0.0])[0]
    return sp.lambdify(th, xs, "numpy")(theta)


A_ROLL = 10.0 / (2.0 + 0.05 / 0.25 ** 2)   # F / (m + J / r^2)

# (id, model, t_end, variable, reference(t), rtol of the run, bound relative to the signal)
TRAJECTORIES = [
    ("ChuaCircuit", oc.Chua, 100.0, "C1.v", chua, 1e-9, 1e-5),
    ("CauerLowPassAnalog", oc.CauerLowPass, 60.0, "C5.v", cauer, 1e-9, 1e-5),
    ("HalfWaveDiodeRectifier", oc.HalfWaveRectifier, 0.04, "C.v", half_wave, 1e-9, 1e-5),
    ("CharacteristicIdealDiodes_D2", oc.IdealDiodes, 1.0, "D2.i", ideal_diode(1), 1e-8, 1e-8),
    ("CharacteristicIdealDiodes_D3", oc.IdealDiodes, 1.0, "D3.i", ideal_diode(2), 1e-8, 1e-8),
    ("HeatingResistor", oc.HeatedResistor, 2.0, "Cth.T", heated_resistor, 1e-9, 1e-6),
    ("BridgeRectifier", oc.BridgeRectifier, 0.01, "load.v", bridge, 1e-8, 1e-5),
    ("OpAmpIntegrator", oc.OpAmpIntegrator, 0.2, "C.v",
     lambda t: (1 - np.cos(2 * np.pi * 10 * t)) / (2 * np.pi * 10 * 1e3 * 1e-5), 1e-9, 1e-6),
    ("RotationalFirst", osy.First, 1.0, "inertia3.w", first, 1e-10, 1e-6),
    ("TranslationalInitialConditions_m1", osy.InitialConditions, 5.0, "m1.s",
     initial_conditions(0), 1e-10, 1e-6),
    ("TranslationalInitialConditions_m2", osy.InitialConditions, 5.0, "m2.s",
     initial_conditions(1), 1e-10, 1e-6),
    ("TranslationalDamper_d", osy.DamperExample, 1.0, "m1.s",
     lambda t: 3 + 10 / 25 * (1 - np.exp(-25 * t)), 1e-9, 1e-6),
    ("TranslationalDamper_sd", osy.DamperExample, 1.0, "m2.s", spring_damper_stop, 1e-9, 1e-6),
    ("RollingWheel", osy.RollingWheel, 2.0, "J.w", lambda t: A_ROLL * t / 0.25, 1e-9, 1e-8),
    ("ThermalTwoMasses", osy.TwoMasses, 1.0, "mass1.T",
     lambda t: 323.15 + 50 * np.exp(-2 * 10 / 15 * t), 1e-9, 1e-7),
    ("MotorThermal_winding", osy.MotorThermal, 1200.0, "winding.T", motor(0), 1e-9, 1e-6),
    ("MotorThermal_core", osy.MotorThermal, 1200.0, "core.T", motor(1), 1e-9, 1e-6),
    ("PID_Controller", osy.SpeedControl, 1.0, "J.w", speed_control, 1e-9, 1e-5),
    ("CriticalDampingFilter", osy.CriticalFilter, 1.0, "tf.y.signal", critical_filter, 1e-9,
     1e-5),
    # y = u - y/2 inside the limits, +-1 outside: y = clip(u/1.5, -1, 1)
    ("SaturatedAlgebraicLoop", osy.SaturatedLoop, 1.0, "lim.y.signal",
     lambda t: np.clip(2 * np.sin(2 * np.pi * t) / 1.5, -1, 1), 1e-9, 1e-6),
    ("LeadLagStep", osy.LeadLag, 1.0, "tf.y.signal",
     lambda t: np.where(t >= 0.1, 1 + 9 * np.exp(-10 * np.maximum(t - 0.1, 0)), 0), 1e-9,
     1e-6),
    ("CartesianPendulum", osy.CartesianPendulum, 5.0, "x", pendulum, 1e-9, 1e-5),
    ("SliderCrankTorqueDriven", osy.TorqueSliderCrank, 1.5, "guide.s", slider_crank, 1e-9,
     1e-6),
    ("RobertsonDAE_y2", osy.Robertson, 40.0, "y2", robertson(1), 1e-9, 1e-5),
    ("RobertsonDAE_y3", osy.Robertson, 40.0, "y3", robertson(2), 1e-9, 1e-5),
]


@pytest.mark.parametrize("model, t_end, name, reference, rtol, bound",
                         [case[1:] for case in TRAJECTORIES],
                         ids=[case[0] for case in TRAJECTORIES])
def test_trajectory_against_independent_reference(model, t_end, name, reference, rtol, bound):
    res = ac.simulate(model(), t_end, n_points=201, rtol=rtol, backend="numpy")
    assert res.success, res.message
    assert _rel(res[name], reference(res.t)) < bound


# Test Set for IVP Solvers 2.4: "transamp" y(0.2) (nodes 1..8), "chemakzo" y(180),
# "hires" y(321.8122)
TRANSAMP_Y = {"R0.n.v": -0.5562145012262709e-2, "T1.b.v": 0.3006522471903042e1,
              "T1.e.v": 0.2849958788608128e1, "T1.c.v": 0.2926422536206241e1,
              "T2.b.v": 0.2704617865010554e1, "T2.e.v": 0.2761837778393145e1,
              "T2.c.v": 0.4770927631616772e1, "R9.p.v": 0.1236995868091548e1}
AKZO_Y = {"y1": 0.1150794920661702, "y2": 0.1203831471567715e-2, "y3": 0.1611562887407974,
          "y4": 0.3656156421249283e-3, "y5": 0.1708010885264404e-1,
          "y6": 0.4873531310307455e-2}
HIRES_Y = {f"y[{i}]": v for i, v in enumerate(
    [0.7371312573325668e-3, 0.1442485726316185e-3, 0.5888729740967575e-4,
     0.1175651343283149e-2, 0.2386356198831331e-2, 0.6238968252742796e-2,
     0.2849998395185769e-2, 0.2850001604814231e-2])}


@pytest.mark.parametrize("model, t_end, published, backend", [
    (oc.TransistorAmplifier, 0.2, TRANSAMP_Y, "numpy"),
    (osy.AkzoNobel, 180.0, AKZO_Y, "numpy"),
    (osy.Hires, 321.8122, HIRES_Y, "numpy"),
    (osy.AkzoNobel, 180.0, AKZO_Y, "c"),
], ids=["transamp", "chemakzo", "hires", "chemakzo_c"])
def test_final_values_against_the_published_test_set(model, t_end, published, backend):
    res = ac.simulate(model(), t_end, rtol=1e-9, backend=backend)
    assert res.success, res.message
    for name, value in published.items():
        assert abs(res[name][-1] - value) < 2e-6 * abs(value), name


def test_chua_parameters_changed_after_compilation_and_the_c_backend():
    compiled = ac.compile(oc.Chua(), backend="c")
    t = np.linspace(0.0, 50.0, 201)
    res = ac.simulate(compiled, 50.0, t_eval=t, rtol=1e-9,
                      parameters={"G.R": 1 / 0.6, "C1.C": 9.0})
    assert res.success
    assert _rel(res["C1.v"], chua(t, G=0.6, C1=9.0)) < 1e-5
    res = ac.simulate(compiled, 50.0, t_eval=t, rtol=1e-9)
    assert _rel(res["C1.v"], chua(t)) < 1e-5


def test_chua_equilibrium_and_its_linearization():
    """The outer equilibrium nearest the start (v1 = 4 V): v2 = Ro iL, iL = G (v1 - v2),
    G (v2 - v1) = Gb (v1 - Ve) + Ga Ve; the Jacobian there by hand (slope Gb)."""
    Ga, Gb, Ve, Ro, G = -0.757576, -0.409091, 1.0, 12.5e-3, 0.565
    k = Ro * G / (1 + Ro * G)                   # v2 = k v1
    v1 = (Ga - Gb) * Ve / (G * (k - 1) - Gb)
    compiled = ac.compile(oc.Chua(), backend="numpy")
    op = ac.steady_state(compiled)
    assert abs(op["C1.v"] - v1) < 1e-9 * v1
    assert abs(op["C2.v"] - k * v1) < 1e-9 * v1
    A = np.array([[-Ro / 18, 0, 1 / 18], [0, (-G - Gb) / 10, G / 10],
                  [-1 / 100, G / 100, -G / 100]])
    poles = np.sort_complex(np.linalg.eigvals(ac.linearize(compiled, at=op).A))
    expected = np.sort_complex(np.linalg.eigvals(A))
    assert np.max(np.abs(poles - expected)) < 1e-6 * np.max(np.abs(expected))


def test_first_linearized_through_its_torque():
    """Poles of the geared drive: J_eff = J2 + n^2 J1 on the damper, the spring to J3."""
    ss = ac.linearize(osy.First(), inputs=["torque.tau.signal"], outputs=["inertia3.w"])
    J_eff, c, d = 12.0, 1e4, 10.0
    A = np.array([[0, 1, 0, 0], [-c / J_eff, -d / J_eff, c / J_eff, 0], [0, 0, 0, 1],
                  [c / 2, 0, -c / 2, 0]])
    poles = np.sort_complex(np.linalg.eigvals(ss.A))
    expected = np.sort_complex(np.linalg.eigvals(A))
    assert np.max(np.abs(poles - expected)) < 1e-6 * np.max(np.abs(expected))


def test_motor_thermal_starts_and_stays_in_equilibrium():
    """der(T) = 0 at t = 0 under 100 W / 50 W: Tc = T_amb + 150/Gc, Tw = Tc + 100/Gwc; the
    losses stay constant until 360 s, so do the temperatures."""
    m = osy.MOTOR
    Tc = m["T_amb"] + 150.0 / m["Gc"]
    Tw = Tc + 100.0 / m["Gwc"]
    res = ac.simulate(osy.MotorThermalSteady(), 300.0, n_points=11, rtol=1e-9)
    assert res.success
    assert np.max(np.abs(res["winding.T"] - Tw)) < 1e-9 * Tw
    assert np.max(np.abs(res["core.T"] - Tc)) < 1e-9 * Tc
    op = ac.steady_state(osy.MotorThermal())
    assert abs(op["winding.T"] - Tw) < 1e-9 * Tw
