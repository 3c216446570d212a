"""Transfer functions, zeros and minimal realizations of ill-scaled and closed-loop
systems, against closed forms and scipy.signal (analysis/realization.py)."""
import warnings

import numpy as np
import pytest
import scipy.signal as ss

import acausal as ac
from acausal.analysis import StateSpace, linearize
from acausal.analysis import realization
from acausal.analysis.realization import TransferFunctionWarning
from acausal.library.blocks import PID, Feedback, TransferFunction
from acausal.ports import RealInput

# Nomoto's second-order ship model psi/delta = K (1 + T3 s) / (s (1 + T1 s)(1 + T2 s))
# (Fossen, Handbook of Marine Craft Hydrodynamics and Motion Control, 7.2) with a PD
# autopilot  delta = Kp (1 + Td s / (1 + Td s / Nd)) (psi_ref - psi).
K, T1, T2, T3 = 0.2, 100.0, 10.0, 20.0
KP, TD, ND = 2.0, 20.0, 100.0


class ShipAutopilot(ac.Component):
    psi_ref = RealInput()
    error = Feedback()
    pd = PID(k=KP, Ti=float("inf"), Td=TD, Nd=ND)
    ship = TransferFunction(b=[K * T3, K], a=[T1 * T2, T1 + T2, 1.0, 0.0])

    def equations(self):
        return [ac.connect(self.psi_ref, self.error.u1),
                ac.connect(self.error.y, self.pd.u),
                ac.connect(self.pd.y, self.ship.u),
                ac.connect(self.ship.y, self.error.u2)]


def closed_loop_heading():
    """psi/psi_ref = Nc Np / (Dc Dp + Nc Np), monic."""
    Np, Dp = np.array([K * T3, K]), np.polymul(np.polymul([T1, 1.0], [T2, 1.0]), [1.0, 0.0])
    Nc, Dc = KP * np.array([TD * (1 + 1 / ND), 1.0]), np.array([TD / ND, 1.0])
    num, den = np.polymul(Nc, Np), np.polyadd(np.polymul(Dc, Dp), np.polymul(Nc, Np))
    return num / den[0], den / den[0]


@pytest.fixture(scope="module")
def autopilot():
    return linearize(ShipAutopilot(), ["psi_ref"], ["ship.y.signal"])


def _close(a, b, rtol):
    """Same degree and coefficients within rtol (of the largest, for those that are
    round-off next to it)."""
    a = np.trim_zeros(np.atleast_1d(np.asarray(a, float)), "f")
    b = np.trim_zeros(np.atleast_1d(np.asarray(b, float)), "f")
    return len(a) == len(b) and np.allclose(a, b, rtol=rtol,
                                            atol=rtol * np.max(np.abs(b), initial=0.0))


def test_ship_autopilot_transfer_function_is_the_closed_form(autopilot):
    num, den = autopilot.tf()
    num_ref, den_ref = closed_loop_heading()
    assert _close(num, num_ref, 1e-9) and _close(den, den_ref, 1e-9)
    assert autopilot.dcgain()[0, 0] == pytest.approx(1.0, rel=1e-10)   # integrating plant
    zeros_ref = [-1 / (TD * (1 + 1 / ND)), -1 / T3]
    assert np.sort(autopilot.zeros().real) == pytest.approx(np.sort(zeros_ref), rel=1e-9)
    assert np.all(autopilot.zeros().imag == 0)
    # the PD's integral state (Ti = inf) is the one mode the loop does not reach
    assert autopilot.minimal().n_states == 4 == len(den_ref) - 1


@pytest.mark.filterwarnings("ignore::scipy.signal.BadCoefficients")
def test_ship_autopilot_without_cancellation_matches_scipy_ss2tf(autopilot):
    num, den = autopilot.tf(minimal=False)
    num_ref, den_ref = ss.ss2tf(autopilot.A, autopilot.B, autopilot.C, autopilot.D)
    # ss2tf's cancelled leading terms leave round-off behind (1e-15 next to 0.8)
    num_ref = np.where(np.abs(num_ref) < 1e-12 * np.abs(num_ref).max(), 0.0, num_ref)
    assert _close(den, den_ref, 1e-9)
    # the PD's integral state stays: its pole s = 0 and the zero s = 0 that cancels it
    assert _close(num, num_ref[0], 1e-9) and abs(num[-1]) < 1e-12 * abs(num[-2])
    _, p_ref, k_ref = ss.ss2zpk(autopilot.A, autopilot.B, autopilot.C, autopilot.D)
    assert np.sort_complex(autopilot.poles()) == pytest.approx(np.sort_complex(p_ref),
                                                               rel=1e-9, abs=1e-12)
    assert num[0] == pytest.approx(k_ref, rel=1e-9)


