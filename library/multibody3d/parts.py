"""Rigid parts of spatial multibody systems (Modelica.Mechanics.MultiBody.Parts: Fixed,
FixedTranslation, FixedRotation, Body, BodyShape, PointMass; BodyBox and BodyCylinder
are in ``shapes``; the World is in ``world``).

Vector parameters are three scalar parameters with the MSL's index (``r_CM_1``, ``r_CM_2``,
``r_CM_3`` for r_CM[1..3]), so that each can be modified and bound with ``ac.ref``, and a
zero stays a structural zero.  Vector variables are arrays (``v_0``, indexed from 0 as
Python indexes: ``body.v_0[0]`` is the MSL's ``body.v_0[1]``).
"""
from __future__ import annotations

from acausal._sympy import sympy as sp

import acausal as ac
from acausal.ports.spatial import Frame

from .frames import (angular_velocity2, force, orientation, planar_rotation, position,
                     resolve1, resolve2, torque)
from .interfaces import (PartialOneFrame_a, PartialRigidTwoFrames, direction, equal,
                         propagate, vector_of)
from .world import world_of
from .world import World

__all__ = ["World", "Fixed", "FixedTranslation", "FixedRotation", "Body", "BodyShape",
           "PointMass"]

_CM = "centre of mass from frame_a, {} (resolved in frame_a)"
_R = "frame_b from frame_a, {} (resolved in frame_a)"


class Fixed(ac.Component):
    """A frame fixed in the world at r (MSL MultiBody.Parts.Fixed):

        frame_b.r_0 = r,   frame_b.R = I

    A root of the orientation tree, as the World.
    """

    r_1 = ac.Parameter(0.0, unit="m", description="frame_b from the world frame, x")
    r_2 = ac.Parameter(0.0, unit="m", description="frame_b from the world frame, y")
    r_3 = ac.Parameter(0.0, unit="m", description="frame_b from the world frame, z")
    frame_b = Frame()

    energy_role = "lossless"  # fixed in the world: does no work

    def equations(self):
        f = self.frame_b
        return [*equal(position(f), vector_of(self, "r")),
                *equal(orientation(f), sp.eye(3))]


class FixedTranslation(PartialRigidTwoFrames):
    """Massless rigid bar; frame_b at r from frame_a, resolved in frame_a, with frame_a's
    orientation (MSL MultiBody.Parts.FixedTranslation):

        r_0,b = r_0,a + R_a^T r,   R_b = R_a,   f_a + f_b = 0,   t_a + t_b + r x f_b = 0
    """

    r_1 = ac.Parameter(0.0, unit="m", description=_R.format("x"))
    r_2 = ac.Parameter(0.0, unit="m", description=_R.format("y"))
    r_3 = ac.Parameter(0.0, unit="m", description=_R.format("z"))

    energy_role = "lossless"  # a rigid massless bar

    def equations(self):
        a, b = self.frame_a, self.frame_b
        r = vector_of(self, "r")
        return [*equal(position(b), position(a) + resolve1(orientation(a), r)),
                *propagate(a, b),
                *equal(force(a), -force(b)),
                *equal(torque(a), -torque(b) - r.cross(force(b)))]


