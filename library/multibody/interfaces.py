"""Partial models of planar multibody mechanics (Modelica PlanarMechanics.Interfaces).

Frames carry the position (x, y) and angle phi of a point in the world, and the cut
force (fx, fy) and torque tau acting on the component, in world coordinates.
"""
import acausal as ac
from acausal.ports import Frame

__all__ = ["PartialOneFrame", "PartialTwoFrames", "PartialLineForce"]


class PartialOneFrame(ac.Component):
    """One frame, named frame."""

    frame = Frame()


class PartialTwoFrames(ac.Component):
    """Two frames, frame_a and frame_b."""

    frame_a = Frame()
    frame_b = Frame()


class PartialLineForce(PartialTwoFrames):
    """A massless force element acting along the line through the two frame origins
    (MSL PlanarMechanics line-force elements):

        s^2 = |r_b - r_a|^2,   (frame_b.fx, frame_b.fy) = f (r_b - r_a)/s,
        frame_a.f = -frame_b.f,   frame_a.tau = frame_b.tau = 0

    f > 0 is tension: it pulls the frames towards each other.  The direction is
    undefined at s = 0.  The distance is defined implicitly (s > 0 by its start
    value), the form of the DAE notes' constraint (3.2.4): differentiated twice it
    stays polynomial, where s = sqrt(...) made a 10-rod chain compile 9 times slower.
    """

    s = ac.Variable(start=1.0, unit="m", min=0, state_select="avoid",
                    description="distance between the frame origins")
    f = ac.Variable(unit="N", description="tension force along the line")

    def equations(self):
        dx = self.frame_b.x - self.frame_a.x
        dy = self.frame_b.y - self.frame_a.y
        return [ac.Eq(self.s**2, dx**2 + dy**2),
                ac.Eq(self.frame_b.fx * self.s, self.f * dx),
                ac.Eq(self.frame_b.fy * self.s, self.f * dy),
                ac.Eq(self.frame_a.fx, -self.frame_b.fx),
                ac.Eq(self.frame_a.fy, -self.frame_b.fy),
                ac.Eq(self.frame_a.tau, 0),
                ac.Eq(self.frame_b.tau, 0)]
