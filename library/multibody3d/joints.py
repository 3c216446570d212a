"""Joints of spatial multibody systems (Modelica.Mechanics.MultiBody.Joints).

A joint is massless: it writes frame_b's position and orientation from frame_a's and
its joint coordinates, and frame_a's cut force and torque from frame_b's.  frame_a must
therefore face the World (``acausal.ports.spatial``).  The joint coordinates are
preferred states, as in the MSL, so that an open chain keeps them as its states.

Joints with three rotational degrees of freedom (Spherical, FreeMotion) carry the
relative orientation as Euler parameters Q (a quaternion, four states) with the
normalization of Egeland & Gravdahl (6.336), ``frames.quaternion_rates``:

    der(Q) = 1/2 G(Q)^T w_rel + lam/2 (1 - Q^T Q) Q

e = 1 - Q^T Q then obeys der(e) = -lam e (1 - e): a drift of the norm decays with the
time constant 1/lam.  The default lam = 100 1/s is the value E&G quote (section 6.9.6,
"a time constant of 0.01 s"); the implicit BDF takes the fast mode in its stride.
Euler parameters have no singular orientation, so unlike Cardan angles no orientation
needs to be detected and refused.  R(Q) is divided by Q^T Q (``frames.from_Q``), kept as
the joint's variable Q_2 = Q^T Q: index reduction differentiates R twice, and the
quotient of the full polynomial made the generated code of a free body 3.5 times longer.
"""
from __future__ import annotations

import numpy as np
from acausal._sympy import sympy as sp

import acausal as ac
from acausal.ports import RealOutput, RotationalFlange, TranslationalFlange

from .frames import (axes_rotations, force, from_Q, orientation, planar_rotation, position,
                     quaternion_rates, resolve1, to_Q, torque)
from .interfaces import PartialRigidTwoFrames, PartialTwoFrames, direction, equal, propagate

__all__ = ["Revolute", "Prismatic", "Spherical", "FreeMotion", "Universal",
           "RevolutePlanarLoopConstraint", "FreeMotionScalarInit"]


def _axis(c):
    return direction(c, "n")


class Revolute(PartialRigidTwoFrames):
    """Revolute joint: frame_b turned by phi about the axis n fixed in frame_a, both
    origins coincide (MSL MultiBody.Joints.Revolute):

        r_0,b = r_0,a,   R_b = R_rel R_a,   R_rel = planarRotation(e, phi),   e = n/|n|
        w = der(phi),   a = der(w),
        f_a = -R_rel^T f_b,   t_a = -R_rel^T t_b,   tau = -e . t_b,
        axis.phi = phi,   axis.tau = tau,   support.phi = 0

    ``axis`` drives the joint (a torque on it turns frame_b in +phi) and ``support`` is
    its housing, fixed in the world as in the MSL (a Damper between axis and support
    damps the joint).  Left unconnected, axis and support carry no torque (the MSL's
    useAxisFlange = false) and the joint is free.
    """

    n_1 = ac.Parameter(0.0, description="axis of rotation in frame_a, x")
    n_2 = ac.Parameter(0.0, description="axis of rotation in frame_a, y")
    n_3 = ac.Parameter(1.0, description="axis of rotation in frame_a, z")
    axis = RotationalFlange()
    support = RotationalFlange()
    phi = ac.Variable(start=0.0, unit="rad", state_select="prefer",
                      description="rotation angle of frame_b relative to frame_a")
    w = ac.Variable(start=0.0, unit="rad/s", state_select="prefer",
                    description="relative angular velocity")
    a = ac.Variable(unit="rad/s2", description="relative angular acceleration")
    tau = ac.Variable(unit="N.m", description="driving torque in the direction of the axis")

    energy_role = "lossless"  # an ideal joint: the axis takes what the frames give

    def equations(self):
        a, b = self.frame_a, self.frame_b
        e = _axis(self)
        R_rel = planar_rotation(e, self.phi)
        return [*equal(position(b), position(a)),
                *propagate(a, b, R_rel),
                ac.Eq(self.w, ac.der(self.phi)),
                ac.Eq(self.a, ac.der(self.w)),
                *equal(force(a), -resolve1(R_rel, force(b))),
                *equal(torque(a), -resolve1(R_rel, torque(b))),
                ac.Eq(self.tau, -e.dot(torque(b))),
                ac.Eq(self.axis.tau, self.tau),
                ac.Eq(self.axis.phi, self.phi),
                ac.Eq(self.support.phi, 0)]


