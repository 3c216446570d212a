"""Modelica.Mechanics.MultiBody.Examples.Elementary.ThreeSprings (MSL v4.0.0): a body
(0.8 kg, 0.1 kg.m2 about each axis, its centre of mass 0.2 m below frame_a) on a spring
(40 N/m) from a massless node that two springs (20 N/m each) hold to the world, 0.3 m
along x and 0.3 m along z; all unstretched at 0.1 m.  spring3 fixes the node's
orientation (fixedRotationAtFrame_b); the node's position is found from the balance of
the three line forces, spring1's position guess r_rel_0 = (-0.2, -0.2, 0.2).  The
body's free-motion states are on a FreeMotion joint from the World."""
import acausal as ac
from acausal.library.multibody3d import Body, FixedTranslation, FreeMotion, Spring, World

from . import MSLNames

__all__ = ["ThreeSprings"]


class ThreeSprings(ac.Component):
    """3-dim. springs in series and parallel connection."""

    msl_name = "Modelica.Mechanics.MultiBody.Examples.Elementary.ThreeSprings"
    stop_time = 10.0
    tolerance = 1e-6
    msl_signals = MSLNames()

    world = World()
    body1 = Body(r_CM_1=0.0, r_CM_2=-0.2, r_CM_3=0.0, m=0.8, I_11=0.1, I_22=0.1, I_33=0.1)
    freeMotion = FreeMotion(r_rel_a={"start": [0.5, -0.3, 0.0], "fixed": True},
                            v_rel_a={"fixed": True}, angles_fixed=True,
                            w_rel_b={"fixed": True})
    bar1 = FixedTranslation(r_1=0.3, r_2=0.0, r_3=0.0)
    spring1 = Spring(r_rel_0={"start": [-0.2, -0.2, 0.2]}, s_unstretched=0.1, c=20.0)
    bar2 = FixedTranslation(r_1=0.0, r_2=0.0, r_3=0.3)
    spring2 = Spring(s_unstretched=0.1, c=40.0)
    spring3 = Spring(s_unstretched=0.1, c=20.0, fixedRotationAtFrame_b=True)

    def equations(self):
        return [ac.connect(self.world.frame_b, self.bar1.frame_a),
                ac.connect(self.world.frame_b, self.bar2.frame_a, self.freeMotion.frame_a),
                ac.connect(self.bar1.frame_b, self.spring1.frame_a),
                ac.connect(self.bar2.frame_b, self.spring3.frame_a),
                ac.connect(self.spring2.frame_b, self.body1.frame_a, self.freeMotion.frame_b),
                ac.connect(self.spring3.frame_b, self.spring1.frame_b),
                ac.connect(self.spring2.frame_a, self.spring1.frame_b)]
