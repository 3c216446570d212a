"""Ideal rolling wheels on the plane z = 0 (Modelica.Mechanics.MultiBody: Joints.RollingWheel,
Joints.RollingWheelSet, Joints.Internal.RollingConstraintVerticalWheel, Parts.RollingWheel,
Parts.RollingWheelSet, Parts.Mounting1D).

The ground is the world's x-y plane, its normal e_n = (0, 0, 1); gravity should point
along -z (``World(n_1=0, n_2=0, n_3=-1)``).  A wheel rolls without slipping: the
velocity of its contact point is 0 along the ground (two non-holonomic constraints on
the velocities), and it touches the ground (one holonomic constraint).  The wheel
joints are roots of the orientation tree (they set their frames' orientation from their
own coordinates, as the MSL's Connections.root).
"""
from __future__ import annotations

from acausal._sympy import sympy as sp

import acausal as ac
from acausal.ports import RotationalFlange
from acausal.ports.spatial import Frame

from .frames import angular_velocity1, axes_rotations, force, orientation, position, resolve2, torque
from .interfaces import equal
from .joints import Prismatic, Revolute
from .parts import Body, Fixed, FixedTranslation

__all__ = ["RollingWheelJoint", "RollingConstraintVerticalWheel", "RollingWheelSetJoint",
           "Mounting1D", "RollingWheel", "RollingWheelSet"]

_UP = sp.Matrix([0, 0, 1])


def _unit(v):
    return v / sp.sqrt(v.dot(v))


class RollingWheelJoint(ac.Component):
    """Joint (no mass, no inertia) of an ideal wheel rolling on the plane z = 0 (MSL
    MultiBody.Joints.RollingWheel; frame_a in the wheel's centre, its y along the wheel
    axis):

        r_0,a = (x, y, z),   R_a = axesRotations({3, 2, 1}, angles),
        e_axis = R_a^T (0, 1, 0),   e_long = e_n x e_axis / |e_n x e_axis|,
        e_lat = e_long x e_n,   delta = (s, w, 0) - r_0,a,
        0 = delta . e_axis,   0 = delta . e_long,   0 = radius - delta . (e_long x e_axis),
        v_c = der(r_0,a) + w_0 x delta,   0 = v_c . e_long,   0 = v_c . e_lat,
        f_wheel = f_n e_n + f_lat e_lat + f_long e_long,
        0 = f_a + R_a f_wheel,   0 = t_a + R_a (delta x f_wheel)

    (s, w) is the contact point on the ground, w_0 the wheel's angular velocity in the
    world.
    """

    radius = ac.Parameter(1.0, unit="m", min=0, description="wheel radius")
    frame_a = Frame()
    x = ac.Variable(start=0.0, unit="m", description="x of the wheel centre")
    y = ac.Variable(start=0.0, unit="m", description="y of the wheel centre")
    z = ac.Variable(start=1.0, unit="m", description="z of the wheel centre")
    angles = ac.Variable(shape=3, start=0.0, unit="rad",
                         description="angles about z, y, x that turn the world into frame_a")
    der_angles = ac.Variable(shape=3, start=0.0, unit="rad/s", description="der(angles)")
    s = ac.Variable(start=0.0, unit="m", description="x of the contact point")
    w = ac.Variable(start=0.0, unit="m", description="y of the contact point")
    f_n = ac.Variable(unit="N", description="contact force normal to the ground")
    f_lat = ac.Variable(unit="N", description="contact force along e_lat")
    f_long = ac.Variable(unit="N", description="contact force along e_long")

    energy_role = "lossless"  # ideal rolling: the contact point does not move

    def __init__(self, *, stateSelect: str = "always", **modifications):
        for name in ("x", "y", "angles", "der_angles"):
            own = modifications.get(name, {})
            own = own if isinstance(own, dict) else {"start": own}
            modifications[name] = {"state_select": stateSelect, **own}
        super().__init__(**modifications)

    def equations(self):
        fa = self.frame_a
        angles, der_angles = sp.Matrix(self.angles), sp.Matrix(self.der_angles)
        R = axes_rotations((3, 2, 1), angles)
        r = sp.Matrix([self.x, self.y, self.z])
        e_axis = R.T * sp.Matrix([0, 1, 0])
        e_long = _unit(_UP.cross(e_axis))
        e_lat = e_long.cross(_UP)
        delta = sp.Matrix([self.s, self.w, 0]) - r
        w_0 = angular_velocity1(R, R.applyfunc(ac.der))
        v_c = r.applyfunc(ac.der) + w_0.cross(delta)
        f_wheel = self.f_n * _UP + self.f_lat * e_lat + self.f_long * e_long
        return [*equal(position(fa), r),
                *equal(der_angles, angles.applyfunc(ac.der)),
                *equal(orientation(fa), R),
                ac.Eq(0, delta.dot(e_axis)),
                ac.Eq(0, delta.dot(e_long)),
                ac.Eq(0, self.radius - delta.dot(e_long.cross(e_axis))),
                ac.Eq(0, v_c.dot(e_long)),
                ac.Eq(0, v_c.dot(e_lat)),
                *equal(sp.zeros(3, 1), force(fa) + resolve2(R, f_wheel)),
                *equal(sp.zeros(3, 1), torque(fa) + resolve2(R, delta.cross(f_wheel)))]