class Prismatic(PartialRigidTwoFrames):
    """Prismatic joint: frame_b shifted by s along the axis n fixed in frame_a, same
    orientation (MSL MultiBody.Joints.Prismatic):

        r_0,b = r_0,a + R_a^T (e s),   R_b = R_a,   v = der(s),   a = der(v),
        f_a = -f_b,   t_a = -t_b - (e s) x f_b,   f = -e . f_b,
        axis.s = s,   axis.f = f,   support.s = 0

    ``axis`` drives the joint (a force on it pushes frame_b along +e), ``support`` is
    its housing, fixed in the world as in the MSL.
    """

    n_1 = ac.Parameter(1.0, description="axis of translation in frame_a, x")
    n_2 = ac.Parameter(0.0, description="axis of translation in frame_a, y")
    n_3 = ac.Parameter(0.0, description="axis of translation in frame_a, z")
    axis = TranslationalFlange()
    support = TranslationalFlange()
    s = ac.Variable(start=0.0, unit="m", state_select="prefer",
                    description="translation of frame_b relative to frame_a along n")
    v = ac.Variable(start=0.0, unit="m/s", state_select="prefer",
                    description="relative velocity along n")
    a = ac.Variable(unit="m/s2", description="relative acceleration along n")
    f = ac.Variable(unit="N", description="driving force in the direction of the axis")

    energy_role = "lossless"  # an ideal joint: the axis takes what the frames give

    def equations(self):
        a, b = self.frame_a, self.frame_b
        e = _axis(self)
        r = e * self.s
        return [*equal(position(b), position(a) + resolve1(orientation(a), r)),
                *propagate(a, b),
                ac.Eq(self.v, ac.der(self.s)),
                ac.Eq(self.a, ac.der(self.v)),
                *equal(force(a), -force(b)),
                *equal(torque(a), -torque(b) - r.cross(force(b))),
                ac.Eq(self.f, -e.dot(force(b))),
                ac.Eq(self.axis.f, self.f),
                ac.Eq(self.axis.s, self.s),
                ac.Eq(self.support.s, 0)]


def _starts(angles_start, sequence_start, angles_fixed, modifications, where):
    """The modifications with Q's start values from the Cardan angles (and fixed where
    angles_fixed) merged under the user's own modification of Q."""
    angles = np.asarray(angles_start, dtype=float)
    if angles.shape != (3,) or not np.all(np.isfinite(angles)):
        raise ac.InvalidValue(f"{where}: angles_start = {angles_start!r} is not three "
                              "finite angles")
    if sorted(set(sequence_start)) != sorted(sequence_start) or \
            not set(sequence_start) <= {1, 2, 3} or len(sequence_start) != 3:
        raise ac.InvalidValue(f"{where}: sequence_start = {sequence_start!r} is not a "
                              "sequence of three different axes among 1, 2, 3")
    T = np.array(axes_rotations(sequence_start, angles).evalf(), dtype=float)
    Q = {"start": to_Q(T).tolist()}
    if angles_fixed:
        Q["fixed"] = [True, True, True, False]
    own = modifications.get("Q", {})
    if not isinstance(own, dict):
        own = {"start": own}
    return {**modifications, "Q": {**Q, **own}}


