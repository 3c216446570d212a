"""Modelica.Mechanics.MultiBody.Examples.Elementary.SpringMassSystem (MSL v4.0.0): two
bodies of 1 kg on prismatic joints along -y, the first held by a 1-D translational
spring between the joint's axis and its support, the second by a 3-D spring (both
30 N/m, unstretched 0.1 m), started at s = 0.1 m."""
import acausal as ac
from acausal.library.multibody3d import Body, FixedTranslation, Prismatic, Spring, World
from acausal.library.translational import Spring as TranslationalSpring

from . import MSLNames

__all__ = ["SpringMassSystem"]


class SpringMassSystem(ac.Component):
    """Mass attached with a spring to the world frame."""

    msl_name = "Modelica.Mechanics.MultiBody.Examples.Elementary.SpringMassSystem"
    stop_time = 5.0
    tolerance = 1e-6
    msl_signals = MSLNames()

    world = World()
    p1 = Prismatic(n_1=0.0, n_2=-1.0, n_3=0.0, s={"fixed": True, "start": 0.1},
                   v={"fixed": True})
    spring1 = TranslationalSpring(c=30.0, s_rel0=0.1)
    body1 = Body(m=1.0, r_CM_1=0.0, r_CM_2=0.0, r_CM_3=0.0)
    bar1 = FixedTranslation(r_1=0.3, r_2=0.0, r_3=0.0)
    bar2 = FixedTranslation(r_1=0.3, r_2=0.0, r_3=0.0)
    body2 = Body(m=1.0, r_CM_1=0.0, r_CM_2=0.0, r_CM_3=0.0)
    p2 = Prismatic(n_1=0.0, n_2=-1.0, n_3=0.0, s={"fixed": True, "start": 0.1,
                                                  "state_select": "always"},
                   v={"fixed": True, "state_select": "always"})
    spring2 = Spring(c=30.0, s_unstretched=0.1)

    def equations(self):
        return [ac.connect(self.body1.frame_a, self.p1.frame_b),
                ac.connect(self.world.frame_b, self.bar1.frame_a),
                ac.connect(self.bar1.frame_b, self.p1.frame_a),
                ac.connect(self.spring1.flange_b, self.p1.axis),
                ac.connect(self.bar1.frame_b, self.bar2.frame_a),
                ac.connect(self.bar2.frame_b, self.p2.frame_a),
                ac.connect(self.p2.frame_b, self.body2.frame_a),
                ac.connect(self.bar2.frame_b, self.spring2.frame_a),
                ac.connect(self.body2.frame_a, self.spring2.frame_b),
                ac.connect(self.spring1.flange_a, self.p1.support)]
