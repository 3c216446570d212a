"""MB-11/MB-12: the planar two-link manipulator (Egeland & Gravdahl, 001 §8.2.8-8.2.11).

The book's Lagrangian model in joint coordinates q = (q_1, q_2), q_2 relative to link 1,
angles from the horizontal, gravity in -y:

    m_11 = I_1z + I_2z + m_1 L_c1^2 + m_2 (L_1^2 + L_c2^2 + 2 L_1 L_c2 cos q_2)   (8.77)
    m_12 = m_21 = I_2z + m_2 L_c2^2 + m_2 L_1 L_c2 cos q_2                        (8.78)
    m_22 = I_2z + m_2 L_c2^2                                                      (8.79)
    U = (m_1 g L_c1 + m_2 g L_1) sin q_1 + m_2 g L_c2 sin(q_1 + q_2)                (8.80)

    M(q) q'' + C(q, q') q' + g(q) = tau                                           (8.56)

with C from the Christoffel symbols c_ijk = (dm_kj/dq_i + dm_ki/dq_j - dm_ij/dq_k)/2
(8.58), N = M' - 2C skew-symmetric (8.67)-(8.70), and E = q'^T M q'/2 + U obeying
E' = q'^T tau (8.73): the manipulator is passive from tau to q'.

The manipulator is assembled as a user would from the planar multibody library (two
Revolutes, massless FixedTranslations to each link's centre of mass and to the elbow, two
Bodies), driven by two sine torques.  Checked:

* the trajectory against scipy's solve_ivp (DOP853, rtol 1e-11) on the book's equations
  (8.77)-(8.80), (8.56), error relative to each signal's range;
* N = M' - 2C is skew: exactly (sympy) and at sample points to round-off of |M'| + |C|;
* the energy balance E(t) - E(0) = int_0^t q'^T tau dt along acausal's trajectory, E
  taken from the book's (8.77)-(8.80) and the power from the simulated joint speeds.
"""
import numpy as np
import pytest
import sympy as sp
from scipy.integrate import cumulative_simpson, solve_ivp

import acausal as ac
from acausal.library.blocks import Sine
from acausal.library.multibody import Body, FixedFrame, FixedTranslation, Revolute
from acausal.library.rotational import Torque

M1, M2, L1, LC1, LC2, I1, I2, G = 2.0, 1.5, 0.8, 0.4, 0.35, 0.12, 0.08, 9.81
Q0 = (0.3, -0.5)
W0 = (0.0, 0.4)
TAU = ((6.0, 0.5, 0.0), (-2.0, 0.8, 0.7))   # amplitude, frequency (Hz), phase
T_END = 3.0


class TwoLinkManipulator(ac.Component):
    """Two links on revolute joints, each driven by a sine torque (001 §8.2.10, Fig. 8.4)."""

    world = FixedFrame()
    shoulder = Revolute(phi={"start": Q0[0], "fixed": True}, w={"start": W0[0], "fixed": True})
    to_c1 = FixedTranslation(rx=LC1, ry=0.0)
    link1 = Body(m=M1, J=I1, g=G)
    to_elbow = FixedTranslation(rx=L1, ry=0.0)
    elbow = Revolute(phi={"start": Q0[1], "fixed": True}, w={"start": W0[1], "fixed": True})
    to_c2 = FixedTranslation(rx=LC2, ry=0.0)
    link2 = Body(m=M2, J=I2, g=G)
    torque1_signal = Sine(amplitude=TAU[0][0], f=TAU[0][1], phase=TAU[0][2])
    torque2_signal = Sine(amplitude=TAU[1][0], f=TAU[1][1], phase=TAU[1][2])
    motor1 = Torque()
    motor2 = Torque()

    def equations(self):
        return [ac.connect(self.world.frame, self.shoulder.frame_a),
                ac.connect(self.shoulder.frame_b, self.to_c1.frame_a, self.to_elbow.frame_a),
                ac.connect(self.to_c1.frame_b, self.link1.frame),
                ac.connect(self.to_elbow.frame_b, self.elbow.frame_a),
                ac.connect(self.elbow.frame_b, self.to_c2.frame_a),
                ac.connect(self.to_c2.frame_b, self.link2.frame),
                ac.connect(self.torque1_signal.y, self.motor1.tau),
                ac.connect(self.torque2_signal.y, self.motor2.tau),
                ac.connect(self.motor1.flange, self.shoulder.flange),
                ac.connect(self.motor2.flange, self.elbow.flange)]


