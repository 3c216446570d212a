"""TF-04: water turbine with a penstock (Egeland & Gravdahl 11.2.9, (11.101)-(11.114)),
built from ``Penstock`` and ``PeltonTurbine``.

Linearized at the nominal gate A_0, flow q_0 and shaft speed w_0 (held by the grid), the
torque's answer to the gate is (11.109) with the rigid column's H_pq = rho L s/A_p
(11.111):

    dT_t/dA = (2/gamma)(r_t rho q_0^2/A_0^2)(1 - gamma tau s)/(1 + tau s)      (11.113)
    tau = L A_0^2/(alpha q_0 A_p),  alpha = 1 - A_0^2/A_p^2,
    beta = 2 - r_t w_0 A_0/q_0,  gamma = 1/(beta/alpha - 1)

At the speed of the most power beta = 1.5, and for alpha -> 1 gamma -> 2: the full-load
form (11.114), zero at 1/T_r and pole at -2/T_r with T_r = 2 tau.  The example's
A_0/A_p = 0.05 gives alpha = 0.9975, gamma = 1.985.
"""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal as ac
from acausal.library.hydraulics.examples import pelton_turbine as pt


@pytest.fixture(scope="module")
def linear():
    plant = ac.compile(pt.PeltonPlant())
    op = ac.steady_state(plant, hold=["turbine.flange.phi"])
    assert op["penstock.q"] == pytest.approx(pt.Q_0, rel=1e-10)
    return ac.linearize(plant, inputs=["gate.offset"], outputs=["turbine.T_t"], at=op)


def _closed_form():
    alpha = 1 - pt.A_0**2 / pt.A_P**2
    beta = 2 - pt.R_T * pt.W_0 * pt.A_0 / pt.Q_0
    gamma = 1 / (beta / alpha - 1)
    tau = pt.L * pt.A_0**2 / (alpha * pt.Q_0 * pt.A_P)
    K = pt.R_T * pt.RHO * pt.Q_0**2 / pt.A_0**2
    return alpha, beta, gamma, tau, K


def test_zero_pole_and_gains_are_11_113(linear):
    """The pole is an eigenvalue of the symbolic Jacobian; the zero and the gains go
    through the input columns, which ac.linearize takes as central differences in the
    parameter (agreeing to ~1e-9)."""
    alpha, beta, gamma, tau, K = _closed_form()
    assert beta == pytest.approx(1.5, rel=1e-12)          # half the jet speed
    sys = linear.minimal()
    assert sys.n_states == 1                  # the grid's angle is neither seen nor driven
    zeros, poles = sys.zeros(), sys.poles()
    assert len(zeros) == 1 and len(poles) == 1
    assert zeros[0].real == pytest.approx(1 / (gamma * tau), rel=1e-7)   # right half-plane
    assert poles[0].real == pytest.approx(-1 / tau, rel=1e-9)
    assert abs(zeros[0].imag) + abs(poles[0].imag) == 0
    assert sys.dcgain()[0, 0] == pytest.approx(2 / gamma * K, rel=1e-7)
    # at high frequency the flow cannot change: dT = -2 r_t rho q_0^2/A_0^2 dA (11.107)
    assert sys.D[0, 0] == pytest.approx(-2 * K, rel=1e-7)


def test_full_load_form_11_114(linear):
    """alpha = 0.9975 instead of 1: gamma = 1.985 instead of 2, and the zero and pole are
    within 1 % of (11.114)'s 1/T_r and -2/T_r, T_r = 2 L A_0^2/(q_0^2 A_p) q_max (mu = 1)."""
    alpha, _, gamma, _, _ = _closed_form()
    T_r = 2 * pt.L * pt.A_0**2 / (pt.Q_0 * pt.A_P)
    sys = linear.minimal()
    assert gamma == pytest.approx(2.0, rel=1e-2)
    assert sys.zeros()[0].real == pytest.approx(1 / T_r, rel=1e-2)
    assert sys.poles()[0].real == pytest.approx(-2 / T_r, rel=1e-2)


