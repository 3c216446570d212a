"""Rigid parts of planar multibody systems (Modelica PlanarMechanics.Parts).

Rotation of a frame by phi maps a vector r given in that frame to the world:

    R(phi) r = (cos(phi) r_x - sin(phi) r_y,  sin(phi) r_x + cos(phi) r_y)
"""
from acausal._sympy import sympy as sp

import acausal as ac

from .interfaces import PartialOneFrame, PartialTwoFrames

__all__ = ["FixedFrame", "Body", "PointMass", "FixedTranslation"]


def rotate(phi, rx, ry) -> tuple:
    """R(phi) r: a vector given in a frame at angle phi, in world coordinates.

    Parameters
    ----------
    phi : sympy expression
        Angle of the frame [rad].
    rx, ry : sympy expression or float
        The vector's components in the frame.

    Returns
    -------
    tuple
        The world components (cos(phi) rx - sin(phi) ry, sin(phi) rx + cos(phi) ry).
    """
    c, s = sp.cos(phi), sp.sin(phi)
    return c * rx - s * ry, s * rx + c * ry


class FixedFrame(PartialOneFrame):
    """A frame fixed in the world (MSL PlanarMechanics.Parts.Fixed):

        frame.x = x0,   frame.y = y0,   frame.phi = phi0
    """

    x0 = ac.Parameter(0.0, unit="m", description="x position in the world frame")
    y0 = ac.Parameter(0.0, unit="m", description="y position in the world frame")
    phi0 = ac.Parameter(0.0, unit="rad", description="fixed angle")

    energy_role = "lossless"  # fixed in the world: does no work

    def equations(self):
        return [ac.Eq(self.frame.x, self.x0),
                ac.Eq(self.frame.y, self.y0),
                ac.Eq(self.frame.phi, self.phi0)]


class Body(PartialOneFrame):
    """Rigid body with mass m and moment of inertia J about its centre of mass, where
    its frame is; gravity g acts in -y (Newton-Euler in the plane, Egeland & Gravdahl
    (7.32), (7.128); MSL PlanarMechanics.Parts.Body):

        v = der(r),   w = der(phi),
        m der(vx) = frame.fx,   m der(vy) = frame.fy - m g,   J der(w) = frame.tau

    A point mass is J = 0 on a body whose angle is set by what it is attached to.
    """

    m = ac.Parameter(1.0, unit="kg", min=0, description="mass")
    J = ac.Parameter(0.1, unit="kg.m2", min=0, description="inertia about the centre of mass")
    g = ac.Parameter(9.81, unit="m/s2", description="gravity, acting in -y")
    x = ac.Variable(start=0.0, unit="m", description="x position of the centre of mass")
    y = ac.Variable(start=0.0, unit="m", description="y position of the centre of mass")
    phi = ac.Variable(start=0.0, unit="rad", description="angle of the body")
    vx = ac.Variable(start=0.0, unit="m/s", description="velocity in x")
    vy = ac.Variable(start=0.0, unit="m/s", description="velocity in y")
    w = ac.Variable(start=0.0, unit="rad/s", description="angular velocity")

    def stored_energy(self):
        """Kinetic and potential energy m (vx^2 + vy^2)/2 + J w^2/2 + m g y
        (Egeland & Gravdahl (7.34))."""
        return (self.m * (self.vx**2 + self.vy**2) / 2 + self.J * self.w**2 / 2
                + self.m * self.g * self.y)

    def equations(self):
        f = self.frame
        return [ac.Eq(self.x, f.x), ac.Eq(self.y, f.y), ac.Eq(self.phi, f.phi),
                ac.Eq(self.vx, ac.der(self.x)),
                ac.Eq(self.vy, ac.der(self.y)),
                ac.Eq(self.w, ac.der(self.phi)),
                ac.Eq(self.m * ac.der(self.vx), f.fx),
                ac.Eq(self.m * ac.der(self.vy), f.fy - self.m * self.g),
                ac.Eq(self.J * ac.der(self.w), f.tau)]


class PointMass(PartialOneFrame):
    """Point mass m without orientation; gravity g acts in -y (the particles of the DAE
    notes, 000 section 3.2):

        v = der(r),   m der(vx) = frame.fx,   m der(vy) = frame.fy - m g,   frame.phi = 0

    Its frame is kept parallel to the world, so it takes any torque.  Attach it with
    elements that leave the angle free (``Rod``, ``Spring``, ``Damper``).  On a bar it
    would hold the bar's angle at 0 and lock the joints before it: use ``Body(J=0)``.
    """

    m = ac.Parameter(1.0, unit="kg", min=0, description="mass")
    g = ac.Parameter(9.81, unit="m/s2", description="gravity, acting in -y")
    x = ac.Variable(start=0.0, unit="m", description="x position")
    y = ac.Variable(start=0.0, unit="m", description="y position")
    vx = ac.Variable(start=0.0, unit="m/s", description="velocity in x")
    vy = ac.Variable(start=0.0, unit="m/s", description="velocity in y")

    def stored_energy(self):
        """Kinetic and potential energy m (vx^2 + vy^2)/2 + m g y."""
        return self.m * (self.vx**2 + self.vy**2) / 2 + self.m * self.g * self.y

    def equations(self):
        f = self.frame
        return [ac.Eq(self.x, f.x), ac.Eq(self.y, f.y), ac.Eq(f.phi, 0),
                ac.Eq(self.vx, ac.der(self.x)),
                ac.Eq(self.vy, ac.der(self.y)),
                ac.Eq(self.m * ac.der(self.vx), f.fx),
                ac.Eq(self.m * ac.der(self.vy), f.fy - self.m * self.g)]


class FixedTranslation(PartialTwoFrames):
    """Massless rigid bar from frame_a to frame_b; r is fixed in frame_a
    (MSL PlanarMechanics.Parts.FixedTranslation):

        (frame_b.x, frame_b.y) = (frame_a.x, frame_a.y) + R(frame_a.phi) r,
        frame_b.phi = frame_a.phi,
        frame_a.f + frame_b.f = 0,
        frame_a.tau + frame_b.tau + r0_x frame_b.fy - r0_y frame_b.fx = 0,  r0 = R(phi) r
    """

    rx = ac.Parameter(1.0, unit="m", description="x of frame_b in frame_a")
    ry = ac.Parameter(0.0, unit="m", description="y of frame_b in frame_a")

    energy_role = "lossless"  # a rigid massless bar

    def equations(self):
        a, b = self.frame_a, self.frame_b
        r0x, r0y = rotate(a.phi, self.rx, self.ry)
        return [ac.Eq(b.x, a.x + r0x),
                ac.Eq(b.y, a.y + r0y),
                ac.Eq(b.phi, a.phi),
                ac.Eq(0, a.fx + b.fx),
                ac.Eq(0, a.fy + b.fy),
                ac.Eq(0, a.tau + b.tau + r0x * b.fy - r0y * b.fx)]
