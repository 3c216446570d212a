"""Orientation algebra of spatial frames (Modelica.Mechanics.MultiBody.Frames), on sympy
matrices of the frames' variables.

R (MSL ``R.T``) maps world coordinates to frame coordinates: v_frame = R v_0.  A frame b
turned relative to a frame a by R_rel has R_b = R_rel R_a (MSL absoluteRotation).
resolve1(R, v) = R^T v takes a vector from the frame to the world (or to the parent),
resolve2(R, v) = R v the other way.

With R(t) orthogonal, der(R) = -skew(w) R (Egeland & Gravdahl (6.256)-(6.257), written
for the transpose), w the angular velocity resolved in the frame, so

    skew(w) = -der(R) R^T                                        (angular_velocity2)

Euler parameters (quaternion) Q = (q_1, q_2, q_3, q_4) = (n sin(phi/2), cos(phi/2)), the
MSL order (Egeland & Gravdahl's epsilon, eta, (6.160)):

    R(Q) = ((q_4^2 - q^T q) I + 2 q q^T - 2 q_4 skew(q)) / (Q^T Q)   (E&G (6.164), transposed)
    der(Q) = 1/2 G(Q)^T w + lam/2 (1 - Q^T Q) Q                   (E&G (6.329)-(6.336))

where G(Q) is the 3x4 matrix of MSL Quaternions.angularVelocity2, w = 2 G(Q) der(Q).
The second term is the normalization of E&G section 6.9.6: with e = 1 - Q^T Q it gives
der(e) = -lam e (1 - e), so a drift of |Q| decays with the time constant 1/lam.

R(Q) is written in its homogeneous form, divided by Q^T Q (on the unit sphere it is
E&G's (2 q_4^2 - 1) I + 2 q q^T - 2 q_4 skew(q)): it is then orthogonal for every Q != 0
and depends on the direction of Q only, so a drift of |Q| never reaches the bodies, and
the angular velocity the bodies compute from R is exactly w (G(Q) Q = 0 and
G(Q) G(Q)^T = Q^T Q I).  Without the division a drift of 1e-6 in |Q| made R
non-orthogonal by as much, and the stabilization then fought the bodies' dynamics.
"""
from __future__ import annotations

import numpy as np
from acausal._sympy import sympy as sp

__all__ = ["orientation", "position", "force", "torque", "vector", "skew",
           "planar_rotation", "axis_rotation", "axes_rotations", "from_nxy", "to_Q",
           "from_Q", "quaternion_rates", "angular_velocity2", "angular_velocity1",
           "resolve1", "resolve2", "resolve_dyade1", "unit"]


def vector(*entries) -> sp.Matrix:
    """A 3-vector (column) of expressions or numbers."""
    return sp.Matrix(entries)


def orientation(frame) -> sp.Matrix:
    """The frame's R as a 3x3 matrix of its variables."""
    return sp.Matrix(3, 3, [frame.R11, frame.R12, frame.R13, frame.R21, frame.R22,
                            frame.R23, frame.R31, frame.R32, frame.R33])


def position(frame) -> sp.Matrix:
    """r_0, the frame origin in world coordinates."""
    return vector(frame.x, frame.y, frame.z)


def force(frame) -> sp.Matrix:
    """f, the cut force on the component, in frame coordinates."""
    return vector(frame.fx, frame.fy, frame.fz)


def torque(frame) -> sp.Matrix:
    """t, the cut torque on the component, in frame coordinates."""
    return vector(frame.tx, frame.ty, frame.tz)


def skew(v) -> sp.Matrix:
    """skew(v) u = v x u."""
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


def unit(n) -> sp.Matrix:
    """n / |n| (n of parameters: the normalization stays symbolic, as MSL's
    Modelica.Math.Vectors.normalizeWithAssert)."""
    n = sp.Matrix(n)
    return n / sp.sqrt(n.dot(n))


def planar_rotation(e, phi) -> sp.Matrix:
    """R_rel of a rotation by phi about the unit axis e (MSL Frames.planarRotation):
    R_rel = e e^T + (I - e e^T) cos(phi) - skew(e) sin(phi)."""
    e = sp.Matrix(e)
    eet = e * e.T
    return eet + (sp.eye(3) - eet) * sp.cos(phi) - skew(e) * sp.sin(phi)


def axis_rotation(axis: int, angle) -> sp.Matrix:
    """R_rel of a rotation by angle about the frame's axis 1, 2 or 3 (MSL
    Frames.TransformationMatrices.axisRotation)."""
    c, s = sp.cos(angle), sp.sin(angle)
    if axis == 1:
        return sp.Matrix([[1, 0, 0], [0, c, s], [0, -s, c]])
    if axis == 2:
        return sp.Matrix([[c, 0, -s], [0, 1, 0], [s, 0, c]])
    return sp.Matrix([[c, s, 0], [-s, c, 0], [0, 0, 1]])