def _rescaled(sys, exponents, u_scale=1.0, y_scale=1.0):
    """The same system with states x = S x', u = u_scale u', y' = y_scale y."""
    S = 10.0 ** np.asarray(exponents, float)
    A = sys.A * S[None, :] / S[:, None]
    return StateSpace(A, sys.B / S[:, None] * u_scale, y_scale * sys.C * S[None, :],
                      y_scale * sys.D * u_scale)


@pytest.mark.parametrize("exponents", [[0, 3, -3, 5, -2], [-6, 0, 6, 2, -4],
                                       [4, 4, -4, -4, 0], [8, -8, 3, 0, 1]])
def test_units_of_the_states_do_not_change_the_answer(autopilot, exponents):
    """Heading in mrad, rudder in rad, rates in deg/h...: a diagonal similarity and an
    input/output scaling change H(s) by the constant factor only."""
    scaled = _rescaled(autopilot, exponents, u_scale=1e-3, y_scale=1e4)
    num, den = scaled.tf()
    num_ref, den_ref = closed_loop_heading()
    assert _close(num, 10.0 * num_ref, 1e-8) and _close(den, den_ref, 1e-8)
    assert scaled.minimal().n_states == 4
    assert np.sort_complex(scaled.zeros()) == pytest.approx(
        np.sort_complex(autopilot.zeros()), rel=1e-8)
    assert scaled.dcgain()[0, 0] == pytest.approx(10.0, rel=1e-9)


def _modal(poles, zeros, k):
    """A diagonal realization of k prod(s - z) / prod(s - p) (distinct real poles)."""
    p, z = np.asarray(poles, float), np.asarray(zeros, float)
    r = [k * np.prod(pi - z) / np.prod([pi - pj for pj in p if pj != pi]) for pi in p]
    return StateSpace(np.diag(p), np.ones((len(p), 1)), np.array([r]))


@pytest.mark.parametrize("seed", range(8))
def test_random_ill_scaled_realizations_against_their_closed_form(seed):
    rng = np.random.default_rng(seed)
    n = int(rng.integers(2, 7))
    poles = -np.sort(10.0 ** rng.uniform(-2, 2, n))
    zeros = -10.0 ** rng.uniform(-2, 2, int(rng.integers(0, n))) * rng.choice([-1, 1])
    k = 10.0 ** rng.uniform(-3, 3)
    # a random orthogonal change of coordinates, then units over +-6 decades
    Q, _ = np.linalg.qr(rng.normal(size=(n, n)))
    m = _modal(poles, zeros, k)
    sys = StateSpace(Q.T @ m.A @ Q, Q.T @ m.B, m.C @ Q)
    sys = _rescaled(sys, rng.uniform(-6, 6, n))
    num, den = sys.tf()
    assert _close(den, np.poly(poles), 1e-7)
    assert _close(num, k * np.poly(zeros), 1e-7)
    assert np.sort(sys.zeros().real) == pytest.approx(np.sort(zeros), rel=1e-7)
    w = realization.check_frequencies(np.concatenate([poles, zeros]))
    exact = k * np.polyval(np.atleast_1d(np.poly(zeros)), 1j * w) / np.polyval(np.poly(poles), 1j * w)
    assert np.allclose(np.polyval(num, 1j * w) / np.polyval(den, 1j * w), exact,
                       rtol=1e-7, atol=0)
    # at high frequency H ~ s^-r is a sum of modal terms r_i/(s - p_i) that cancel:
    # the state-space evaluation is judged against the size of those terms
    terms = np.abs(m.C[0][None, :] / (1j * w[:, None] - poles[None, :])).sum(axis=1)
    assert np.all(np.abs(sys.freqresp(w) - exact) <= 1e-9 * terms)


