"""Joints of planar multibody systems (Modelica PlanarMechanics.Joints).

A joint is massless: the forces and torques on its two frames balance.  Its flange is
an optional drive acting between frame_a and frame_b; left unconnected it carries no
torque (force), and the joint is free.
"""
import acausal as ac
from acausal.ports import RotationalFlange, TranslationalFlange

from .interfaces import PartialTwoFrames
from .parts import rotate

__all__ = ["Revolute", "Prismatic"]


class Revolute(PartialTwoFrames):
    """Revolute joint, frame_b turned by phi relative to frame_a about their common
    origin (MSL PlanarMechanics.Joints.Revolute):

        (frame_b.x, frame_b.y) = (frame_a.x, frame_a.y),   frame_b.phi = frame_a.phi + phi,
        w = der(phi),   a = der(w),   frame_a.f + frame_b.f = 0,
        frame_b.tau = -flange.tau,   frame_a.tau = flange.tau,   flange.phi = phi

    A torque tau driving the flange turns frame_b in +phi relative to frame_a.  phi and
    w are preferred states, as in the MSL: the joint coordinates are then the states of
    an open chain and need not be re-chosen at run time.  a = der(w) is there, as in
    the MSL, so that phi appears twice differentiated: index reduction then
    differentiates the joint's angle equation twice and phi, w can be states.
    """

    flange = RotationalFlange()
    phi = ac.Variable(start=0.0, unit="rad", state_select="prefer",
                      description="rotation angle of frame_b relative to frame_a")
    w = ac.Variable(start=0.0, unit="rad/s", state_select="prefer",
                    description="relative angular velocity")
    a = ac.Variable(unit="rad/s2", description="relative angular acceleration")

    energy_role = "lossless"  # an ideal joint: the flange takes what the frames give

    def equations(self):
        a, b = self.frame_a, self.frame_b
        return [ac.Eq(b.x, a.x), ac.Eq(b.y, a.y),
                ac.Eq(b.phi, a.phi + self.phi),
                ac.Eq(self.w, ac.der(self.phi)),
                ac.Eq(self.a, ac.der(self.w)),
                ac.Eq(0, a.fx + b.fx), ac.Eq(0, a.fy + b.fy),
                ac.Eq(b.tau, -self.flange.tau),
                ac.Eq(a.tau, self.flange.tau),
                ac.Eq(self.flange.phi, self.phi)]


class Prismatic(PartialTwoFrames):
    """Prismatic joint, frame_b shifted by s along the unit direction e fixed in
    frame_a (MSL PlanarMechanics.Joints.Prismatic):

        e0 = R(frame_a.phi) e / |e|,   (frame_b.x, frame_b.y) = (frame_a.x, frame_a.y) + s e0,
        frame_b.phi = frame_a.phi,   v = der(s),   a = der(v),
        frame_a.f + frame_b.f = 0,   e0 . frame_b.f = -flange.f,
        frame_a.tau + frame_b.tau + s (e0_x frame_b.fy - e0_y frame_b.fx) = 0,
        flange.s = s

    A force f driving the flange pushes frame_b in +e relative to frame_a.
    """

    ex = ac.Parameter(1.0, description="x of the direction of translation in frame_a")
    ey = ac.Parameter(0.0, description="y of the direction of translation in frame_a")
    flange = TranslationalFlange()
    s = ac.Variable(start=0.0, unit="m", state_select="prefer",
                    description="translation of frame_b relative to frame_a along e")
    v = ac.Variable(start=0.0, unit="m/s", state_select="prefer",
                    description="relative velocity along e")
    a = ac.Variable(unit="m/s2", description="relative acceleration along e")

    energy_role = "lossless"  # an ideal joint: the flange takes what the frames give

    def equations(self):
        a, b = self.frame_a, self.frame_b
        norm = (self.ex**2 + self.ey**2)**0.5
        e0x, e0y = rotate(a.phi, self.ex / norm, self.ey / norm)
        return [ac.Eq(b.x, a.x + self.s * e0x),
                ac.Eq(b.y, a.y + self.s * e0y),
                ac.Eq(b.phi, a.phi),
                ac.Eq(self.v, ac.der(self.s)),
                ac.Eq(self.a, ac.der(self.v)),
                ac.Eq(0, a.fx + b.fx), ac.Eq(0, a.fy + b.fy),
                ac.Eq(e0x * b.fx + e0y * b.fy, -self.flange.f),
                ac.Eq(0, a.tau + b.tau + self.s * (e0x * b.fy - e0y * b.fx)),
                ac.Eq(self.flange.s, self.s)]
