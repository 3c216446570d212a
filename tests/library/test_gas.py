"""Gas components (Egeland & Gravdahl 14.1.2, 14.4.5, 14.5.9) against closed forms,
hand linearizations and scipy's solve_ivp on the hand-written equations."""
import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import root

import acausal as ac
from acausal.library.gas.examples import moore_greitzer as mg

H, W, PSI_C0, SIGMA, GAMMA_T, L_C = mg.H, mg.W, mg.PSI_C0, mg.SIGMA, mg.GAMMA_T, mg.L_C


# -- Moore-Greitzer (14.1)-(14.3), written by hand -------------------------------------------
def _mg3(t, x, B):
    Psi, Phi, J = x
    m = Phi / W - 1
    return [(Phi - GAMMA_T * np.sqrt(Psi)) / (4 * L_C * B**2),
            H / L_C * (-(Psi - PSI_C0) / H + 1 + 1.5 * m * (1 - J / 2) - 0.5 * m**3),
            J * (1 - m**2 - J / 4) * SIGMA]


def _mg3_jacobian(x, B):
    Psi, Phi, J = x
    m = Phi / W - 1
    return np.array([
        [-GAMMA_T / (2 * np.sqrt(Psi)) / (4 * L_C * B**2), 1 / (4 * L_C * B**2), 0],
        [-1 / L_C, H / L_C * (1.5 * (1 - J / 2) - 1.5 * m**2) / W, -H / L_C * 0.75 * m],
        [0, -2 * SIGMA * J * m / W, SIGMA * (1 - m**2 - J / 2)]])


def _stall_closed_form():
    """The stall equilibrium: J = 4 (1 - m^2) from (14.3), then (14.2) gives
    Psi = psi_c0 + H (1 - 3m/2 + 5m^3/2), and the throttle W (1 + m) = gamma_T sqrt(Psi):
    a cubic in m = Phi/W - 1, with one root in (-1, 1) for these data."""
    g2 = GAMMA_T**2
    roots = np.roots([2.5 * H * g2, -W**2, -(1.5 * H * g2 + 2 * W**2), g2 * (PSI_C0 + H) - W**2])
    m = [r.real for r in roots if abs(r.imag) < 1e-12 and -1 < r.real < 1]
    assert len(m) == 1
    m = m[0]
    return np.array([PSI_C0 + H * (1 - 1.5 * m + 2.5 * m**3), W * (1 + m), 4 * (1 - m**2)])


def test_stall_equilibrium_closed_form_and_root_finder_agree():
    closed = _stall_closed_form()
    sol = root(lambda x: _mg3(0.0, x, 0.1), [0.4, 0.3, 3.5], method="hybr", tol=1e-13)
    assert sol.success and np.max(np.abs(_mg3(0.0, sol.x, 0.1))) < 1e-14
    assert np.allclose(sol.x, closed, rtol=1e-12, atol=0)
    # INVENTORY TF-08 (scipy LSODA, t = 500): Psi 0.4133, Phi 0.3215, J 3.673
    assert np.allclose(closed, [0.4133, 0.3215, 3.673], atol=6e-4)


@pytest.fixture(scope="module")
def stall():
    return ac.simulate(mg.RotatingStall(), t_end=mg.RotatingStall.stop_time, rtol=1e-8,
                       raise_on_failure=True)


def test_rotating_stall_settles_at_the_closed_form_equilibrium(stall):
    """B = 0.1: the component model falls into rotating stall, J > 0 (Figure 14.2)."""
    closed = _stall_closed_form()
    end = np.array([stall["plenum.psi"][-1], stall["compressor.phi"][-1],
                    stall["compressor.J"][-1]])
    assert np.allclose(end, closed, rtol=1e-6, atol=0)
    op = ac.steady_state(ac.compile(mg.RotatingStall()), guess={
        "plenum.psi": 0.4, "compressor.phi": 0.3, "compressor.J": 3.5})
    assert np.allclose([op["plenum.psi"], op["compressor.phi"], op["compressor.J"]], closed,
                       rtol=1e-9, atol=0)