class FixedRotation(PartialRigidTwoFrames):
    """Massless rigid part; frame_b at r from frame_a and turned by angle (in degrees, as
    the MSL's Angle_deg) about n (MSL MultiBody.Parts.FixedRotation, rotationType =
    RotationAxis):

        r_0,b = r_0,a + R_a^T r,   R_b = R_rel R_a,   R_rel = planarRotation(n/|n|, angle)
        f_a = -R_rel^T f_b,   t_a = -R_rel^T t_b - r x (R_rel^T f_b)
    """

    r_1 = ac.Parameter(0.0, unit="m", description=_R.format("x"))
    r_2 = ac.Parameter(0.0, unit="m", description=_R.format("y"))
    r_3 = ac.Parameter(0.0, unit="m", description=_R.format("z"))
    n_1 = ac.Parameter(0.0, description="axis of rotation in frame_a, x")
    n_2 = ac.Parameter(0.0, description="axis of rotation in frame_a, y")
    n_3 = ac.Parameter(1.0, description="axis of rotation in frame_a, z")
    angle = ac.Parameter(0.0, unit="deg", description="rotation angle of frame_b about n")

    energy_role = "lossless"  # a rigid massless part

    def equations(self):
        a, b = self.frame_a, self.frame_b
        r = vector_of(self, "r")
        R_rel = planar_rotation(direction(self, "n"), self.angle * sp.pi / 180)
        f_b_in_a = resolve1(R_rel, force(b))
        return [*equal(position(b), position(a) + resolve1(orientation(a), r)),
                *propagate(a, b, R_rel),
                *equal(force(a), -f_b_in_a),
                *equal(torque(a), -resolve1(R_rel, torque(b)) - r.cross(f_b_in_a))]


class Body(PartialOneFrame_a):
    """Rigid body with mass m, centre of mass at r_CM from frame_a and inertia tensor I
    about the centre of mass, resolved in frame_a (MSL MultiBody.Parts.Body; Newton-Euler
    about a point that is not the centre of mass, Egeland & Gravdahl (7.94)-(7.96)):

        r_0 = frame_a.r_0,   v_0 = der(r_0),   a_0 = der(v_0),
        w_a = angularVelocity2(R),   z_a = der(w_a),
        g_0 = world.gravityAcceleration(r_0 + R^T r_CM)
        f = m (R (a_0 - g_0) + z_a x r_CM + w_a x (w_a x r_CM))
        t = I z_a + w_a x (I w_a) + r_CM x f

    f and t are frame_a's cut force and torque (resolved in frame_a), g_0 the field of
    the enclosing World at the centre of mass.  The body reads its orientation from its
    frame: it is attached by a joint (a free body by FreeMotion), it never sets it.
    """

    m = ac.Parameter(1.0, unit="kg", min=0, description="mass")
    r_CM_1 = ac.Parameter(0.0, unit="m", description=_CM.format("x"))
    r_CM_2 = ac.Parameter(0.0, unit="m", description=_CM.format("y"))
    r_CM_3 = ac.Parameter(0.0, unit="m", description=_CM.format("z"))
    I_11 = ac.Parameter(0.001, unit="kg.m2", min=0, description="inertia I[1,1] about the CM")
    I_22 = ac.Parameter(0.001, unit="kg.m2", min=0, description="inertia I[2,2] about the CM")
    I_33 = ac.Parameter(0.001, unit="kg.m2", min=0, description="inertia I[3,3] about the CM")
    I_21 = ac.Parameter(0.0, unit="kg.m2", description="product of inertia I[2,1] = I[1,2]")
    I_31 = ac.Parameter(0.0, unit="kg.m2", description="product of inertia I[3,1] = I[1,3]")
    I_32 = ac.Parameter(0.0, unit="kg.m2", description="product of inertia I[3,2] = I[2,3]")
    r_0 = ac.Variable(shape=3, start=0.0, unit="m", state_select="avoid",
                      description="position of frame_a's origin, world frame")
    v_0 = ac.Variable(shape=3, start=0.0, unit="m/s", state_select="avoid",
                      description="velocity of frame_a's origin, world frame (= der(r_0))")
    a_0 = ac.Variable(shape=3, unit="m/s2",
                      description="acceleration of frame_a's origin, world frame")
    w_a = ac.Variable(shape=3, start=0.0, unit="rad/s", state_select="avoid",
                      description="angular velocity of frame_a, resolved in frame_a")
    z_a = ac.Variable(shape=3, unit="rad/s2",
                      description="angular acceleration of frame_a, resolved in frame_a")
    g_0 = ac.Variable(shape=3, unit="m/s2",
                      description="gravity acceleration at the centre of mass, world frame")

    def inertia(self) -> sp.Matrix:
        """I about the centre of mass, resolved in frame_a."""
        return sp.Matrix([[self.I_11, self.I_21, self.I_31],
                          [self.I_21, self.I_22, self.I_32],
                          [self.I_31, self.I_32, self.I_33]])

    def stored_energy(self):
        """m |v_CM|^2 / 2 + w_a^T I w_a / 2 + m V(r_CM,0), with v_CM = v_0 + R^T (w_a x
        r_CM), r_CM,0 = r_0 + R^T r_CM and V the World's gravity potential."""
        R, w = orientation(self.frame_a), sp.Matrix(self.w_a)
        r_CM = vector_of(self, "r_CM")
        v_CM = sp.Matrix(self.v_0) + resolve1(R, w.cross(r_CM))
        r_CM0 = position(self.frame_a) + resolve1(R, r_CM)
        return (self.m * v_CM.dot(v_CM) / 2 + (w.T * self.inertia() * w)[0] / 2
                + self.m * world_of(self).gravityPotential(r_CM0))

    def equations(self):
        fa = self.frame_a
        R = orientation(fa)
        r_0, v_0, a_0 = sp.Matrix(self.r_0), sp.Matrix(self.v_0), sp.Matrix(self.a_0)
        w_a, z_a, g_0 = sp.Matrix(self.w_a), sp.Matrix(self.z_a), sp.Matrix(self.g_0)
        r_CM = vector_of(self, "r_CM")
        f = self.m * (resolve2(R, a_0 - g_0) + z_a.cross(r_CM) + w_a.cross(w_a.cross(r_CM)))
        I = self.inertia()
        g = world_of(self).gravityAcceleration(position(fa) + resolve1(R, r_CM))
        return [*equal(r_0, position(fa)),
                *equal(v_0, r_0.applyfunc(ac.der)),
                *equal(a_0, v_0.applyfunc(ac.der)),
                *equal(w_a, angular_velocity2(R, R.applyfunc(ac.der))),
                *equal(z_a, w_a.applyfunc(ac.der)),
                *equal(g_0, g),
                *equal(force(fa), f),
                *equal(torque(fa), I * z_a + w_a.cross(I * w_a) + r_CM.cross(force(fa)))]


