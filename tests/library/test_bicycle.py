"""The Whipple bicycle against the published benchmark of Meijaard, Papadopoulos, Ruina
& Schwab (2007), Proc. R. Soc. A 463, 1955-1982: the matrices M, C1, K0, K2 printed in
section 5 for the Table 1 parameters, the eigenvalues of Table 2 at v = 0 ... 10 m/s,
its weave, capsize and bifurcation speeds (Table 2 (a)), and a simulated response
against the matrix exponential of the linear system written with the printed matrices.
"""
import numpy as np
import pytest
from scipy.linalg import expm
from scipy.optimize import brentq

import acausal as ac
from acausal.library.multibody3d.bicycle import WhippleBicycle
from acausal.library.multibody3d.examples.bicycle import BenchmarkBicycle

G = 9.81
# section 5 of the paper (printed to 14 digits; the same values are in the benchmark's
# later reproductions, e.g. Meijaard et al. 2011 and the BicycleParameters package)
M = np.array([[80.81722, 2.31941332208709], [2.31941332208709, 0.29784188199686]])
C1 = np.array([[0.0, 33.86641391492494], [-0.85035641456978, 1.68540397397560]])
K0 = np.array([[-80.95, -2.59951685249872], [-2.59951685249872, -0.80329488458618]])
K2 = np.array([[0.0, 76.59734589573222], [0.0, 2.65431523794604]])

# Table 2 (b), (c): the eigenvalues at v = 0, 1, ..., 10 m/s
TABLE_2 = {
    0: [-5.53094371765393, -3.13164324790656, 3.13164324790656, 5.53094371765393],
    1: [-7.11008014637442, -3.13423125066578, 3.52696170990070 + 0.80774027519930j],
    2: [-8.67387984831735, -3.07158645641514, 2.68234517512745 + 1.68066296590675j],
    3: [-10.35101467245920, -2.63366137253667, 1.70675605663975 + 2.31582447384325j],
    4: [-12.15861426576450, -1.42944427361326, 0.41325331521125 + 3.07910818603206j],
    5: [-14.07838969279820, -0.32286642900409, -0.77534188219585 + 4.46486771378823j],
    6: [-16.08537123098030, -0.00406690076970, -1.52644486584142 + 5.87673060598709j],
    7: [-18.15788466125262, 0.10268170574766, -2.13875644258362 + 7.19525913329805j],
    8: [-20.27940894394569, 0.14327879765713, -2.69348683581097 + 8.46037971396931j],
    9: [-22.43788559040858, 0.15790184030917, -3.21675402252485 + 9.69377351531791j],
    10: [-24.62459635017404, 0.16105338653172, -3.72016840437287 + 10.90681139476287j],
}
V_WEAVE, V_CAPSIZE = 4.29238253634111, 6.02426201538837       # Table 2 (a)
V_BIFURCATION, DOUBLE_ROOT = 0.68428307889246, 3.78290405129320
WEAVE_FREQUENCY = 3.43503384866144                            # rad/s, at v = v_w


def _published(values):
    full = [complex(x) for x in values]
    full += [z.conjugate() for z in full if z.imag != 0]
    return np.sort_complex(np.array(full))


@pytest.fixture(scope="module")
def compiled():
    return ac.compile(BenchmarkBicycle())


def _poles(compiled, v):
    return np.sort_complex(ac.linearize(compiled, at={"bike.v": v}).poles())


def test_matrices_of_appendix_a_reproduce_the_printed_ones():
    """M, C1, K0, K2 read back from the linearization of the component, its torques
    the inputs: with x = (q, q'), B = [0; M^-1] and
    A = [0 I; -M^-1 (g K0 + v^2 K2)  -M^-1 v C1]."""
    at_0 = ac.linearize(WhippleBicycle(v=1e-3), inputs=["T_phi", "T_delta"], at={"v": 0.0})
    at_1 = ac.linearize(WhippleBicycle(v=1e-3), inputs=["T_phi", "T_delta"], at={"v": 1.0})
    assert list(at_0.states[:2]) == ["q[0]", "q[1]"]
    M_got = np.linalg.inv(at_0.B[2:])
    K0_got = -M_got @ at_0.A[2:, :2] / G
    K2_got = -M_got @ at_1.A[2:, :2] - G * K0_got
    C1_got = -M_got @ at_1.A[2:, 2:]
    for got, want in ((M_got, M), (C1_got, C1), (K0_got, K0), (K2_got, K2)):
        np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-12 * np.abs(want).max())


