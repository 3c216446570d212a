"""Rigid parts of spatial multibody systems (Modelica.Mechanics.MultiBody: World,
Parts.Body, BodyShape, BodyBox, BodyCylinder, FixedTranslation, FixedRotation).

Vectors are given as three scalar parameters with the MSL's index (``r_CM_1``, ``r_CM_2``,
``r_CM_3`` for r_CM), so that each can be modified and bound with ``ac.ref``.
"""
from __future__ import annotations

from acausal._sympy import sympy as sp

import acausal as ac
from acausal.ports.spatial import Frame

from .frames import (angular_velocity2, force, gravity, orientation, planar_rotation,
                     position, resolve1, resolve2, torque, vector)
from .interfaces import PartialOneFrame_a, PartialRigidTwoFrames, direction, equal, propagate

__all__ = ["World", "Body", "BodyShape", "BodyBox", "BodyCylinder", "FixedTranslation",
           "FixedRotation"]


class World(ac.Component):
    """The inertial frame and the gravity field (MSL MultiBody.World, uniform gravity):

        frame_b.r_0 = 0,   frame_b.R = I,   frame_b.g_0 = g n/|n|

    One per model: it is the root of the spanning tree along which orientation and
    gravity travel (``acausal.ports.spatial``).  The default is the MSL's, g = 9.80665
    m/s2 along -y.
    """

    g = ac.Parameter(9.80665, unit="m/s2", description="gravity acceleration")
    n_1 = ac.Parameter(0.0, description="direction of gravity, world x")
    n_2 = ac.Parameter(-1.0, description="direction of gravity, world y")
    n_3 = ac.Parameter(0.0, description="direction of gravity, world z")
    frame_b = Frame()

    energy_role = "lossless"  # fixed in the world: does no work

    def equations(self):
        f = self.frame_b
        return [*equal(position(f), sp.zeros(3, 1)),
                *equal(orientation(f), sp.eye(3)),
                *equal(gravity(f), self.g * direction(self, "n"))]


