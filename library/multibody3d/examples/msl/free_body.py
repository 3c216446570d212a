"""Modelica.Mechanics.MultiBody.Examples.Elementary.FreeBody (MSL v4.0.0): a free body
(1 kg, inertia 1 kg.m2 about each axis, 0.4 m long, its centre of mass 0.2 m along it)
hanging on two springs (20 N/m, unstretched 0): one from the world's origin to its
frame_a, one from 0.8 m along the world's x to its frame_b.

The MSL's body carries its own free-motion states (r_0, v_0 fixed at the start, its
orientation from angles_start about the axes 1, 2, 3, w_0 fixed at 0); here a
FreeMotion joint between the World and the body carries them, with the same starts.
"""
import acausal as ac
from acausal.library.multibody3d import (BodyShape, FixedTranslation, FreeMotion, Spring,
                                         World)

from . import MSLNames

__all__ = ["FreeBody"]

_ANGLE = 0.174532925199433    # 10 degrees


class FreeBody(ac.Component):
    """Free flying body attached by two springs to the environment."""

    msl_name = "Modelica.Mechanics.MultiBody.Examples.Elementary.FreeBody"
    stop_time = 10.0
    tolerance = 1e-6
    msl_signals = MSLNames()

    world = World()
    bar2 = FixedTranslation(r_1=0.8, r_2=0.0, r_3=0.0)
    spring1 = Spring(c=20.0, s_unstretched=0.0)
    body = BodyShape(m=1.0, I_11=1.0, I_22=1.0, I_33=1.0, r_1=0.4, r_2=0.0, r_3=0.0,
                     r_CM_1=0.2, r_CM_2=0.0, r_CM_3=0.0)
    freeMotion = FreeMotion(r_rel_a={"start": [0.2, -0.5, 0.1], "fixed": True},
                            v_rel_a={"fixed": True},
                            angles_start=(_ANGLE, _ANGLE, _ANGLE), angles_fixed=True,
                            w_rel_b={"fixed": True})
    spring2 = Spring(c=20.0, s_unstretched=0.0)

    def equations(self):
        return [ac.connect(self.bar2.frame_a, self.world.frame_b),
                ac.connect(self.spring1.frame_b, self.body.frame_a),
                ac.connect(self.bar2.frame_b, self.spring2.frame_a),
                ac.connect(self.spring1.frame_a, self.world.frame_b),
                ac.connect(self.body.frame_b, self.spring2.frame_b),
                ac.connect(self.world.frame_b, self.freeMotion.frame_a),
                ac.connect(self.freeMotion.frame_b, self.body.frame_a)]