def _book_model():
    """M, C, g and U of (8.77)-(8.80), (8.58) as sympy expressions."""
    q1, q2, w1, w2 = sp.symbols("q1 q2 w1 w2", real=True)
    q, w = [q1, q2], [w1, w2]
    m11 = I1 + I2 + M1 * LC1**2 + M2 * (L1**2 + LC2**2 + 2 * L1 * LC2 * sp.cos(q2))
    m12 = I2 + M2 * LC2**2 + M2 * L1 * LC2 * sp.cos(q2)
    m22 = I2 + M2 * LC2**2
    M = sp.Matrix([[m11, m12], [m12, m22]])
    U = (M1 * G * LC1 + M2 * G * L1) * sp.sin(q1) + M2 * G * LC2 * sp.sin(q1 + q2)
    C = sp.zeros(2, 2)
    for k in range(2):
        for j in range(2):
            C[k, j] = sum(sp.Rational(1, 2) * (sp.diff(M[k, j], q[i]) + sp.diff(M[k, i], q[j])
                                               - sp.diff(M[i, j], q[k])) * w[i]
                          for i in range(2))
    gvec = sp.Matrix([sp.diff(U, qi) for qi in q])
    Mdot = sp.Matrix(2, 2, lambda a, b: sum(sp.diff(M[a, b], q[i]) * w[i] for i in range(2)))
    return (q1, q2, w1, w2), M, C, gvec, U, Mdot


def _torques(t):
    t = np.asarray(t, dtype=float)
    return np.array([a * np.sin(2 * np.pi * f * t + p) for a, f, p in TAU])


@pytest.fixture(scope="module")
def book():
    syms, M, C, gvec, U, Mdot = _book_model()
    f = {name: sp.lambdify(syms, expr, "numpy")
         for name, expr in (("M", M), ("C", C), ("g", gvec), ("U", U), ("Mdot", Mdot))}
    return syms, (M, C, gvec, U, Mdot), f


@pytest.fixture(scope="module")
def result():
    return ac.simulate(TwoLinkManipulator(), t_end=T_END, rtol=1e-10, n_points=3001,
                       raise_on_failure=True)


def test_trajectory_matches_the_book_equations(book, result):
    _, _, f = book

    def rhs(t, x):
        q1, q2, w1, w2 = x
        M = np.array(f["M"](q1, q2, w1, w2), dtype=float)
        C = np.array(f["C"](q1, q2, w1, w2), dtype=float)
        g = np.array(f["g"](q1, q2, w1, w2), dtype=float).ravel()
        acc = np.linalg.solve(M, _torques(t) - C @ np.array([w1, w2]) - g)
        return [w1, w2, acc[0], acc[1]]

    ref = solve_ivp(rhs, (0.0, T_END), [*Q0, *W0], method="DOP853", rtol=1e-11,
                    atol=1e-12, t_eval=result.t, dense_output=False)
    assert ref.success
    for k, name in enumerate(("shoulder.phi", "elbow.phi", "shoulder.w", "elbow.w")):
        ours, theirs = result[name], ref.y[k]
        scale = np.ptp(theirs) + np.max(np.abs(theirs))
        assert np.max(np.abs(ours - theirs)) < 1e-7 * scale, name


def test_mdot_minus_2c_is_skew_symmetric(book):
    (q1, q2, w1, w2), (M, C, gvec, U, Mdot), f = book
    N = Mdot - 2 * C
    assert sp.simplify(N + N.T) == sp.zeros(2, 2)
    rng = np.random.default_rng(8)
    for q_a, q_b, w_a, w_b in rng.uniform(-3.0, 3.0, size=(20, 4)):
        Nn = np.array(f["Mdot"](q_a, q_b, w_a, w_b), dtype=float) \
            - 2 * np.array(f["C"](q_a, q_b, w_a, w_b), dtype=float)
        size = np.abs(f["Mdot"](q_a, q_b, w_a, w_b)).max() \
            + np.abs(np.array(f["C"](q_a, q_b, w_a, w_b), dtype=float)).max()
        # skew to round-off (the exact identity is the sympy check above)
        assert np.max(np.abs(Nn + Nn.T)) <= 1e-12 * size
        # N is not zero: the check is not vacuous
        assert np.max(np.abs(Nn)) > 1e-3 * size


def test_energy_rate_is_joint_power(book, result):
    _, _, f = book
    q1, q2 = result["shoulder.phi"], result["elbow.phi"]
    w1, w2 = result["shoulder.w"], result["elbow.w"]
    M = np.array([np.asarray(f["M"](a, b, c, d), dtype=float)
                  for a, b, c, d in zip(q1, q2, w1, w2)])
    kinetic = 0.5 * np.einsum("ti,tij,tj->t", np.stack([w1, w2], 1), M, np.stack([w1, w2], 1))
    energy = kinetic + f["U"](q1, q2, w1, w2)
    power = np.sum(_torques(result.t) * np.stack([w1, w2]), axis=0)
    work = cumulative_simpson(power, x=result.t, initial=0.0)
    change = energy - energy[0]
    assert np.max(np.abs(change)) > 1.0            # torques do real work on the arm
    assert np.max(np.abs(change - work)) < 1e-6 * np.max(np.abs(change))