class BodyShape(PartialRigidTwoFrames):
    """Rigid body with a second frame: a Body at frame_a and a massless bar from frame_a
    to frame_b at r (MSL MultiBody.Parts.BodyShape, without its visual shape):

        Body(m, r_CM, I) at frame_a,   FixedTranslation(r) from frame_a to frame_b,
        r_0 = frame_a.r_0,   v_0 = der(r_0),   a_0 = der(v_0)

    r and r_CM are resolved in frame_a, I is about the centre of mass; the body's
    Newton-Euler equations and the bar's are those of ``Body`` and ``FixedTranslation``.
    """

    r_1 = ac.Parameter(0.0, unit="m", description=_R.format("x"))
    r_2 = ac.Parameter(0.0, unit="m", description=_R.format("y"))
    r_3 = ac.Parameter(0.0, unit="m", description=_R.format("z"))
    m = ac.Parameter(1.0, unit="kg", min=0, description="mass")
    r_CM_1 = ac.Parameter(0.0, unit="m", description=_CM.format("x"))
    r_CM_2 = ac.Parameter(0.0, unit="m", description=_CM.format("y"))
    r_CM_3 = ac.Parameter(0.0, unit="m", description=_CM.format("z"))
    I_11 = ac.Parameter(0.001, unit="kg.m2", min=0, description="inertia I[1,1] about the CM")
    I_22 = ac.Parameter(0.001, unit="kg.m2", min=0, description="inertia I[2,2] about the CM")
    I_33 = ac.Parameter(0.001, unit="kg.m2", min=0, description="inertia I[3,3] about the CM")
    I_21 = ac.Parameter(0.0, unit="kg.m2", description="product of inertia I[2,1] = I[1,2]")
    I_31 = ac.Parameter(0.0, unit="kg.m2", description="product of inertia I[3,1] = I[1,3]")
    I_32 = ac.Parameter(0.0, unit="kg.m2", description="product of inertia I[3,2] = I[2,3]")
    r_0 = ac.Variable(shape=3, unit="m", description="position of frame_a's origin, world frame")
    v_0 = ac.Variable(shape=3, unit="m/s", description="velocity of frame_a's origin, world frame")
    a_0 = ac.Variable(shape=3, unit="m/s2",
                      description="acceleration of frame_a's origin, world frame")
    body = Body(m=ac.ref("m"), r_CM_1=ac.ref("r_CM_1"), r_CM_2=ac.ref("r_CM_2"),
                r_CM_3=ac.ref("r_CM_3"), I_11=ac.ref("I_11"), I_22=ac.ref("I_22"),
                I_33=ac.ref("I_33"), I_21=ac.ref("I_21"), I_31=ac.ref("I_31"),
                I_32=ac.ref("I_32"))
    frameTranslation = FixedTranslation(r_1=ac.ref("r_1"), r_2=ac.ref("r_2"),
                                        r_3=ac.ref("r_3"))

    def equations(self):
        return [*equal(sp.Matrix(self.r_0), sp.Matrix(self.body.r_0)),
                *equal(sp.Matrix(self.v_0), sp.Matrix(self.body.v_0)),
                *equal(sp.Matrix(self.a_0), sp.Matrix(self.body.a_0)),
                ac.connect(self.frame_a, self.body.frame_a, self.frameTranslation.frame_a),
                ac.connect(self.frameTranslation.frame_b, self.frame_b)]