class RollingConstraintVerticalWheel(ac.Component):
    """Rolling constraint of a wheel that stays perpendicular to the ground (MSL
    MultiBody.Joints.Internal.RollingConstraintVerticalWheel; frame_a in the wheel's
    centre, its y along the wheel axis):

        e_axis = R_a^T (0, 1, 0),   e_long = e_n x e_axis / |e_n x e_axis|,
        e_lat = e_long x e_n,   r_c = (0, 0, -radius),
        v_c = der(r_0,a) + w_0 x r_c,   0 = v_c . e_long,
        0 = v_c . e_lat and f_wheel = f_lat e_lat + f_long e_long   (lateral constraint)
        f_lat = 0 and f_wheel = f_long e_long                       (otherwise)
        0 = f_a + R_a f_wheel,   0 = t_a + R_a (r_c x f_wheel)

    ``lateralSlidingConstraint=False`` (given when it is made) leaves the lateral
    constraint out, for the second wheel of an axle, which the first already holds.
    """

    radius = ac.Parameter(1.0, unit="m", min=0, description="wheel radius")
    frame_a = Frame()
    f_lat = ac.Variable(unit="N", description="contact force along e_lat")
    f_long = ac.Variable(unit="N", description="contact force along e_long")

    energy_role = "lossless"

    def __init__(self, *, lateralSlidingConstraint: bool = True, **modifications):
        self.lateralSlidingConstraint = bool(lateralSlidingConstraint)
        super().__init__(**modifications)

    def equations(self):
        fa = self.frame_a
        R = orientation(fa)
        e_axis = R.T * sp.Matrix([0, 1, 0])
        e_long = _unit(_UP.cross(e_axis))
        e_lat = e_long.cross(_UP)
        r_c = sp.Matrix([0, 0, -self.radius])
        w_0 = angular_velocity1(R, R.applyfunc(ac.der))
        v_c = position(fa).applyfunc(ac.der) + w_0.cross(r_c)
        if self.lateralSlidingConstraint:
            lateral = [ac.Eq(0, v_c.dot(e_lat))]
            f_wheel = self.f_lat * e_lat + self.f_long * e_long
        else:
            lateral = [ac.Eq(self.f_lat, 0)]
            f_wheel = self.f_long * e_long
        return [ac.Eq(0, v_c.dot(e_long)), *lateral,
                *equal(sp.zeros(3, 1), force(fa) + resolve2(R, f_wheel)),
                *equal(sp.zeros(3, 1), torque(fa) + resolve2(R, r_c.cross(f_wheel)))]


