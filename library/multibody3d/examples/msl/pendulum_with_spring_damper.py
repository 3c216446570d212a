"""Modelica.Mechanics.MultiBody.Examples.Elementary.PendulumWithSpringDamper (MSL
v4.0.0): a body of 1 kg on a prismatic joint along x on a revolute joint about z at the
end of a 0.3 m bar, held by a spring (20 N/m, unstretched 0.2 m) and a damper
(1 N.s/m) between the bar's end and the body."""
import acausal as ac
from acausal.library.multibody3d import (Body, Damper, FixedTranslation, Prismatic, Revolute,
                                         Spring, World)

from . import MSLNames

__all__ = ["PendulumWithSpringDamper"]


class PendulumWithSpringDamper(ac.Component):
    """Simple spring/damper/mass system."""

    msl_name = "Modelica.Mechanics.MultiBody.Examples.Elementary.PendulumWithSpringDamper"
    stop_time = 10.0
    tolerance = 1e-6
    msl_signals = MSLNames()

    world = World()
    body1 = Body(m=1.0, I_11=1.0, I_22=1.0, I_33=1.0, r_CM_1=0.0, r_CM_2=0.0, r_CM_3=0.0)
    bar1 = FixedTranslation(r_1=0.3, r_2=0.0, r_3=0.0)
    spring1 = Spring(c=20.0, s_unstretched=0.2)
    damper1 = Damper(d=1.0)
    revolute = Revolute(phi={"fixed": True}, w={"fixed": True})
    prismatic = Prismatic(s={"fixed": True, "start": 0.5}, v={"fixed": True})

    def equations(self):
        return [ac.connect(self.world.frame_b, self.bar1.frame_a),
                ac.connect(self.revolute.frame_a, self.bar1.frame_b),
                ac.connect(self.prismatic.frame_a, self.revolute.frame_b),
                ac.connect(self.damper1.frame_a, self.bar1.frame_b),
                ac.connect(self.damper1.frame_b, self.prismatic.frame_b),
                ac.connect(self.spring1.frame_a, self.bar1.frame_b),
                ac.connect(self.spring1.frame_b, self.prismatic.frame_b),
                ac.connect(self.body1.frame_a, self.prismatic.frame_b)]