class Body(PartialOneFrame_a):
    """Rigid body with mass m, centre of mass at r_CM from frame_a and inertia tensor I
    about the centre of mass, resolved in frame_a (MSL MultiBody.Parts.Body; Newton-Euler
    about a point that is not the centre of mass, Egeland & Gravdahl (7.94)-(7.96)):

        v_0 = der(r_0),   a_0 = der(v_0),   w_a = angular_velocity2(R),   z_a = der(w_a)
        f = m (R (a_0 - g_0) + z_a x r_CM + w_a x (w_a x r_CM))
        t = I z_a + w_a x (I w_a) + r_CM x f

    f and t are frame_a's cut force and torque (resolved in frame_a), g_0 the world's
    gravity that frame_a carries.  The body reads its orientation from its frame: it is
    attached by a joint (a free body by FreeMotion), it never sets it.
    """

    m = ac.Parameter(1.0, unit="kg", min=0, description="mass")
    r_CM_1 = ac.Parameter(0.0, unit="m", description="centre of mass from frame_a, x")
    r_CM_2 = ac.Parameter(0.0, unit="m", description="centre of mass from frame_a, y")
    r_CM_3 = ac.Parameter(0.0, unit="m", description="centre of mass from frame_a, z")
    I_11 = ac.Parameter(0.001, unit="kg.m2", min=0, description="inertia I[1,1] about the CM")
    I_22 = ac.Parameter(0.001, unit="kg.m2", min=0, description="inertia I[2,2] about the CM")
    I_33 = ac.Parameter(0.001, unit="kg.m2", min=0, description="inertia I[3,3] about the CM")
    I_21 = ac.Parameter(0.0, unit="kg.m2", description="product of inertia I[2,1] = I[1,2]")
    I_31 = ac.Parameter(0.0, unit="kg.m2", description="product of inertia I[3,1] = I[1,3]")
    I_32 = ac.Parameter(0.0, unit="kg.m2", description="product of inertia I[3,2] = I[2,3]")
    v_x = ac.Variable(start=0.0, unit="m/s", description="velocity of frame_a, world x")
    v_y = ac.Variable(start=0.0, unit="m/s", description="velocity of frame_a, world y")
    v_z = ac.Variable(start=0.0, unit="m/s", description="velocity of frame_a, world z")
    a_x = ac.Variable(unit="m/s2", description="acceleration of frame_a, world x")
    a_y = ac.Variable(unit="m/s2", description="acceleration of frame_a, world y")
    a_z = ac.Variable(unit="m/s2", description="acceleration of frame_a, world z")
    w_x = ac.Variable(start=0.0, unit="rad/s", description="angular velocity, frame_a x")
    w_y = ac.Variable(start=0.0, unit="rad/s", description="angular velocity, frame_a y")
    w_z = ac.Variable(start=0.0, unit="rad/s", description="angular velocity, frame_a z")
    z_x = ac.Variable(unit="rad/s2", description="angular acceleration, frame_a x")
    z_y = ac.Variable(unit="rad/s2", description="angular acceleration, frame_a y")
    z_z = ac.Variable(unit="rad/s2", description="angular acceleration, frame_a z")

    def inertia(self) -> sp.Matrix:
        """I about the centre of mass, resolved in frame_a."""
        return sp.Matrix([[self.I_11, self.I_21, self.I_31],
                          [self.I_21, self.I_22, self.I_32],
                          [self.I_31, self.I_32, self.I_33]])

    def stored_energy(self):
        """m |v_CM|^2 / 2 + w_a^T I w_a / 2 - m g_0 . r_CM,0, with v_CM = v_0 + R^T (w_a x
        r_CM) and r_CM,0 = r_0 + R^T r_CM (uniform gravity)."""
        R, w = orientation(self.frame_a), vector(self.w_x, self.w_y, self.w_z)
        r_CM = vector(self.r_CM_1, self.r_CM_2, self.r_CM_3)
        v_CM = vector(self.v_x, self.v_y, self.v_z) + resolve1(R, w.cross(r_CM))
        r_CM0 = position(self.frame_a) + resolve1(R, r_CM)
        return (self.m * v_CM.dot(v_CM) / 2 + (w.T * self.inertia() * w)[0] / 2
                - self.m * gravity(self.frame_a).dot(r_CM0))

    def equations(self):
        fa = self.frame_a
        R = orientation(fa)
        r_0 = position(fa)
        v_0 = vector(self.v_x, self.v_y, self.v_z)
        a_0 = vector(self.a_x, self.a_y, self.a_z)
        w_a = vector(self.w_x, self.w_y, self.w_z)
        z_a = vector(self.z_x, self.z_y, self.z_z)
        r_CM = vector(self.r_CM_1, self.r_CM_2, self.r_CM_3)
        f = self.m * (resolve2(R, a_0 - gravity(fa)) + z_a.cross(r_CM)
                      + w_a.cross(w_a.cross(r_CM)))
        I = self.inertia()
        return [*equal(v_0, r_0.applyfunc(ac.der)),
                *equal(a_0, v_0.applyfunc(ac.der)),
                *equal(w_a, angular_velocity2(R, R.applyfunc(ac.der))),
                *equal(z_a, w_a.applyfunc(ac.der)),
                *equal(force(fa), f),
                *equal(torque(fa), I * z_a + w_a.cross(I * w_a) + r_CM.cross(force(fa)))]


class FixedTranslation(PartialRigidTwoFrames):
    """Massless rigid bar; frame_b at r from frame_a, resolved in frame_a, with frame_a's
    orientation (MSL MultiBody.Parts.FixedTranslation):

        r_0,b = r_0,a + R_a^T r,   R_b = R_a,   f_a + f_b = 0,   t_a + t_b + r x f_b = 0
    """

    r_1 = ac.Parameter(0.0, unit="m", description="frame_b from frame_a, x in frame_a")
    r_2 = ac.Parameter(0.0, unit="m", description="frame_b from frame_a, y in frame_a")
    r_3 = ac.Parameter(0.0, unit="m", description="frame_b from frame_a, z in frame_a")

    energy_role = "lossless"  # a rigid massless bar

    def equations(self):
        a, b = self.frame_a, self.frame_b
        r = vector(self.r_1, self.r_2, self.r_3)
        return [*equal(position(b), position(a) + resolve1(orientation(a), r)),
                *propagate(a, b),
                *equal(force(a), -force(b)),
                *equal(torque(a), -torque(b) - r.cross(force(b)))]