def test_eigenvalues_of_table_2(compiled):
    for v, published in TABLE_2.items():
        np.testing.assert_allclose(_poles(compiled, float(v)), _published(published),
                                   rtol=1e-12, atol=1e-12)


def test_weave_and_capsize_speeds_of_table_2(compiled):
    """The self-stable range: where the largest real part of the linearization's
    eigenvalues crosses zero, found by root-finding on ac.linearize."""
    def abscissa(v):
        return _poles(compiled, v).real.max()
    v_w = brentq(abscissa, 4.0, 5.0, xtol=1e-14)
    v_c = brentq(abscissa, 5.5, 7.0, xtol=1e-14)
    assert abs(v_w - V_WEAVE) < 1e-11 and abs(v_c - V_CAPSIZE) < 1e-11
    weave = _poles(compiled, V_WEAVE)
    assert np.abs(weave.imag).max() == pytest.approx(WEAVE_FREQUENCY, rel=1e-12)
    assert abscissa(0.5 * (v_w + v_c)) < 0 and abscissa(v_w - 0.1) > 0 \
        and abscissa(v_c + 0.1) > 0


def test_bifurcation_speed_of_table_2(compiled):
    """At v_d the two unstable real roots meet (then become the weave pair).  A double
    root splits by the square root of a perturbation: at the printed 14-digit v_d the
    pair may be ~1e-7 apart, about the printed real value."""
    poles = _poles(compiled, V_BIFURCATION)
    unstable = poles[poles.real > 0]
    assert len(unstable) == 2
    np.testing.assert_allclose(unstable.real, DOUBLE_ROOT, rtol=1e-12)
    assert np.abs(unstable - DOUBLE_ROOT).max() < 1e-6 * DOUBLE_ROOT


def test_lean_and_steer_response_against_expm():
    """The example's run (v = 4.6 m/s, lean rate 0.5 rad/s, steer torque 0.05 N m)
    against exp(A t) of the state-space form written with the printed matrices."""
    v, T_delta = 4.6, 0.05
    Minv = np.linalg.inv(M)
    A = np.block([[np.zeros((2, 2)), np.eye(2)],
                  [-Minv @ (G * K0 + v**2 * K2), -v * Minv @ C1]])
    b = np.concatenate([np.zeros(2), Minv @ [0.0, T_delta]])
    # the constant input as a fifth state: d/dt (x, 1) = [[A, b], [0, 0]] (x, 1)
    augmented = np.zeros((5, 5))
    augmented[:4, :4], augmented[:4, 4] = A, b
    x0 = np.array([0.0, 0.0, 0.5, 0.0, 1.0])
    t = np.linspace(0.0, BenchmarkBicycle.stop_time, 101)
    reference = np.array([expm(augmented * tk) @ x0 for tk in t])
    res = ac.simulate(BenchmarkBicycle(), BenchmarkBicycle.stop_time, t_eval=t,
                      rtol=1e-9, atol=1e-11)
    assert res.success
    for name, column in (("bike.phi", 0), ("bike.delta", 1), ("bike.dq[0]", 2)):
        scale = np.abs(reference[:, column]).max()
        assert np.abs(res[name] - reference[:, column]).max() < 1e-6 * scale, name
    # and the steady turn the torque holds: (g K0 + v^2 K2) q_ss = (0, T_delta)
    q_ss = np.linalg.solve(G * K0 + v**2 * K2, [0.0, T_delta])
    np.testing.assert_allclose(-np.linalg.solve(A, b)[:2], q_ss, rtol=1e-12)