class _QuaternionJoint(PartialRigidTwoFrames):
    """The relative orientation R_rel = R(Q) with the Euler parameters Q and the
    relative angular velocity (resolved in frame_b) as states (module docstring).

    ``angles_start`` (three angles in rad about the axes ``sequence_start`` of frame_a,
    the MSL's Cardan angles, default (1, 2, 3)) gives Q's start values; with
    ``angles_fixed=True`` they are the initial orientation: Q[0..2] fixed and Q[3] from
    the normalization Q^T Q = 1 at the start (``Q_2``, fixed at 1).  Both are given
    when the joint is made.
    """

    lam = ac.Parameter(100.0, unit="1/s", min=0,
                       description="gain lambda of the quaternion normalization (E&G 6.336)")
    Q = ac.Variable(shape=4, start=[0.0, 0.0, 0.0, 1.0], state_select="prefer",
                    description="Euler parameters (n sin(phi/2), cos(phi/2)) of R_rel")
    Q_2 = ac.Variable(start=1.0, fixed=True, state_select="avoid",
                      description="Q^T Q (1 at the start; the normalization keeps it so)")

    def __init__(self, *, angles_start=(0.0, 0.0, 0.0), sequence_start=(1, 2, 3),
                 angles_fixed: bool = False, **modifications):
        if not isinstance(angles_fixed, bool):
            raise ac.InvalidValue(f"{type(self).__name__}: angles_fixed = {angles_fixed!r} "
                                  "must be True or False")
        modifications = _starts(angles_start, tuple(sequence_start), angles_fixed,
                                modifications, type(self).__name__)
        super().__init__(**modifications)

    def relative_orientation(self) -> sp.Matrix:
        """R_rel = R(Q), its division by Q^T Q through the variable Q_2."""
        return from_Q(list(self.Q), self.Q_2)

    def rotation_equations(self, w, z) -> list:
        Q = sp.Matrix(list(self.Q))
        w, z = sp.Matrix(w), sp.Matrix(z)
        return [ac.Eq(self.Q_2, Q.dot(Q)),
                *propagate(self.frame_a, self.frame_b, self.relative_orientation()),
                *equal(Q.applyfunc(ac.der), quaternion_rates(Q, w, self.lam)),
                *equal(z, w.applyfunc(ac.der))]


class Spherical(_QuaternionJoint):
    """Spherical joint (ball joint): both origins coincide, the orientation is free; no
    torque is transmitted (MSL MultiBody.Joints.Spherical with enforceStates, its
    relative quaternion and angular velocity the states):

        r_0,b = r_0,a,   R_b = R(Q) R_a,   der(Q) = 1/2 G(Q)^T w_rel + lam/2 (1 - Q^T Q) Q,
        z_rel = der(w_rel),   t_b = 0,   t_a = 0,   f_a = -R(Q)^T f_b
    """

    w_rel = ac.Variable(shape=3, start=0.0, unit="rad/s", state_select="prefer",
                        description="angular velocity of frame_b relative to frame_a, "
                                    "resolved in frame_b")
    z_rel = ac.Variable(shape=3, unit="rad/s2", description="der(w_rel)")

    energy_role = "lossless"  # transmits no torque

    def equations(self):
        a, b = self.frame_a, self.frame_b
        zero = sp.zeros(3, 1)
        return [*equal(position(b), position(a)),
                *self.rotation_equations(self.w_rel, self.z_rel),
                *equal(torque(b), zero),
                *equal(torque(a), zero),
                *equal(force(a), -resolve1(self.relative_orientation(), force(b)))]