class FixedRotation(PartialRigidTwoFrames):
    """Massless rigid part; frame_b at r from frame_a and turned by angle about n
    (MSL MultiBody.Parts.FixedRotation, rotationType = RotationAxis, angle in rad):

        r_0,b = r_0,a + R_a^T r,   R_b = R_rel R_a,   R_rel = planarRotation(n/|n|, angle)
        f_a = -R_rel^T f_b,   t_a = -R_rel^T t_b - r x (R_rel^T f_b)
    """

    r_1 = ac.Parameter(0.0, unit="m", description="frame_b from frame_a, x in frame_a")
    r_2 = ac.Parameter(0.0, unit="m", description="frame_b from frame_a, y in frame_a")
    r_3 = ac.Parameter(0.0, unit="m", description="frame_b from frame_a, z in frame_a")
    n_1 = ac.Parameter(0.0, description="axis of rotation in frame_a, x")
    n_2 = ac.Parameter(0.0, description="axis of rotation in frame_a, y")
    n_3 = ac.Parameter(1.0, description="axis of rotation in frame_a, z")
    angle = ac.Parameter(0.0, unit="rad", description="rotation angle of frame_b about n")

    energy_role = "lossless"  # a rigid massless part

    def equations(self):
        a, b = self.frame_a, self.frame_b
        r = vector(self.r_1, self.r_2, self.r_3)
        R_rel = planar_rotation(direction(self, "n"), self.angle)
        f_b_in_a = resolve1(R_rel, force(b))
        return [*equal(position(b), position(a) + resolve1(orientation(a), r)),
                *propagate(a, b, R_rel),
                *equal(force(a), -f_b_in_a),
                *equal(torque(a), -resolve1(R_rel, torque(b)) - r.cross(f_b_in_a))]


class BodyShape(PartialRigidTwoFrames):
    """Rigid body with a second frame: a Body at frame_a and a massless bar from frame_a
    to frame_b at r (MSL MultiBody.Parts.BodyShape, without its visual shape):

        Body(m, r_CM, I) at frame_a,   FixedTranslation(r) from frame_a to frame_b

    r and r_CM are resolved in frame_a, I is about the centre of mass; the body's
    Newton-Euler equations and the bar's are those of ``Body`` and ``FixedTranslation``.
    """

    r_1 = ac.Parameter(0.0, unit="m", description="frame_b from frame_a, x in frame_a")
    r_2 = ac.Parameter(0.0, unit="m", description="frame_b from frame_a, y in frame_a")
    r_3 = ac.Parameter(0.0, unit="m", description="frame_b from frame_a, z in frame_a")
    m = ac.Parameter(1.0, unit="kg", min=0, description="mass")
    r_CM_1 = ac.Parameter(0.0, unit="m", description="centre of mass from frame_a, x")
    r_CM_2 = ac.Parameter(0.0, unit="m", description="centre of mass from frame_a, y")
    r_CM_3 = ac.Parameter(0.0, unit="m", description="centre of mass from frame_a, z")
    I_11 = ac.Parameter(0.001, unit="kg.m2", min=0, description="inertia I[1,1] about the CM")
    I_22 = ac.Parameter(0.001, unit="kg.m2", min=0, description="inertia I[2,2] about the CM")
    I_33 = ac.Parameter(0.001, unit="kg.m2", min=0, description="inertia I[3,3] about the CM")
    I_21 = ac.Parameter(0.0, unit="kg.m2", description="product of inertia I[2,1] = I[1,2]")
    I_31 = ac.Parameter(0.0, unit="kg.m2", description="product of inertia I[3,1] = I[1,3]")
    I_32 = ac.Parameter(0.0, unit="kg.m2", description="product of inertia I[3,2] = I[2,3]")
    body = Body(m=ac.ref("m"), r_CM_1=ac.ref("r_CM_1"), r_CM_2=ac.ref("r_CM_2"),
                r_CM_3=ac.ref("r_CM_3"), I_11=ac.ref("I_11"), I_22=ac.ref("I_22"),
                I_33=ac.ref("I_33"), I_21=ac.ref("I_21"), I_31=ac.ref("I_31"),
                I_32=ac.ref("I_32"))
    bar = FixedTranslation(r_1=ac.ref("r_1"), r_2=ac.ref("r_2"), r_3=ac.ref("r_3"))

    def equations(self):
        return [ac.connect(self.frame_a, self.body.frame_a, self.bar.frame_a),
                ac.connect(self.bar.frame_b, self.frame_b)]