def test_a_nearly_cancelled_mode_is_kept():
    """A pole 5 % from a zero in companion form: its Krylov vectors are nearly parallel,
    but removing the mode would change H by a percent."""
    poles = [-2.52398103, -0.02089437, -0.00919052, -0.00356867, -0.02366384, -0.90534217]
    zeros = [-2.20461867e-02, 5.43426134, -55.9905619]
    sys = StateSpace.from_tf(8687.19 * np.poly(zeros), np.poly(poles))
    assert sys.minimal().n_states == 6
    assert np.sort(sys.zeros().real) == pytest.approx(np.sort(zeros), rel=1e-6)


def test_multivariable_transmission_zero():
    """H = [[1/(s+1), 2/(s+3)], [1/(s+1), 1/(s+1)]]:  det H = (1 - s)/((s+1)^2 (s+3)),
    a right-half-plane transmission zero at s = 1; McMillan degree 3."""
    A = np.diag([-1.0, -3.0, -1.0])
    B = np.array([[1.0, 0.0], [0.0, 1.0], [0.0, 1.0]])
    C = np.array([[1.0, 2.0, 0.0], [1.0, 0.0, 1.0]])
    sys = StateSpace(A, B, C)
    for s in (sys, _rescaled(sys, [5, -4, 2], u_scale=1e3, y_scale=1e-2)):
        assert s.minimal().n_states == 3
        assert s.zeros() == pytest.approx([1.0], rel=1e-9)
    padded = StateSpace(np.diag([-1.0, -3.0, -1.0, -7.0]), np.vstack([B, [1.0, 1.0]]),
                        np.hstack([C, np.zeros((2, 1))]))          # an unobservable mode
    assert padded.minimal().n_states == 3
    assert padded.zeros() == pytest.approx([1.0], rel=1e-9)


def test_biproper_and_static_systems():
    sys = StateSpace.from_tf([3.0, 6.0], [1.0, 1.0])              # 3 (s + 2)/(s + 1)
    num, den = sys.tf()
    assert _close(num, [3.0, 6.0], 1e-12) and _close(den, [1.0, 1.0], 1e-12)
    assert sys.zeros() == pytest.approx([-2.0], rel=1e-12)
    gain = StateSpace.from_tf([2.5], [0.5])
    assert gain.n_states == 0 and gain.dcgain()[0, 0] == pytest.approx(5.0, rel=1e-15)
    P = StateSpace.from_tf([1.0], [1.0, 1.0])
    closed = P.series(StateSpace.from_tf([4.0], [1.0])).feedback()
    assert closed.n_states == 1 and closed.poles() == pytest.approx([-5.0], rel=1e-12)


def test_a_channel_the_input_does_not_reach_is_zero():
    sys = StateSpace(np.diag([-1.0, -2.0]), [[1.0], [0.0]], [[0.0, 1.0]])
    num, den = sys.tf()
    assert np.all(num == 0.0) and _close(den, [1.0], 0)
    with pytest.raises(ValueError, match="not defined"):
        sys.zeros()


def test_a_pole_at_zero_seen_by_the_output_has_no_dc_gain():
    with pytest.raises(ValueError, match="s = 0"):
        StateSpace.from_tf([1.0], [1.0, 1.0, 0.0]).dcgain()


def test_a_wrong_numerator_is_caught_and_recomputed(monkeypatch, autopilot):
    """The check against the state-space frequency response: a numerator that does not
    reproduce H(jw) is replaced (by interpolation of den H) and the user is told."""
    monkeypatch.setattr(realization, "_num_from_zeros", lambda *a: np.array([0.0, 0.0, 0.0]))
    with pytest.warns(TransferFunctionWarning, match="interpolation"):
        num, den = autopilot.tf()
    num_ref, den_ref = closed_loop_heading()
    assert _close(num, num_ref, 1e-8) and _close(den, den_ref, 1e-9)


def test_a_correct_transfer_function_gives_no_warning(autopilot):
    with warnings.catch_warnings():
        warnings.simplefilter("error", TransferFunctionWarning)
        autopilot.tf()
        autopilot.tf(minimal=False)