class FreeMotion(_QuaternionJoint):
    """Free motion of frame_b relative to frame_a: six degrees of freedom, nothing
    transmitted (MSL MultiBody.Joints.FreeMotion with quaternion states).  Put it
    between the World and a body to let the body fly (the MSL's free body, whose states
    the MSL's Body holds itself):

        r_0,b = r_0,a + R_a^T r_rel_a,   v_rel_a = der(r_rel_a),   a_rel_a = der(v_rel_a),
        R_b = R(Q) R_a,   der(Q) = 1/2 G(Q)^T w_rel_b + lam/2 (1 - Q^T Q) Q,
        z_rel_b = der(w_rel_b),   f_a = f_b = 0,   t_a = t_b = 0

    r_rel_a, v_rel_a, a_rel_a are resolved in frame_a, w_rel_b and z_rel_b in frame_b.
    """

    r_rel_a = ac.Variable(shape=3, start=0.0, unit="m", state_select="prefer",
                          description="frame_b's origin from frame_a's, resolved in frame_a")
    v_rel_a = ac.Variable(shape=3, start=0.0, unit="m/s", state_select="prefer",
                          description="der(r_rel_a)")
    a_rel_a = ac.Variable(shape=3, unit="m/s2", description="der(v_rel_a)")
    w_rel_b = ac.Variable(shape=3, start=0.0, unit="rad/s", state_select="prefer",
                          description="angular velocity of frame_b relative to frame_a, "
                                      "resolved in frame_b")
    z_rel_b = ac.Variable(shape=3, unit="rad/s2", description="der(w_rel_b)")

    energy_role = "lossless"  # transmits nothing

    def equations(self):
        a, b = self.frame_a, self.frame_b
        r, v = sp.Matrix(self.r_rel_a), sp.Matrix(self.v_rel_a)
        zero = sp.zeros(3, 1)
        return [*equal(position(b), position(a) + resolve1(orientation(a), r)),
                *equal(v, r.applyfunc(ac.der)),
                *equal(sp.Matrix(self.a_rel_a), v.applyfunc(ac.der)),
                *self.rotation_equations(self.w_rel_b, self.z_rel_b),
                *equal(force(b), zero), *equal(torque(b), zero),
                *equal(force(a), zero), *equal(torque(a), zero)]


class Universal(PartialRigidTwoFrames):
    """Universal (Cardan) joint: a Revolute about n_a fixed in frame_a followed by a
    Revolute about n_b fixed in the intermediate frame (MSL MultiBody.Joints.Universal),
    angles revolute_a.phi and revolute_b.phi (the states)."""

    n_a_1 = ac.Parameter(1.0, description="axis of revolute_a in frame_a, x")
    n_a_2 = ac.Parameter(0.0, description="axis of revolute_a in frame_a, y")
    n_a_3 = ac.Parameter(0.0, description="axis of revolute_a in frame_a, z")
    n_b_1 = ac.Parameter(0.0, description="axis of revolute_b in the middle frame, x")
    n_b_2 = ac.Parameter(1.0, description="axis of revolute_b in the middle frame, y")
    n_b_3 = ac.Parameter(0.0, description="axis of revolute_b in the middle frame, z")
    revolute_a = Revolute(n_1=ac.ref("n_a_1"), n_2=ac.ref("n_a_2"), n_3=ac.ref("n_a_3"))
    revolute_b = Revolute(n_1=ac.ref("n_b_1"), n_2=ac.ref("n_b_2"), n_3=ac.ref("n_b_3"))

    energy_role = "lossless"

    def equations(self):
        return [ac.connect(self.frame_a, self.revolute_a.frame_a),
                ac.connect(self.revolute_a.frame_b, self.revolute_b.frame_a),
                ac.connect(self.revolute_b.frame_b, self.frame_b)]