class Mounting1D(ac.Component):
    """The housing of a 1-D drive train fixed in a 3-D frame (MSL
    MultiBody.Parts.Mounting1D, driveTrainMechanics3D):

        flange_b.phi = phi0,   frame_a.f = 0,   frame_a.t = -n flange_b.tau
    """

    phi0 = ac.Parameter(0.0, unit="rad", description="fixed offset angle of the housing")
    n_1 = ac.Parameter(1.0, description="axis of the support torque in frame_a, x")
    n_2 = ac.Parameter(0.0, description="axis of the support torque in frame_a, y")
    n_3 = ac.Parameter(0.0, description="axis of the support torque in frame_a, z")
    flange_b = RotationalFlange()
    frame_a = Frame()

    energy_role = "lossless"

    def equations(self):
        n = sp.Matrix([self.n_1, self.n_2, self.n_3])
        return [ac.Eq(self.flange_b.phi, self.phi0),
                *equal(force(self.frame_a), sp.zeros(3, 1)),
                *equal(torque(self.frame_a), -n * self.flange_b.tau)]


class RollingWheelSetJoint(ac.Component):
    """Joint (no mass, no inertia) of two ideal rolling wheels on one axle (MSL
    MultiBody.Joints.RollingWheelSet): the axle's middle moves on prismatic joints along
    x and y and turns about z from a point at the wheel's height, the wheels turn about
    the axle (y of frameMiddle) at +-track/2, the first held by a rolling constraint
    with, the second without, the lateral constraint:

        prismatic1.s = x,   prismatic2.s = y,   revolute.phi = phi,
        revolute1.phi = theta1,   revolute2.phi = theta2,   der_theta_i = der(theta_i)

    axis1 and axis2 drive the wheels, their housing ``support`` is mounted on
    frameMiddle (Mounting1D).
    """

    radius = ac.Parameter(1.0, unit="m", min=0, description="radius of one wheel")
    track = ac.Parameter(1.0, unit="m", min=0, description="distance between the two wheels")
    half_track = ac.Parameter(lambda c: c.track / 2, unit="m", description="track/2")
    minus_half_track = ac.Parameter(lambda c: -c.track / 2, unit="m", description="-track/2")
    frameMiddle = Frame()
    frame1 = Frame()
    frame2 = Frame()
    axis1 = RotationalFlange()
    axis2 = RotationalFlange()
    support = RotationalFlange()
    x = ac.Variable(start=0.0, unit="m", description="x of the axle's middle")
    y = ac.Variable(start=0.0, unit="m", description="y of the axle's middle")
    phi = ac.Variable(start=0.0, unit="rad", description="turn of the axle about z")
    theta1 = ac.Variable(start=0.0, unit="rad", description="angle of wheel 1")
    theta2 = ac.Variable(start=0.0, unit="rad", description="angle of wheel 2")
    der_theta1 = ac.Variable(start=0.0, unit="rad/s", description="der(theta1)")
    der_theta2 = ac.Variable(start=0.0, unit="rad/s", description="der(theta2)")
    fixed = Fixed(r_1=0.0, r_2=0.0, r_3=ac.ref("radius"))
    prismatic1 = Prismatic(n_1=1.0, n_2=0.0, n_3=0.0)
    prismatic2 = Prismatic(n_1=0.0, n_2=1.0, n_3=0.0)
    revolute = Revolute(n_1=0.0, n_2=0.0, n_3=1.0)
    rod1 = FixedTranslation(r_1=0.0, r_2=ac.ref("half_track"), r_3=0.0)
    rod2 = FixedTranslation(r_1=0.0, r_2=ac.ref("minus_half_track"), r_3=0.0)
    revolute1 = Revolute(n_1=0.0, n_2=1.0, n_3=0.0)
    revolute2 = Revolute(n_1=0.0, n_2=1.0, n_3=0.0)
    rolling1 = RollingConstraintVerticalWheel(radius=ac.ref("radius"))
    rolling2 = RollingConstraintVerticalWheel(radius=ac.ref("radius"),
                                              lateralSlidingConstraint=False)
    mounting1D = Mounting1D()

    energy_role = "lossless"

    def __init__(self, *, stateSelect: str = "default", **modifications):
        for name in ("x", "y", "phi", "theta1", "theta2", "der_theta1", "der_theta2"):
            own = modifications.get(name, {})
            own = own if isinstance(own, dict) else {"start": own}
            modifications[name] = {"state_select": stateSelect, **own}
        for joint in ("prismatic1", "prismatic2", "revolute", "revolute1", "revolute2"):
            own = modifications.get(joint, {})
            coordinates = ("s", "v") if joint.startswith("prismatic") else ("phi", "w")
            modifications[joint] = {**{c: {"state_select": "default"} for c in coordinates},
                                    **own}
        super().__init__(**modifications)

    def equations(self):
        return [ac.Eq(self.prismatic1.s, self.x), ac.Eq(self.prismatic2.s, self.y),
                ac.Eq(self.revolute.phi, self.phi), ac.Eq(self.revolute1.phi, self.theta1),
                ac.Eq(self.revolute2.phi, self.theta2),
                ac.Eq(self.der_theta1, ac.der(self.theta1)),
                ac.Eq(self.der_theta2, ac.der(self.theta2)),
                ac.connect(self.revolute.frame_b, self.frameMiddle, self.rod1.frame_a,
                           self.rod2.frame_a, self.mounting1D.frame_a),
                ac.connect(self.rod1.frame_b, self.revolute1.frame_a),
                ac.connect(self.revolute1.frame_b, self.frame1, self.rolling1.frame_a),
                ac.connect(self.revolute2.frame_a, self.rod2.frame_b),
                ac.connect(self.revolute2.frame_b, self.frame2, self.rolling2.frame_a),
                ac.connect(self.prismatic1.frame_a, self.fixed.frame_b),
                ac.connect(self.prismatic1.frame_b, self.prismatic2.frame_a),
                ac.connect(self.prismatic2.frame_b, self.revolute.frame_a),
                ac.connect(self.revolute1.axis, self.axis1),
                ac.connect(self.revolute2.axis, self.axis2),
                ac.connect(self.mounting1D.flange_b, self.support)]


