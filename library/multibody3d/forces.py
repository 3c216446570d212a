"""Force elements of spatial multibody systems (Modelica.Mechanics.MultiBody.Forces):
line forces between two frames, and a force or torque given in the world acting on one
frame.  They read the frames' positions and orientations and write only cut forces and
torques."""
from acausal._sympy import sympy as sp

import acausal as ac
from acausal.ports import RealInput
from acausal.ports.spatial import Frame

from ..multibody.forces import _DamperLaw, _SpringDamperLaw, _SpringLaw
from .frames import force, orientation, position, resolve2, torque, vector
from .interfaces import PartialTwoFrames, equal

__all__ = ["PartialLineForce", "Spring", "Damper", "SpringDamper", "WorldForce",
           "WorldTorque"]


class PartialLineForce(PartialTwoFrames):
    """A massless force element acting along the line from frame_a's origin to
    frame_b's (MSL MultiBody.Interfaces.PartialLineForce):

        s^2 = |r_0,b - r_0,a|^2,   e_0 = (r_0,b - r_0,a)/s,
        f_b = R_b (f e_0),   f_a = -R_a (f e_0),   t_a = t_b = 0

    f > 0 is tension: it pulls the frames towards each other.  As in the planar
    library the distance is defined implicitly (s > 0 by its start value), which stays
    polynomial when index reduction differentiates it.  The direction is undefined at
    s = 0.
    """

    s = ac.Variable(start=1.0, unit="m", min=0, state_select="avoid",
                    description="distance between the frame origins")
    f = ac.Variable(unit="N", description="tension force along the line")

    def equations(self):
        a, b = self.frame_a, self.frame_b
        d = position(b) - position(a)
        zero = sp.zeros(3, 1)
        return [ac.Eq(self.s**2, d.dot(d)),
                *equal(self.s * force(b), self.f * resolve2(orientation(b), d)),
                *equal(self.s * force(a), -self.f * resolve2(orientation(a), d)),
                *equal(torque(a), zero), *equal(torque(b), zero)]


class Spring(_SpringLaw, PartialLineForce):
    """Linear spring along the line:  f = c (s - s_unstretched)."""


class Damper(_DamperLaw, PartialLineForce):
    """Linear damper along the line:  f = d der(s)."""


class SpringDamper(_SpringDamperLaw, PartialLineForce):
    """Spring and damper in parallel:  f = c (s - s_unstretched) + d der(s)."""


class WorldForce(ac.Component):
    """Force F given in world coordinates by three signals, acting on frame_b at its
    origin (MSL MultiBody.Forces.WorldForce, resolveInFrame = world):

        f_b = -R_b F,   t_b = 0
    """

    frame_b = Frame()
    force_x = RealInput()
    force_y = RealInput()
    force_z = RealInput()

    energy_role = "source"

    def equations(self):
        b = self.frame_b
        F = vector(self.force_x.signal, self.force_y.signal, self.force_z.signal)
        return [*equal(force(b), -resolve2(orientation(b), F)),
                *equal(torque(b), sp.zeros(3, 1))]


class WorldTorque(ac.Component):
    """Torque T given in world coordinates by three signals, acting on frame_b
    (MSL MultiBody.Forces.WorldTorque, resolveInFrame = world):

        t_b = -R_b T,   f_b = 0
    """

    frame_b = Frame()
    torque_x = RealInput()
    torque_y = RealInput()
    torque_z = RealInput()

    energy_role = "source"

    def equations(self):
        b = self.frame_b
        T = vector(self.torque_x.signal, self.torque_y.signal, self.torque_z.signal)
        return [*equal(torque(b), -resolve2(orientation(b), T)),
                *equal(force(b), sp.zeros(3, 1))]
