"""NM-26a/b: the pneumatic spring and its two-mass stiff variant (Egeland & Gravdahl,
001 §14.4.5 and §14.5.9, (14.100)-(14.107), (14.144)-(14.150)).

NM-26a: a mass m on a gas column of area A, isentropic with exponent kappa:

    x'' + g [1 - x^(-kappa)] = 0                                         (14.100)
    A = 0.01 m^2, m = 200 kg, kappa = 1.4, p_0 = 2e5 N/m^2, g = 10 m/s^2 (m g = A p_0)
    J(x*) = [[0, 1], [-g kappa x*^-(kappa+1), 0]],   lambda = +-j omega_0      (14.103)-(14.104)
    E = p_0 A x^-(kappa-1) / (kappa - 1) + m g x + m v^2 / 2                  (14.106)
    E_min = p_0 A / (kappa - 1) + m g = 7000 J  (at x = 1, v = 0)             (14.107)

omega_0(1) = sqrt(g kappa) = 3.74 rad/s, printed 3.7.  The printed table (14.105) gives
4.3 and 3.3 rad/s at x* = 0.5 and 2; (14.104) gives 8.60 and 1.63 (INVENTORY §0.4): the
test checks (14.103)-(14.104), and only 3.7 against the printed table.

NM-26b: two masses m_1 = m_2 = 100 kg, the gas under mass 1, a spring K = m_1 omega_2^2/2
between them, omega_2 = 1000 rad/s:

    x_1'' + g (1 - (m/m_1) x_1^-kappa) + (omega_2^2/2)(x_1 - x_2) = 0        (14.144)
    x_2'' + g + (omega_2^2/2)(x_2 - x_1) = 0                                 (14.145)

equilibrium x_1* = 1, x_2* = 1 - m_2 g / K (printed "1 - m_2/K", §0.4), eigenvalues
+-j3.7 and +-j1000 (14.149)-(14.150).

The energy behaviour the book shows for its integrators (plots lost): exact solutions keep
E; implicit Euler dissipates most (energy converges to the equilibrium energy), the
higher-order L-stable methods less.  For acausal's BDF: E is kept to the tolerance at
rtol 1e-11 (relative to the oscillation energy E - E_min, the signal here), the run
agrees with scipy's DOP853 (rtol 1e-11/1e-12); limited to order 1 (implicit Euler) at a
loose tolerance the energy falls at every step and stays above E_min.  In the two-mass
system the BDF damps the 1000 rad/s mode slightly and never feeds it.
"""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal as ac

A, M, KAPPA, P0, G = 0.01, 200.0, 1.4, 2e5, 10.0
M1 = M2 = 100.0
OMEGA_2 = 1000.0
K_SPRING = M1 * OMEGA_2**2 / 2


class PneumaticSpring(ac.Component):
    """m x'' = p_0 A x^-kappa - m g: (14.100) as a force balance."""

    x = ac.Variable(start=1.3, fixed=True, unit="m")
    v = ac.Variable(start=0.0, fixed=True, unit="m/s")
    energy = ac.Variable(unit="J", description="(14.106)")

    def equations(self):
        x, v = self.x, self.v
        return [ac.Eq(ac.der(x), v),
                ac.Eq(M * ac.der(v), P0 * A * x**(-KAPPA) - M * G),
                ac.Eq(self.energy, P0 * A * x**(1 - KAPPA) / (KAPPA - 1) + M * G * x
                      + M * v**2 / 2)]


class TwoMassSpring(ac.Component):
    """(14.144)-(14.145) as force balances on the two masses."""

    x1 = ac.Variable(start=1.2, fixed=True, unit="m")
    v1 = ac.Variable(start=0.0, fixed=True, unit="m/s")
    x2 = ac.Variable(start=1.2 - 2e-5 + 1e-4, fixed=True, unit="m")
    v2 = ac.Variable(start=0.0, fixed=True, unit="m/s")
    energy = ac.Variable(unit="J")

    def equations(self):
        x1, v1, x2, v2 = self.x1, self.v1, self.x2, self.v2
        return [ac.Eq(ac.der(x1), v1), ac.Eq(ac.der(x2), v2),
                ac.Eq(M1 * ac.der(v1), P0 * A * x1**(-KAPPA) - M1 * G - K_SPRING * (x1 - x2)),
                ac.Eq(M2 * ac.der(v2), -M2 * G - K_SPRING * (x2 - x1)),
                ac.Eq(self.energy, P0 * A * x1**(1 - KAPPA) / (KAPPA - 1) + M1 * G * x1
                      + M2 * G * x2 + K_SPRING * (x1 - x2)**2 / 2
                      + M1 * v1**2 / 2 + M2 * v2**2 / 2)]


def _energy_1dof(x, v):
    return P0 * A * x**(1 - KAPPA) / (KAPPA - 1) + M * G * x + M * v**2 / 2


def test_minimum_energy_is_7000_J():
    """(14.107): E at the equilibrium, found by acausal's steady state, is 7000 J."""
    compiled = ac.compile(PneumaticSpring(x={"start": 1.1, "fixed": False}))
    op = ac.steady_state(compiled)
    assert op["x"] == pytest.approx(1.0, rel=1e-10)
    assert op["energy"] == pytest.approx(7000.0, rel=1e-12)