def test_gate_step_against_the_hand_written_column():
    """The nonlinear run against DOP853 on (rho L/A_p) q' = rho g h - (rho/2) q^2
    (1/A^2 - 1/A_p^2), and the torque (11.106) on it: the torque first drops (the
    right half-plane zero), then rises to the new steady value."""
    res = ac.simulate(pt.PeltonPlant(), t_end=pt.PeltonPlant.stop_time, rtol=1e-10,
                      n_points=401, raise_on_failure=True)
    A_1 = 1.1 * pt.A_0

    def rhs(t, q):
        return [pt.A_P / (pt.RHO * pt.L) * (pt.RHO * pt.G * pt.H - pt.RHO / 2 * q[0]**2
                                          * (1 / A_1**2 - 1 / pt.A_P**2))]
    after = res.t >= 1.0
    t1 = res.t[after]
    q1 = np.interp(1.0, res.t, res["penstock.q"])
    assert q1 == pytest.approx(pt.Q_0, rel=1e-9)     # at rest until the step
    ref = solve_ivp(rhs, (1.0, t1[-1]), [pt.Q_0], method="DOP853", rtol=1e-12, atol=1e-12,
                    t_eval=t1)
    q = res["penstock.q"][after]
    assert np.max(np.abs(q - ref.y[0])) < 1e-7 * np.ptp(ref.y[0])
    T_ref = 2 * pt.R_T * pt.RHO * ref.y[0] * (ref.y[0] / A_1 - pt.R_T * pt.W_0)
    T = res["turbine.T_t"][after]
    assert np.max(np.abs(T[1:] - T_ref[1:])) < 1e-6 * np.ptp(T_ref)
    T_0 = res["turbine.T_t"][0]
    assert T[1:6].max() < T_0 < T[-1]


def _elastic_response(model, w):
    plant = ac.compile(model)
    guess = {n: (pt.RHO * pt.G * pt.H if n.endswith(".p") else pt.Q_0)
             for n in plant.states if n.startswith("penstock.")}
    op = ac.steady_state(plant, hold=["turbine.flange.phi"], guess=guess)
    sys = ac.linearize(plant, inputs=["gate.offset"], outputs=["turbine.T_t"], at=op)
    return np.asarray(sys.freqresp(w)).reshape(-1)


def _exact_11_109(s, H_pq):
    alpha, _, gamma, _, K = _closed_form()
    k = pt.A_0**2 / (alpha * pt.RHO * pt.Q_0)
    return 2 / gamma * K * (1 - gamma * k * H_pq) / (1 + k * H_pq)


def test_compressible_penstock_tends_to_11_119():
    """The rigid column swapped for a LumpedLine, nothing else changed: its response
    tends, at first order in 1/n, to (11.109) with the compressible pipe's
    H_pq = (rho c/A_p) tanh(L s/c) (11.119), up to the quarter-wave resonance at
    6.3 rad/s, where the rigid column's (11.111) is off by half."""
    w = np.array([0.1, 0.5, 1.0, 2.0, 4.0, 6.0])
    s = 1j * w
    exact = _exact_11_109(s, pt.RHO * pt.C / pt.A_P * np.tanh(pt.L * s / pt.C))
    rigid = _exact_11_109(s, pt.RHO * pt.L * s / pt.A_P)

    class Coarse(pt.ElasticPeltonPlant):
        penstock = ac.library.hydraulics.LumpedLine(
            n=10, form="hybrid", L=pt.L, A=pt.A_P, rho=pt.RHO, beta=pt.RHO * pt.C**2,
            p_start=pt.RHO * pt.G * pt.H, q_start=pt.Q_0)
    err_20 = np.abs(_elastic_response(pt.ElasticPeltonPlant(), w) / exact - 1)
    err_10 = np.abs(_elastic_response(Coarse(), w) / exact - 1)
    assert np.max(err_20) < 3e-2
    # first order (below 6 rad/s: near the resonance the error changes sign)
    ratio = err_10[:-1] / err_20[:-1]
    assert np.all((1.8 < ratio) & (ratio < 2.2))
    assert np.abs(rigid[-1] / exact[-1] - 1) > 0.5