def _wheel_body(m, I_axis, I_long):
    return Body(r_CM_1=0.0, r_CM_2=0.0, r_CM_3=0.0, m=ac.ref(m), I_11=ac.ref(I_long),
                I_22=ac.ref(I_axis), I_33=ac.ref(I_long), I_21=0.0, I_31=0.0, I_32=0.0)


class RollingWheel(ac.Component):
    """An ideal rolling wheel on the plane z = 0: a Body (mass m, inertia I_axis about
    its axis, I_long about the others) on a RollingWheelJoint (MSL
    MultiBody.Parts.RollingWheel; 5 positional, 3 velocity degrees of freedom).  Its
    coordinates x, y, angles and der_angles are the states, all fixed at the start by
    default (the MSL's), starting from 0."""

    radius = ac.Parameter(1.0, unit="m", min=0, description="radius of the wheel")
    m = ac.Parameter(1.0, unit="kg", min=0, description="mass of the wheel")
    I_axis = ac.Parameter(1.0, unit="kg.m2", description="inertia about the wheel axis")
    I_long = ac.Parameter(1.0, unit="kg.m2", description="inertia perpendicular to the wheel axis")
    frame_a = Frame()
    x = ac.Variable(start=0.0, fixed=True, unit="m", state_select="always",
                    description="x of the wheel centre")
    y = ac.Variable(start=0.0, fixed=True, unit="m", state_select="always",
                    description="y of the wheel centre")
    angles = ac.Variable(shape=3, start=0.0, fixed=True, unit="rad", state_select="always",
                         description="angles about z, y, x that turn the world into frame_a")
    der_angles = ac.Variable(shape=3, start=0.0, fixed=True, unit="rad/s",
                             state_select="always", description="der(angles)")
    body = _wheel_body("m", "I_axis", "I_long")
    rollingWheel = RollingWheelJoint(radius=ac.ref("radius"), stateSelect="avoid")

    def equations(self):
        j = self.rollingWheel
        return [ac.Eq(j.x, self.x), ac.Eq(j.y, self.y),
                *(ac.Eq(a, b) for a, b in zip(j.angles, self.angles)),
                *(ac.Eq(a, b) for a, b in zip(j.der_angles, self.der_angles)),
                ac.connect(self.body.frame_a, self.frame_a, j.frame_a)]