@pytest.mark.parametrize("x_star", [0.5, 1.0, 2.0])
def test_jacobian_is_14_103(x_star):
    sys = ac.linearize(PneumaticSpring(), at={"x": x_star, "v": 0.0})
    i, j = list(sys.states).index("x"), list(sys.states).index("v")
    omega_sq = G * KAPPA * x_star**(-(KAPPA + 1))
    assert sys.A[j, i] == pytest.approx(-omega_sq, rel=1e-8)
    assert sys.A[i, j] == pytest.approx(1.0, rel=1e-12)
    omega = np.sort(np.abs(sys.poles().imag))[-1]
    assert omega == pytest.approx(np.sqrt(omega_sq), rel=1e-8)
    assert np.max(np.abs(sys.poles().real)) < 1e-8 * omega
    if x_star == 1.0:
        assert round(omega, 1) == 3.7                # the printed omega_0 at x* = 1


def test_energy_is_kept_at_tight_tolerance():
    res = ac.simulate(PneumaticSpring(), t_end=10.0, rtol=1e-11, n_points=501,
                      raise_on_failure=True)
    ref = solve_ivp(lambda t, s: [s[1], -G * (1 - s[0]**(-KAPPA))], (0.0, 10.0), [1.3, 0.0],
                    method="DOP853", rtol=1e-11, atol=1e-13, t_eval=res.t)
    assert np.max(np.abs(res["x"] - ref.y[0])) < 1e-7 * np.ptp(ref.y[0])
    E = res["energy"]
    assert np.allclose(E, _energy_1dof(res["x"], res["v"]), rtol=1e-12, atol=0)
    swing = E[0] - 7000.0
    assert swing > 100.0
    assert np.max(np.abs(E - E[0])) < 1e-7 * swing


@pytest.fixture(scope="module")
def implicit_euler():
    return ac.simulate(PneumaticSpring(), t_end=20.0, rtol=1e-3, max_order=1,
                       raise_on_failure=True)


def test_implicit_euler_only_loses_energy(implicit_euler):
    """BDF1 is implicit Euler: on the oscillator it only dissipates, step after step,
    towards the equilibrium energy (the book's implicit Euler curve at h = 0.5 s)."""
    E = implicit_euler["energy"]
    swing = E[0] - 7000.0
    # accepted steps only: E is non-increasing (to round-off of E itself)
    assert np.all(np.diff(E) <= 1e-12 * E[0])
    assert E[-1] < E[0] - 1e-2 * swing
    assert E[-1] > 7000.0


def test_two_mass_eigenvalues():
    compiled = ac.compile(TwoMassSpring())
    x2_star = 1 - M2 * G / K_SPRING
    sys = ac.linearize(compiled, at={"x1": 1.0, "x2": x2_star, "v1": 0.0, "v2": 0.0})
    stiffness = np.array([[(G * KAPPA * M + K_SPRING) / M1, -K_SPRING / M1],
                          [-K_SPRING / M2, K_SPRING / M2]])
    exact = np.sort(np.sqrt(np.linalg.eigvals(stiffness).real))
    omegas = np.sort(np.abs(sys.poles().imag))[::2]
    assert np.allclose(omegas, exact, rtol=1e-8)
    assert np.max(np.abs(sys.poles().real)) < 1e-8 * exact[-1]
    # printed: omega_1 = 3.7 rad/s, omega_2 = 1000 rad/s (14.149)-(14.150)
    assert round(omegas[0], 1) == 3.7 and abs(omegas[1] - 1000.0) < 0.5


def test_two_mass_equilibrium_is_1_and_1_minus_m2_g_over_K():
    compiled = ac.compile(TwoMassSpring(x1={"start": 1.05, "fixed": False},
                                        x2={"start": 1.05, "fixed": False}))
    op = ac.steady_state(compiled)
    assert op["x1"] == pytest.approx(1.0, rel=1e-10)
    assert op["x2"] == pytest.approx(1 - M2 * G / K_SPRING, rel=1e-10)


def test_two_mass_energy_and_trajectory():
    res = ac.simulate(TwoMassSpring(), t_end=0.5, rtol=1e-9, n_points=401,
                      raise_on_failure=True)
    k = K_SPRING

    def rhs(t, s):
        x1, v1, x2, v2 = s
        return [v1, (P0 * A * x1**(-KAPPA) - M1 * G - k * (x1 - x2)) / M1,
                v2, (-M2 * G - k * (x2 - x1)) / M2]
    ref = solve_ivp(rhs, (0.0, 0.5), [1.2, 0.0, 1.2 - 2e-5 + 1e-4, 0.0], method="DOP853",
                    rtol=1e-12, atol=1e-14, t_eval=res.t)
    assert np.max(np.abs(res["x1"] - ref.y[0])) < 1e-6 * np.ptp(ref.y[0])
    stretch, stretch_ref = res["x1"] - res["x2"], ref.y[0] - ref.y[2]
    # the stretch x_1 - x_2 is ~1e-4 of x: the error test (rtol 1e-9 of |x|) allows it
    # ~1e-5 of its own size per step, and the 1000 rad/s phase error accumulates over
    # 80 periods
    assert np.max(np.abs(stretch - stretch_ref)) < 1e-3 * np.ptp(stretch_ref)
    E = res["energy"]
    fast = K_SPRING * ((1.2 - (1.2 - 2e-5 + 1e-4)) - M2 * G / K_SPRING)**2 / 2
    # BDF damps the 1000 rad/s mode a little (an L-stable-like method, as the book
    # says of Lobatto IIIC), and never feeds it
    assert E[0] - E[-1] > -1e-9 * E[0]
    assert E[0] - E[-1] < 1e-2 * fast