class RevolutePlanarLoopConstraint(PartialTwoFrames):
    """Closes a planar kinematic loop with a revolute joint about n, writing only the
    constraints that are not redundant in the plane (MSL MultiBody.Joints.
    RevolutePlanarLoopConstraint):

        r_rel = R_a (r_0,b - r_0,a),   e_1 . r_rel = 0,   e_2 . r_rel = 0,
        f_a = f_1 e_1 + f_2 e_2,   f_b = -R_b R_a^T f_a,   t_a = t_b = 0

    e_1, e_2 span the plane normal to n in frame_a.  Both frames keep the orientations
    their own branches of the tree give them: the joint writes neither, so the loop
    does not write an orientation twice.  It has no joint coordinate and no flange.  In
    a planar loop of revolutes (and prismatics) the position along n and the
    orientation are fixed by the other joints; the loop closes only in the plane.

    n is structural (it chooses which directions are constrained): give it when the
    joint is created, ``RevolutePlanarLoopConstraint(n=(0, 0, 1))``.
    """

    f_1 = ac.Variable(unit="N", description="constraint force along e_1 on frame_a")
    f_2 = ac.Variable(unit="N", description="constraint force along e_2 on frame_a")

    energy_role = "lossless"  # ideal constraint: its forces do no work

    def __init__(self, n=(0.0, 0.0, 1.0), **modifications):
        super().__init__(**modifications)
        n = np.asarray(n, dtype=float)
        if n.shape != (3,) or not np.all(np.isfinite(n)) or np.linalg.norm(n) == 0:
            raise ac.ModelError(f"RevolutePlanarLoopConstraint: n = {n.ravel().tolist()} is "
                                "not a nonzero 3-vector")
        n = n / np.linalg.norm(n)
        # the world axis least parallel to n, made orthogonal to it (as the MSL does)
        helper = np.eye(3)[int(np.argmin(np.abs(n)))]
        e1 = helper - n * (helper @ n)
        e1 /= np.linalg.norm(e1)
        self.e_1, self.e_2 = e1, np.cross(n, e1)

    def equations(self):
        a, b = self.frame_a, self.frame_b
        e1, e2 = sp.Matrix(self.e_1), sp.Matrix(self.e_2)
        R_a, R_b = orientation(a), orientation(b)
        r_rel = R_a * (position(b) - position(a))
        f_a = self.f_1 * e1 + self.f_2 * e2
        zero = sp.zeros(3, 1)
        return [ac.Eq(0, e1.dot(r_rel)), ac.Eq(0, e2.dot(r_rel)),
                *equal(force(a), f_a),
                *equal(force(b), -R_b * (R_a.T * f_a)),
                *equal(torque(a), zero), *equal(torque(b), zero)]


class FreeMotionScalarInit(PartialTwoFrames):
    """Free motion of frame_b relative to frame_a with scalar outputs that serve to
    initialize it (MSL MultiBody.Joints.FreeMotionScalarInit, its position, velocity and
    acceleration outputs): it sets nothing and transmits nothing,

        r_rel_a = R_a (r_0,b - r_0,a),   v_rel_a = der(r_rel_a),   a_rel_a = der(v_rel_a),
        f_a = f_b = 0,   t_a = t_b = 0

    the elements given as outputs ``r_rel_a_1`` .. ``_3`` with ``use_r=True``, ``v_rel_a_1``
    .. with ``use_v=True`` as well, ``a_rel_a_1`` .. with ``use_a=True`` as well (given
    when it is made).  Fix their start values to put a mechanism's point where it
    belongs at the start: ``FreeMotionScalarInit(use_r=True, r_rel_a_1={"signal":
    {"start": 0.7, "fixed": True}})``.  The MSL's angle and angular-velocity outputs
    (use_angle, use_w) are not there.
    """

    energy_role = "lossless"  # transmits nothing

    def __init__(self, *, use_r: bool = False, use_v: bool = False, use_a: bool = False,
                 **modifications):
        for name, value in (("use_r", use_r), ("use_v", use_v), ("use_a", use_a)):
            if not isinstance(value, bool):
                raise ac.InvalidValue(f"FreeMotionScalarInit: {name} = {value!r} must be "
                                      "True or False")
        self.use_r, self.use_v, self.use_a = use_r, use_r and use_v, use_r and use_v and use_a
        super().__init__(**modifications)

    def build(self):
        for use, name in ((self.use_r, "r_rel_a"), (self.use_v, "v_rel_a"),
                          (self.use_a, "a_rel_a")):
            if use:
                for k in (1, 2, 3):
                    setattr(self, f"{name}_{k}", RealOutput())

    def _outputs(self, name):
        return sp.Matrix([getattr(self, f"{name}_{k}").signal for k in (1, 2, 3)])

    def equations(self):
        a, b = self.frame_a, self.frame_b
        zero = sp.zeros(3, 1)
        eqs = [*equal(force(a), zero), *equal(torque(a), zero),
               *equal(force(b), zero), *equal(torque(b), zero)]
        if self.use_r:
            r = self._outputs("r_rel_a")
            eqs += equal(r, orientation(a) * (position(b) - position(a)))
        if self.use_v:
            v = self._outputs("v_rel_a")
            eqs += equal(v, r.applyfunc(ac.der))
        if self.use_a:
            eqs += equal(self._outputs("a_rel_a"), v.applyfunc(ac.der))
        return eqs
