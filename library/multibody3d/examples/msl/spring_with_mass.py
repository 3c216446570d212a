"""Modelica.Mechanics.MultiBody.Examples.Elementary.SpringWithMass (MSL v4.0.0): a body
of 1 kg hanging from the world's origin on a spring (40 N/m, unstretched 0.2 m) with a
mass of 0.5 kg in its middle, started at rest at (0, -0.3, 0).  The body's free-motion
states (the MSL body's own) are on a FreeMotion joint from the World."""
import acausal as ac
from acausal.library.multibody3d import Body, FreeMotion, Spring, World

from . import MSLNames

__all__ = ["SpringWithMass"]


class SpringWithMass(ac.Component):
    """Point mass hanging on a spring."""

    msl_name = "Modelica.Mechanics.MultiBody.Examples.Elementary.SpringWithMass"
    stop_time = 5.0
    tolerance = 1e-6
    msl_signals = MSLNames()

    world = World()
    spring = Spring(s_unstretched=0.2, m=0.5, c=40.0)
    body = Body(r_CM_1=0.0, r_CM_2=0.0, r_CM_3=0.0, m=1.0)
    freeMotion = FreeMotion(r_rel_a={"start": [0.0, -0.3, 0.0], "fixed": True},
                            v_rel_a={"fixed": True}, angles_fixed=True,
                            w_rel_b={"fixed": True})

    def equations(self):
        return [ac.connect(self.world.frame_b, self.spring.frame_a, self.freeMotion.frame_a),
                ac.connect(self.body.frame_a, self.spring.frame_b, self.freeMotion.frame_b)]