class PointMass(PartialOneFrame_a):
    """A mass point: a body whose rotation and inertia are neglected (MSL
    MultiBody.Parts.PointMass):

        r_0 = frame_a.r_0,   v_0 = der(r_0),   a_0 = der(v_0),
        f = m R (a_0 - world.gravityAcceleration(r_0)),   t = 0

    It takes no torque, so its orientation is set by what it is attached to (a bar, a
    line force with ``fixedRotationAtFrame_a``).  A point mass that is not connected at
    all has nothing to set its frame's orientation: create it ``PointMass(connected=
    False)`` and it sets R = I itself, leaving t free (the MSL does so when
    cardinality(frame_a) == 0).
    """

    m = ac.Parameter(1.0, unit="kg", min=0, description="mass")
    r_0 = ac.Variable(shape=3, start=0.0, unit="m", state_select="avoid",
                      description="position of the mass point, world frame")
    v_0 = ac.Variable(shape=3, start=0.0, unit="m/s", state_select="avoid",
                      description="velocity of the mass point, world frame (= der(r_0))")
    a_0 = ac.Variable(shape=3, unit="m/s2",
                      description="acceleration of the mass point, world frame")

    def __init__(self, *, connected: bool = True, **modifications):
        if not isinstance(connected, bool):
            raise ac.InvalidValue(f"PointMass: connected = {connected!r} must be True or "
                                  "False")
        super().__init__(**modifications)
        self.connected = connected

    def stored_energy(self):
        """m |v_0|^2 / 2 + m V(r_0)."""
        v = sp.Matrix(self.v_0)
        return self.m * v.dot(v) / 2 + self.m * world_of(self).gravityPotential(
            sp.Matrix(self.r_0))

    def equations(self):
        fa = self.frame_a
        R = orientation(fa)
        r_0, v_0, a_0 = sp.Matrix(self.r_0), sp.Matrix(self.v_0), sp.Matrix(self.a_0)
        g = world_of(self).gravityAcceleration(r_0)
        rotation = (equal(R, sp.eye(3)) if not self.connected
                    else equal(torque(fa), sp.zeros(3, 1)))
        return [*equal(r_0, position(fa)),
                *equal(v_0, r_0.applyfunc(ac.der)),
                *equal(a_0, v_0.applyfunc(ac.der)),
                *equal(force(fa), self.m * resolve2(R, a_0 - g)),
                *rotation]
