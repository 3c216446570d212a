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
from acausal.ports import RotationalFlange, TranslationalFlange

from .frames import (force, from_Q, orientation, planar_rotation, position, quaternion_rates,
                     resolve1, torque, vector)
from .interfaces import PartialRigidTwoFrames, PartialTwoFrames, direction, equal, propagate

__all__ = ["Revolute", "Prismatic", "Spherical", "FreeMotion", "Universal",
           "RevolutePlanarLoopConstraint"]


def _axis(c):
    return direction(c, "n")


class Revolute(PartialRigidTwoFrames):
    """Revolute joint: frame_b turned by phi about the axis n fixed in frame_a, both
    origins coincide (MSL MultiBody.Joints.Revolute, useAxisFlange, without support):

        r_0,b = r_0,a,   R_b = R_rel R_a,   R_rel = planarRotation(e, phi),   e = n/|n|
        w = der(phi),   a = der(w),
        f_a = -R_rel^T f_b,   t_a = -R_rel^T t_b,   flange.tau = -e . t_b,   flange.phi = phi

    A torque driving the flange turns frame_b in +phi; its reaction acts on frame_a
    (there is no separate support flange).  An unconnected flange leaves the joint free.
    """

    n_1 = ac.Parameter(0.0, description="axis of rotation in frame_a, x")
    n_2 = ac.Parameter(0.0, description="axis of rotation in frame_a, y")
    n_3 = ac.Parameter(1.0, description="axis of rotation in frame_a, z")
    flange = RotationalFlange()
    phi = ac.Variable(start=0.0, unit="rad", state_select="prefer",
                      description="rotation angle of frame_b relative to frame_a")
    w = ac.Variable(start=0.0, unit="rad/s", state_select="prefer",
                    description="relative angular velocity")
    a = ac.Variable(unit="rad/s2", description="relative angular acceleration")

    energy_role = "lossless"  # an ideal joint: the flange takes what the frames give

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
                ac.Eq(self.flange.tau, -e.dot(torque(b))),
                ac.Eq(self.flange.phi, self.phi)]


class Prismatic(PartialRigidTwoFrames):
    """Prismatic joint: frame_b shifted by s along the axis n fixed in frame_a, same
    orientation (MSL MultiBody.Joints.Prismatic, useAxisFlange, without support):

        r_0,b = r_0,a + R_a^T (e s),   R_b = R_a,   v = der(s),   a = der(v),
        f_a = -f_b,   t_a = -t_b - (e s) x f_b,   flange.f = -e . f_b,   flange.s = s
    """

    n_1 = ac.Parameter(1.0, description="axis of translation in frame_a, x")
    n_2 = ac.Parameter(0.0, description="axis of translation in frame_a, y")
    n_3 = ac.Parameter(0.0, description="axis of translation in frame_a, z")
    flange = TranslationalFlange()
    s = ac.Variable(start=0.0, unit="m", state_select="prefer",
                    description="translation of frame_b relative to frame_a along n")
    v = ac.Variable(start=0.0, unit="m/s", state_select="prefer",
                    description="relative velocity along n")
    a = ac.Variable(unit="m/s2", description="relative acceleration along n")

    energy_role = "lossless"  # an ideal joint: the flange takes what the frames give

    def equations(self):
        a, b = self.frame_a, self.frame_b
        r = _axis(self) * self.s
        return [*equal(position(b), position(a) + resolve1(orientation(a), r)),
                *propagate(a, b),
                ac.Eq(self.v, ac.der(self.s)),
                ac.Eq(self.a, ac.der(self.v)),
                *equal(force(a), -force(b)),
                *equal(torque(a), -torque(b) - r.cross(force(b))),
                ac.Eq(self.flange.f, -_axis(self).dot(force(b))),
                ac.Eq(self.flange.s, self.s)]


