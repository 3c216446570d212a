"""StateSpace against closed forms (Egeland & Gravdahl 1.3, 2.1) and scipy.signal."""
import numpy as np
import pytest
import scipy.signal as ss

from acausal.analysis import StateSpace

m, d, k = 2.0, 0.4, 50.0                       # mass-spring-damper (2.8)
w0, zeta = np.sqrt(k / m), d / (2 * np.sqrt(k * m))


def msd():
    """x'' = (F - d x' - k x)/m, output x."""
    return StateSpace([[0, 1], [-k / m, -d / m]], [[0], [1 / m]], [[1, 0]], [[0]],
                      states=["x", "v"], inputs=["F"], outputs=["x"])


def test_mass_spring_damper_poles_and_resonance_2_14_2_16():
    sys = msd()
    wd = w0 * np.sqrt(1 - zeta**2)
    assert sys.poles() == pytest.approx([-zeta * w0 - 1j * wd, -zeta * w0 + 1j * wd], rel=1e-12)
    H = sys.freqresp([w0])[0]
    assert H == pytest.approx(-1j / (2 * zeta * k), rel=1e-12)      # (2.16)
    w, mag, phase = sys.bode([w0])
    assert phase[0] == pytest.approx(-90.0, abs=1e-9)
    assert sys.dcgain()[0, 0] == pytest.approx(1 / k, rel=1e-12)


def test_transfer_function_and_conversions_match_scipy():
    sys = msd()
    num, den = sys.tf()
    assert sys.transfer_functions()["x", "F"][0] == pytest.approx(num, rel=1e-15)
    assert num == pytest.approx([1 / m], rel=1e-12)
    assert den == pytest.approx([1.0, d / m, k / m], rel=1e-12)
    back = StateSpace.from_scipy(sys.to_scipy())
    assert np.allclose(back.freqresp([0.3, 3.0, 30.0]), sys.freqresp([0.3, 3.0, 30.0]))
    lti = ss.lti([1.0, 2.0], [1.0, 3.0, 5.0, 1.0])
    assert np.allclose(StateSpace.from_scipy(lti).tf()[1], [1.0, 3.0, 5.0, 1.0])


def test_step_and_impulse_responses_match_scipy():
    sys = msd()
    t = np.linspace(0.0, 10.0, 401)
    _, y = sys.step(t)
    _, y_ref = ss.step(sys.to_scipy(), T=t)
    assert np.allclose(y[:, 0], y_ref, atol=1e-9 * np.abs(y_ref).max())
    _, h = sys.impulse(t)
    _, h_ref = ss.impulse(sys.to_scipy(), T=t)
    assert np.allclose(h[:, 0], h_ref, atol=1e-9 * np.abs(h_ref).max())


def test_margins_of_an_integrator_with_a_lag():
    """L = 1/(s (s + 1)): w_c^2 = (sqrt(5) - 1)/2, phase margin 90 - atan(w_c), no w_180."""
    L = StateSpace.from_tf([1.0], [1.0, 1.0, 0.0])
    wc = np.sqrt((np.sqrt(5) - 1) / 2)
    marg = L.margins()
    assert marg.w_c == pytest.approx(wc, rel=1e-12)
    assert marg.phase == pytest.approx(90 - np.degrees(np.arctan(wc)), rel=1e-12)
    assert np.isinf(marg.gain)


def test_zeros_of_a_square_system_and_minimal_realization():
    # H = (s + 2)/((s + 1)(s + 3)) realized with a cancelled extra mode at -5
    A = np.diag([-1.0, -3.0, -5.0])
    B = np.array([[1.0], [1.0], [1.0]])
    C = np.array([[0.5, 0.5, 0.0]])
    sys = StateSpace(A, B, C)
    assert sys.minimal().n_states == 2
    assert sys.zeros() == pytest.approx([-2.0], rel=1e-12)
    with pytest.raises(ValueError, match="as many outputs as inputs"):
        StateSpace(A, B, np.vstack([C, C])).zeros()


def test_feedback_and_series():
    P = StateSpace.from_tf([1.0], [1.0, 1.0])                 # 1/(s + 1)
    K = StateSpace.from_tf([2.0, 1.0], [1.0, 0.0])            # PI: (2 s + 1)/s
    closed = P.series(K).feedback()                            # 1/(s+1) (2s+1)/s / (1 + ..)
    # characteristic polynomial s (s + 1) + 2 s + 1 = s^2 + 3 s + 1
    assert np.sort(closed.poles().real) == pytest.approx(np.sort(np.roots([1, 3, 1])), rel=1e-12)
    assert closed.dcgain()[0, 0] == pytest.approx(1.0, rel=1e-12)


def test_bode_plot_draws():
    pytest.importorskip("matplotlib")
    import matplotlib
    matplotlib.use("Agg")
    w, mag, phase = msd().bode(plot=True)
    assert len(w) == len(mag) == len(phase) and mag.max() == pytest.approx(
        20 * np.log10(1 / (2 * zeta * np.sqrt(1 - zeta**2) * k)), abs=0.05)
