"""FR-07: the LuGre friction model and its passivity condition (Egeland & Gravdahl, 001
§5.3.4-5.3.5, (5.42)-(5.54); Canudas de Wit et al. 1995; Barabanov & Ortega 2000).

    dz/dt = v - sigma_0 |v| z / g(v),   g(v) = F_c + (F_s - F_c) exp(-(v/v_s)^2)   (5.42)-(5.43)
    F = sigma_0 z + sigma_1 dz/dt + sigma_2 v                                      (5.44)

(g is the force level, see ``acausal.library.friction.laws.stribeck_level``.)  The map
v -> F is passive iff sigma_1 <= sigma_2 F_c / (F_s - F_c) (5.54).  With the storage
V = sigma_0 z^2 / 2 the dissipation rate is

    D = F v - dV/dt = sigma_0^2 |v| z^2 / g + sigma_1 v dz/dt + sigma_2 v^2,

and with s = sigma_0 z sgn(v), |s| <= F_s (the invariant set (5.46)):

    D / v^2 = sigma_1 + sigma_2 - sigma_1 s / g + s^2 / (g |v|).

Where (5.54) holds, D >= 0 for every s in [-F_s, F_s] and every v (worked by hand from
the bound g >= F_c).  Where it fails, D < 0 at the state the bound names: bristles
loaded to break-away (s near F_s, after creeping), then a fast slip, |v| >> v_s (g -> F_c)
and |v| >> F_s^2 / (sigma_1 (F_s - F_c)/F_c - sigma_2).

The test drives the library's rotational LuGreFriction with a prescribed speed: creep at
v_s/2 from the steady bristle state z_ss = g sgn(v)/sigma_0 (5.48), then a fast smooth
rise to 10 rad/s and a reversal.  Checked: z(t) agrees with scipy's solve_ivp
(Radau, rtol 1e-11) on (5.42); the steady state at creep is (5.48); D along the run
(from the simulated tau, w, z, z') is >= 0 to round-off for sigma_1 just inside (5.54)
and clearly negative for sigma_1 outside it.
"""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal as ac
from acausal.library.friction.rotational import LuGreFriction
from acausal.library.rotational import Fixed, Speed
from acausal.ports import RealOutput

F_C, F_S, V_S, SIGMA_0, SIGMA_2 = 1.0, 1.5, 0.01, 100.0, 0.4
BOUND = SIGMA_2 * F_C / (F_S - F_C)             # (5.54): 0.8 N m s/rad
V_CREEP, V_FAST, T_RISE, TAU = 0.5 * V_S, 10.0, 0.05, 2e-4
T_END = 0.2


def g(v):
    return F_C + (F_S - F_C) * np.exp(-(v / V_S)**2)


def speed(t):
    """Creep, a tanh rise to V_FAST at T_RISE, a reversal to -V_FAST at 2 T_RISE."""
    up = 0.5 * (1 + np.tanh((t - T_RISE) / TAU))
    down = 0.5 * (1 + np.tanh((t - 2 * T_RISE) / TAU))
    return V_CREEP + (V_FAST - V_CREEP) * up - 2 * V_FAST * down


class SpeedProfile(ac.Component):
    """The prescribed slip speed of ``speed`` as equations of time."""

    out = RealOutput()

    def equations(self):
        t = ac.time
        up = 0.5 * (1 + ac.tanh((t - T_RISE) / TAU))
        down = 0.5 * (1 + ac.tanh((t - 2 * T_RISE) / TAU))
        return [ac.Eq(self.out.signal, V_CREEP + (V_FAST - V_CREEP) * up - 2 * V_FAST * down)]


class DrivenLuGre(ac.Component):
    """LuGre friction between a housing and a shaft turned at the prescribed speed."""

    housing = Fixed()
    friction = LuGreFriction(F_c=F_C, F_s=F_S, v_s=V_S, sigma_0=SIGMA_0, sigma_1=0.5,
                             sigma_2=SIGMA_2,
                             z={"start": g(V_CREEP) / SIGMA_0, "fixed": True})
    profile = SpeedProfile()
    drive = Speed()

    def equations(self):
        return [ac.connect(self.housing.flange, self.friction.flange_a),
                ac.connect(self.friction.flange_b, self.drive.flange),
                ac.connect(self.profile.out, self.drive.w_ref)]


def _run(sigma_1):
    res = ac.simulate(DrivenLuGre(friction={"sigma_1": sigma_1}), t_end=T_END, rtol=1e-10,
                      max_step=TAU, raise_on_failure=True)
    return res


def _dissipation(res):
    tau, w = res["friction.tau"], res["friction.w"]
    z, zdot = res["friction.z"], res["friction.z_dot"]
    return tau * w - SIGMA_0 * z * zdot, tau * w


@pytest.fixture(scope="module")
def runs():
    return {"inside": _run(0.98 * BOUND), "outside": _run(5.0 * BOUND)}


def test_speed_is_the_prescribed_profile(runs):
    res = runs["inside"]
    assert np.max(np.abs(res["friction.w"] - speed(res.t))) < 1e-9 * V_FAST


@pytest.mark.parametrize("case", ["inside", "outside"])
def test_bristle_state_matches_an_independent_solver(runs, case):
    res = runs[case]
    ref = solve_ivp(lambda t, z: [speed(t) - SIGMA_0 * abs(speed(t)) * z[0] / g(speed(t))],
                    (0.0, T_END), [g(V_CREEP) / SIGMA_0], method="Radau", rtol=1e-11,
                    atol=1e-15, dense_output=True, max_step=TAU)
    assert ref.success
    z = ref.sol(res.t)[0]
    scale = np.max(np.abs(z))
    assert np.max(np.abs(res["friction.z"] - z)) < 1e-6 * scale


def test_creep_is_the_steady_state(runs):
    res = runs["inside"]
    before = res.t < T_RISE - 20 * TAU
    # z_ss = g(v) sgn(v) / sigma_0 (5.48), and F = g(v) + sigma_2 v on the Stribeck curve
    assert np.max(np.abs(res["friction.z"][before] * SIGMA_0 - g(V_CREEP))) < 1e-8 * F_S
    assert np.max(np.abs(res["friction.tau"][before] - g(V_CREEP) - SIGMA_2 * V_CREEP)) \
        < 1e-8 * F_S


def test_dissipation_is_nonnegative_inside_the_bound(runs):
    D, power = _dissipation(runs["inside"])
    assert np.max(np.abs(power)) > 1.0                 # the run does real work
    assert np.min(D) >= -1e-9 * np.max(np.abs(D))


def test_dissipation_turns_negative_outside_the_bound(runs):
    res = runs["outside"]
    D, _ = _dissipation(res)
    w = res["friction.w"]
    slipping = np.abs(w) > 10 * V_S
    rate = D[slipping] / w[slipping]**2              # D / v^2, as in the bound
    sigma_1 = 5.0 * BOUND
    # measured about -0.16 (sigma_1 + sigma_2); inside the bound it stays above +0.29
    assert np.min(rate) < -0.05 * (sigma_1 + SIGMA_2)
    # it is negative right after the fast slip starts from loaded bristles
    k = int(np.argmin(rate))
    assert abs(res.t[slipping][k] - T_RISE) < 20 * TAU
