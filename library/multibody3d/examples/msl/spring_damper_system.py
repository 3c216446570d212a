"""Modelica.Mechanics.MultiBody.Examples.Elementary.SpringDamperSystem (MSL v4.0.0): a
body (1 kg, 0.1 kg.m2 about each axis, centre of mass 0.2 m below frame_a) held by a
spring (30 N/m, unstretched 0.1 m) and a damper (2 N.s/m) from 0.3 m along the
world's x, started at (0.3, -0.2, 0) at rest, turning at 2 deg/s about z; and a body of
1 kg on a prismatic joint along -y 0.9 m along x, on a spring of the same data.  The
first body's free-motion states are on a FreeMotion joint from the World."""
import acausal as ac
from acausal.library.multibody3d import (Body, Damper, FixedTranslation, FreeMotion,
                                         Prismatic, Spring, World)

from . import MSLNames

__all__ = ["SpringDamperSystem"]


class SpringDamperSystem(ac.Component):
    """Simple spring/damper/mass system."""

    msl_name = "Modelica.Mechanics.MultiBody.Examples.Elementary.SpringDamperSystem"
    stop_time = 10.0
    tolerance = 1e-6
    msl_signals = MSLNames()

    world = World()
    body1 = Body(m=1.0, r_CM_1=0.0, r_CM_2=-0.2, r_CM_3=0.0, I_11=0.1, I_22=0.1, I_33=0.1)
    freeMotion = FreeMotion(r_rel_a={"start": [0.3, -0.2, 0.0], "fixed": True},
                            v_rel_a={"fixed": True}, angles_fixed=True,
                            w_rel_b={"start": [0.0, 0.0, 0.03490658503988659],
                                     "fixed": True})
    bar1 = FixedTranslation(r_1=0.3, r_2=0.0, r_3=0.0)
    bar2 = FixedTranslation(r_1=0.6, r_2=0.0, r_3=0.0)
    body2 = Body(m=1.0, r_CM_1=0.0, r_CM_2=0.0, r_CM_3=0.0)
    p2 = Prismatic(n_1=0.0, n_2=-1.0, n_3=0.0,
                   s={"fixed": True, "start": 0.1, "state_select": "always"},
                   v={"fixed": True, "state_select": "always"})
    spring2 = Spring(c=30.0, s_unstretched=0.1)
    spring1 = Spring(s_unstretched=0.1, c=30.0)
    damper1 = Damper(d=2.0)

    def equations(self):
        return [ac.connect(self.world.frame_b, self.bar1.frame_a, self.freeMotion.frame_a),
                ac.connect(self.bar1.frame_b, self.bar2.frame_a),
                ac.connect(self.bar2.frame_b, self.p2.frame_a),
                ac.connect(self.p2.frame_b, self.body2.frame_a),
                ac.connect(self.bar2.frame_b, self.spring2.frame_a),
                ac.connect(self.body2.frame_a, self.spring2.frame_b),
                ac.connect(self.damper1.frame_a, self.bar1.frame_b),
                ac.connect(self.spring1.frame_a, self.bar1.frame_b),
                ac.connect(self.damper1.frame_b, self.body1.frame_a, self.freeMotion.frame_b),
                ac.connect(self.spring1.frame_b, self.body1.frame_a)]