class _ShapedBody(PartialRigidTwoFrames):
    """A Body whose mass and inertia follow from a shape along frame_a's x axis, with a
    frame_b at the far end (x = length): MSL BodyShape with lengthDirection = x."""

    length = ac.Parameter(1.0, unit="m", min=0, description="length along frame_a's x")
    density = ac.Parameter(7700.0, unit="kg/m3", min=0, description="density (steel)")
    body = Body(r_CM_1=ac.ref("half_length"), m=ac.ref("m"), I_11=ac.ref("I_11"),
                I_22=ac.ref("I_22"), I_33=ac.ref("I_33"))
    bar = FixedTranslation(r_1=ac.ref("length"))

    def equations(self):
        return [ac.connect(self.frame_a, self.body.frame_a, self.bar.frame_a),
                ac.connect(self.bar.frame_b, self.frame_b)]


class BodyBox(_ShapedBody):
    """Box of length (x), width (y) and height (z) from frame_a, uniform density
    (MSL MultiBody.Parts.BodyBox with lengthDirection x, widthDirection y):

        m = rho L w h,   r_CM = (L/2, 0, 0),
        I = m/12 diag(w^2 + h^2, L^2 + h^2, L^2 + w^2)
    """

    width = ac.Parameter(0.1, unit="m", min=0, description="width along frame_a's y")
    height = ac.Parameter(0.1, unit="m", min=0, description="height along frame_a's z")
    half_length = ac.Parameter(lambda c: c.length / 2, unit="m", description="L/2")
    m = ac.Parameter(lambda c: c.density * c.length * c.width * c.height, unit="kg",
                     description="mass rho L w h")
    I_11 = ac.Parameter(lambda c: c.m * (c.width**2 + c.height**2) / 12, unit="kg.m2",
                        description="m (w^2 + h^2)/12")
    I_22 = ac.Parameter(lambda c: c.m * (c.length**2 + c.height**2) / 12, unit="kg.m2",
                        description="m (L^2 + h^2)/12")
    I_33 = ac.Parameter(lambda c: c.m * (c.length**2 + c.width**2) / 12, unit="kg.m2",
                        description="m (L^2 + w^2)/12")


class BodyCylinder(_ShapedBody):
    """Cylinder (a tube if di > 0) of the given length along frame_a's x, uniform density
    (MSL MultiBody.Parts.BodyCylinder with lengthDirection x):

        m = rho pi (d^2 - di^2)/4 L,   r_CM = (L/2, 0, 0),
        I_11 = m (d^2 + di^2)/8,   I_22 = I_33 = m ((d^2 + di^2)/16 + L^2/12)
    """

    diameter = ac.Parameter(0.1, unit="m", min=0, description="outer diameter d")
    innerDiameter = ac.Parameter(0.0, unit="m", min=0, description="inner diameter di")
    half_length = ac.Parameter(lambda c: c.length / 2, unit="m", description="L/2")
    m = ac.Parameter(lambda c: c.density * sp.pi * (c.diameter**2 - c.innerDiameter**2) / 4
                     * c.length, unit="kg", description="mass rho pi (d^2 - di^2) L/4")
    I_11 = ac.Parameter(lambda c: c.m * (c.diameter**2 + c.innerDiameter**2) / 8,
                        unit="kg.m2", description="m (d^2 + di^2)/8")
    I_22 = ac.Parameter(lambda c: c.m * ((c.diameter**2 + c.innerDiameter**2) / 16
                                         + c.length**2 / 12),
                        unit="kg.m2", description="m ((d^2 + di^2)/16 + L^2/12)")
    I_33 = ac.Parameter(lambda c: c.m * ((c.diameter**2 + c.innerDiameter**2) / 16
                                         + c.length**2 / 12),
                        unit="kg.m2", description="m ((d^2 + di^2)/16 + L^2/12)")