def axes_rotations(sequence, angles) -> sp.Matrix:
    """R_rel of three rotations in turn, about the axes ``sequence`` (e.g. (1, 2, 3)) of
    the frame turned so far by ``angles`` (MSL Frames.axesRotations):
    R = R_seq3(angles_3) R_seq2(angles_2) R_seq1(angles_1)."""
    R = sp.eye(3)
    for axis, angle in zip(sequence, angles):
        R = axis_rotation(axis, angle) * R
    return R


def from_nxy(n_x, n_y) -> np.ndarray:
    """The orientation (numbers) of a frame whose x axis is along n_x and whose x-y plane
    holds n_y (MSL Frames.TransformationMatrices.from_nxy, with its fallbacks for a
    zero or a parallel n_y)."""
    n_x, n_y = np.asarray(n_x, dtype=float), np.asarray(n_y, dtype=float)
    e_x = n_x / np.linalg.norm(n_x) if np.linalg.norm(n_x) >= 1e-10 else np.eye(3)[0]
    e_y = n_y / np.linalg.norm(n_y) if np.linalg.norm(n_y) >= 1e-10 else np.eye(3)[1]
    n_z = np.cross(e_x, e_y)
    if n_z @ n_z <= 1e-6:
        e_y = np.eye(3)[1] if abs(e_x[0]) > 1e-6 else np.eye(3)[0]
    e_z = np.cross(e_x, e_y)
    e_z /= np.linalg.norm(e_z)
    return np.array([e_x, np.cross(e_z, e_x), e_z])


def to_Q(T) -> np.ndarray:
    """Euler parameters (numbers) of the orientation matrix T (MSL
    Frames.TransformationMatrices.to_Q, the largest of the four candidates first, so
    that no division is by a small number; the scalar part is made >= 0)."""
    T = np.asarray(T, dtype=float)
    trace = np.trace(T)
    paux = max(trace, T[0, 0], T[1, 1], T[2, 2])
    if paux == trace:
        q4 = np.sqrt(1.0 + trace) / 2
        Q = np.array([(T[1, 2] - T[2, 1]) / (4 * q4), (T[2, 0] - T[0, 2]) / (4 * q4),
                      (T[0, 1] - T[1, 0]) / (4 * q4), q4])
    else:
        k = int(np.argmax(np.diag(T)))
        i, j = (k + 1) % 3, (k + 2) % 3
        qk = np.sqrt(1.0 + 2 * T[k, k] - trace) / 2
        Q = np.empty(4)
        Q[k] = qk
        Q[i] = (T[k, i] + T[i, k]) / (4 * qk)
        Q[j] = (T[k, j] + T[j, k]) / (4 * qk)
        Q[3] = (T[i, j] - T[j, i]) / (4 * qk)
    return Q if Q[3] >= 0 else -Q


def from_Q(Q, Q_2=None) -> sp.Matrix:
    """R of the Euler parameters Q = (q_1, q_2, q_3, q_4), q_4 the scalar part (MSL
    Frames.Quaternions.to_T in its homogeneous form, module docstring):
    ((q_4^2 - q^T q) I + 2 q q^T - 2 q_4 skew(q)) / Q_2, Q_2 = Q^T Q (a variable equal
    to it may be passed: the derivatives index reduction takes then stay short)."""
    q = sp.Matrix(Q[:3])
    qq = q.dot(q)
    if Q_2 is None:
        Q_2 = qq + Q[3]**2
    return ((Q[3]**2 - qq) * sp.eye(3) + 2 * q * q.T - 2 * Q[3] * skew(q)) / Q_2


def _G(Q) -> sp.Matrix:
    q1, q2, q3, q4 = Q
    return sp.Matrix([[q4, q3, -q2, -q1], [-q3, q4, q1, -q2], [q2, -q1, q4, -q3]])


def quaternion_rates(Q, w, lam) -> sp.Matrix:
    """der(Q) for the angular velocity w resolved in the rotated frame, with the
    normalization term of Egeland & Gravdahl (6.336):
    der(Q) = 1/2 G(Q)^T w + lam/2 (1 - Q^T Q) Q."""
    Q = sp.Matrix(Q)
    return _G(Q).T * sp.Matrix(w) / 2 + lam / 2 * (1 - Q.dot(Q)) * Q


def angular_velocity2(R, Rdot) -> sp.Matrix:
    """w resolved in the frame, from skew(w) = -der(R) R^T."""
    W = -Rdot * R.T
    return vector(W[2, 1], W[0, 2], W[1, 0])


def angular_velocity1(R, Rdot) -> sp.Matrix:
    """w resolved in the parent (world): R^T angular_velocity2."""
    return R.T * angular_velocity2(R, Rdot)


def resolve1(R, v) -> sp.Matrix:
    """R^T v: a vector in frame coordinates, in the parent (world) coordinates."""
    return R.T * sp.Matrix(v)


def resolve2(R, v) -> sp.Matrix:
    """R v: a vector in parent (world) coordinates, in frame coordinates."""
    return R * sp.Matrix(v)


def resolve_dyade1(R, D) -> sp.Matrix:
    """R^T D R: a tensor given in the frame, in the parent's coordinates (MSL
    Frames.TransformationMatrices.resolveDyade1)."""
    return R.T * sp.Matrix(D) * R