class _QuaternionJoint(PartialRigidTwoFrames):
    """The relative orientation R_rel = R(Q) with Euler-parameter states and the relative
    angular velocity w_rel (resolved in frame_b) as states (module docstring)."""

    lam = ac.Parameter(100.0, unit="1/s", min=0,
                       description="gain lambda of the quaternion normalization (E&G 6.336)")
    Q1 = ac.Variable(start=0.0, state_select="prefer", description="Euler parameter n_1 sin(phi/2)")
    Q2 = ac.Variable(start=0.0, state_select="prefer", description="Euler parameter n_2 sin(phi/2)")
    Q3 = ac.Variable(start=0.0, state_select="prefer", description="Euler parameter n_3 sin(phi/2)")
    Q4 = ac.Variable(start=1.0, state_select="prefer", description="Euler parameter cos(phi/2)")
    Q_2 = ac.Variable(start=1.0, state_select="avoid",
                      description="Q^T Q (1 up to the drift the normalization removes)")
    w_x = ac.Variable(start=0.0, unit="rad/s", state_select="prefer",
                      description="relative angular velocity, frame_b x")
    w_y = ac.Variable(start=0.0, unit="rad/s", state_select="prefer",
                      description="relative angular velocity, frame_b y")
    w_z = ac.Variable(start=0.0, unit="rad/s", state_select="prefer",
                      description="relative angular velocity, frame_b z")
    z_x = ac.Variable(unit="rad/s2", description="relative angular acceleration, frame_b x")
    z_y = ac.Variable(unit="rad/s2", description="relative angular acceleration, frame_b y")
    z_z = ac.Variable(unit="rad/s2", description="relative angular acceleration, frame_b z")

    energy_role = "lossless"  # transmits no torque, or nothing at all

    def quaternion(self):
        return [self.Q1, self.Q2, self.Q3, self.Q4]

    def relative_orientation(self) -> sp.Matrix:
        """R_rel = R(Q), its division by Q^T Q through the variable Q_2."""
        return from_Q(self.quaternion(), self.Q_2)

    def rotation_equations(self) -> list:
        Q = self.quaternion()
        w = vector(self.w_x, self.w_y, self.w_z)
        return [ac.Eq(self.Q_2, sum(q**2 for q in Q)),
                *propagate(self.frame_a, self.frame_b, self.relative_orientation()),
                *equal(sp.Matrix(Q).applyfunc(ac.der), quaternion_rates(Q, w, self.lam)),
                *equal(vector(self.z_x, self.z_y, self.z_z), w.applyfunc(ac.der))]


class Spherical(_QuaternionJoint):
    """Spherical joint (ball joint): both origins coincide, the orientation is free; no
    torque is transmitted (MSL MultiBody.Joints.Spherical with enforceStates, its
    relative quaternion and angular velocity the states):

        r_0,b = r_0,a,   R_b = R(Q) R_a,   der(Q) = 1/2 G(Q)^T w_rel + lam/2 (1 - Q^T Q) Q,
        t_b = 0,   t_a = 0,   f_a = -R(Q)^T f_b
    """

    def equations(self):
        a, b = self.frame_a, self.frame_b
        return [*equal(position(b), position(a)),
                *self.rotation_equations(),
                *equal(torque(b), sp.zeros(3, 1)),
                *equal(torque(a), sp.zeros(3, 1)),
                *equal(force(a), -resolve1(self.relative_orientation(), force(b)))]


class FreeMotion(_QuaternionJoint):
    """Free motion of frame_b relative to frame_a: six degrees of freedom, nothing
    transmitted (MSL MultiBody.Joints.FreeMotion with Euler-parameter states).  Put it
    between the World and a body to let the body fly:

        r_0,b = r_0,a + R_a^T r_rel,   v_rel = der(r_rel),   a_rel = der(v_rel),
        R_b = R(Q) R_a,   der(Q) = 1/2 G(Q)^T w_rel + lam/2 (1 - Q^T Q) Q,
        f_a = f_b = 0,   t_a = t_b = 0

    r_rel, v_rel, a_rel are resolved in frame_a.
    """

    r_x = ac.Variable(start=0.0, unit="m", state_select="prefer",
                      description="position of frame_b from frame_a, frame_a x")
    r_y = ac.Variable(start=0.0, unit="m", state_select="prefer",
                      description="position of frame_b from frame_a, frame_a y")
    r_z = ac.Variable(start=0.0, unit="m", state_select="prefer",
                      description="position of frame_b from frame_a, frame_a z")
    v_x = ac.Variable(start=0.0, unit="m/s", state_select="prefer",
                      description="relative velocity, frame_a x")
    v_y = ac.Variable(start=0.0, unit="m/s", state_select="prefer",
                      description="relative velocity, frame_a y")
    v_z = ac.Variable(start=0.0, unit="m/s", state_select="prefer",
                      description="relative velocity, frame_a z")
    a_x = ac.Variable(unit="m/s2", description="relative acceleration, frame_a x")
    a_y = ac.Variable(unit="m/s2", description="relative acceleration, frame_a y")
    a_z = ac.Variable(unit="m/s2", description="relative acceleration, frame_a z")

    def equations(self):
        a, b = self.frame_a, self.frame_b
        r = vector(self.r_x, self.r_y, self.r_z)
        v = vector(self.v_x, self.v_y, self.v_z)
        zero = sp.zeros(3, 1)
        return [*equal(position(b), position(a) + resolve1(orientation(a), r)),
                *equal(v, r.applyfunc(ac.der)),
                *equal(vector(self.a_x, self.a_y, self.a_z), v.applyfunc(ac.der)),
                *self.rotation_equations(),
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