class RollingWheelSet(ac.Component):
    """Two ideal rolling wheels on one axle: a Body each on frame1 and frame2 of a
    RollingWheelSetJoint (MSL MultiBody.Parts.RollingWheelSet).  Its coordinates x, y,
    phi, theta1, theta2, der_theta1, der_theta2 are the states, fixed at the start by
    default (the MSL's), starting from 0."""

    R_wheel = ac.Parameter(1.0, unit="m", min=0, description="radius of one wheel")
    m_wheel = ac.Parameter(1.0, unit="kg", min=0, description="mass of one wheel")
    I_wheelAxis = ac.Parameter(1.0, unit="kg.m2",
                               description="inertia of one wheel about its axis")
    I_wheelLong = ac.Parameter(1.0, unit="kg.m2",
                               description="inertia of one wheel perpendicular to its axis")
    track = ac.Parameter(1.0, unit="m", min=0, description="distance between the two wheels")
    frameMiddle = Frame()
    frame1 = Frame()
    frame2 = Frame()
    axis1 = RotationalFlange()
    axis2 = RotationalFlange()
    support = RotationalFlange()
    x = ac.Variable(start=0.0, fixed=True, unit="m", state_select="always",
                    description="x of the axle's middle")
    y = ac.Variable(start=0.0, fixed=True, unit="m", state_select="always",
                    description="y of the axle's middle")
    phi = ac.Variable(start=0.0, fixed=True, unit="rad", state_select="always",
                      description="turn of the axle about z")
    theta1 = ac.Variable(start=0.0, fixed=True, unit="rad", state_select="always",
                         description="angle of wheel 1")
    theta2 = ac.Variable(start=0.0, fixed=True, unit="rad", state_select="always",
                         description="angle of wheel 2")
    der_theta1 = ac.Variable(start=0.0, fixed=True, unit="rad/s", state_select="always",
                             description="der(theta1)")
    der_theta2 = ac.Variable(start=0.0, fixed=True, unit="rad/s", state_select="always",
                             description="der(theta2)")
    body1 = _wheel_body("m_wheel", "I_wheelAxis", "I_wheelLong")
    body2 = _wheel_body("m_wheel", "I_wheelAxis", "I_wheelLong")
    wheelSetJoint = RollingWheelSetJoint(radius=ac.ref("R_wheel"), track=ac.ref("track"))

    def equations(self):
        j = self.wheelSetJoint
        return [ac.Eq(j.x, self.x), ac.Eq(j.y, self.y), ac.Eq(j.phi, self.phi),
                ac.Eq(j.theta1, self.theta1), ac.Eq(j.theta2, self.theta2),
                ac.Eq(self.der_theta1, ac.der(self.theta1)),
                ac.Eq(self.der_theta2, ac.der(self.theta2)),
                ac.connect(self.body2.frame_a, self.frame2, j.frame2),
                ac.connect(self.body1.frame_a, self.frame1, j.frame1),
                ac.connect(j.axis1, self.axis1), ac.connect(j.axis2, self.axis2),
                ac.connect(j.support, self.support),
                ac.connect(j.frameMiddle, self.frameMiddle)]