def test_rotating_stall_linearization_is_the_hand_jacobian():
    closed = _stall_closed_form()
    sys = ac.linearize(mg.RotatingStall(), at={"plenum.psi": closed[0],
                                               "compressor.phi": closed[1],
                                               "compressor.J": closed[2]})
    hand = np.linalg.eigvals(_mg3_jacobian(closed, 0.1))
    poles = sys.poles()
    assert np.max(np.abs(np.sort_complex(poles) - np.sort_complex(hand))) \
        < 1e-8 * np.max(np.abs(hand))
    assert np.all(hand.real < 0)                # the stall point attracts


@pytest.fixture(scope="module")
def surge():
    return ac.simulate(mg.Surge(), t_end=mg.Surge.stop_time, rtol=1e-10, n_points=6001,
                       raise_on_failure=True)


def test_surge_follows_dop853(surge):
    """B = 1 against DOP853 at rtol 1e-10 on (14.1)-(14.3), over the first four surge
    cycles (the phase error of any integrator grows along a limit cycle)."""
    t = surge.t[surge.t <= 130.0]
    ref = solve_ivp(_mg3, (0.0, t[-1]), [0.6, 0.6, 0.1], args=(1.0,), method="DOP853",
                    rtol=1e-10, atol=1e-12, t_eval=t)
    k = t.size
    for name, row in (("plenum.psi", 0), ("compressor.phi", 1)):
        err = np.max(np.abs(surge[name][:k] - ref.y[row]))
        assert err < 1e-6 * np.ptp(ref.y[row]), (name, err)
    J_err = np.max(np.abs(surge["compressor.J"][:k] - ref.y[2]))
    assert J_err < 1e-6 * np.max(ref.y[2])


def _upward_crossings(t, y):
    level = (y.max() + y.min()) / 2
    i = np.where((y[:-1] < level) & (y[1:] >= level))[0]
    return t[i] + (level - y[i]) / (y[i + 1] - y[i]) * (t[i + 1] - t[i])


def test_surge_is_a_limit_cycle_without_stall(surge):
    """B = 1 surges (Figure 14.3): late in the run Phi and Psi repeat with one period,
    the flow reverses, and the stall amplitude has died out."""
    late = surge.t >= 150.0
    t, phi, psi = surge.t[late], surge["compressor.phi"][late], surge["plenum.psi"][late]
    periods = np.diff(_upward_crossings(t, phi))
    assert len(periods) >= 3
    T = periods.mean()
    assert np.ptp(periods) < 1e-3 * T
    # one period later the state is where it was (interpolated on the output grid)
    for y in (phi, psi):
        again = np.interp(t[t < t[-1] - T] + T, t, y)
        assert np.max(np.abs(again - y[t < t[-1] - T])) < 5e-3 * np.ptp(y)
    # the period of the hand-written equations' cycle
    ref = solve_ivp(_mg3, (0.0, 300.0), [0.6, 0.6, 0.1], args=(1.0,), method="DOP853",
                    rtol=1e-10, atol=1e-12, dense_output=True)
    tr = np.linspace(150.0, 300.0, 15001)
    T_ref = np.diff(_upward_crossings(tr, ref.sol(tr)[1])).mean()
    assert T == pytest.approx(T_ref, rel=1e-4)
    assert phi.min() < -0.15 and phi.max() > 0.7         # deep surge, reverse flow
    assert 0.15 < psi.min() and psi.max() < 0.75
    assert np.max(np.abs(surge["compressor.J"][late])) < 1e-12


def test_energy_audit_refuses_gas_ports():
    """p m_flow (or psi phi) is not a power: the audit says so instead of booking it."""
    model = mg.Surge()
    res = ac.simulate(model, t_end=1.0)
    with pytest.raises(ValueError, match="not a power"):
        ac.energy_balance(res, model)
