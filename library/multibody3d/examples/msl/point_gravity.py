"""Modelica.Mechanics.MultiBody.Examples.Elementary.PointGravity (MSL v4.0.0): two
bodies (1 kg, 0.1 kg.m2 about each axis) in the point gravity field of the World
(mu = 1 m3/s2), started at (0, 0.6, 0) with (1, 0, 0) m/s and at (0.6, 0.6, 0) with
(0.6, 0, 0) m/s, not turning.  Each body's free-motion states (the MSL body's own) are
on a FreeMotion joint from the World."""
import acausal as ac
from acausal.library.multibody3d import Body, FreeMotion, World

from . import MSLNames

__all__ = ["PointGravity"]


def _released(r_0, v_0):
    return FreeMotion(r_rel_a={"start": r_0, "fixed": True},
                      v_rel_a={"start": v_0, "fixed": True},
                      angles_fixed=True, w_rel_b={"fixed": True})


class PointGravity(ac.Component):
    """Two point masses in a point gravity field."""

    msl_name = "Modelica.Mechanics.MultiBody.Examples.Elementary.PointGravity"
    stop_time = 5.0
    tolerance = 1e-6
    msl_signals = MSLNames()
    msl_known_failure = (
        "reference: body2 passes the centre at 0.07 m, and the reference's body2.r_0[1] "
        "differs by 4.7e-3 of its amplitude from Kepler's orbit solved to 1e-13 "
        "(acausal at the tolerance 1e-6: 1.2e-3, at 1e-8: 2e-5)")

    world = World(gravityType="PointGravity", mu=1.0)
    body1 = Body(m=1.0, I_11=0.1, I_22=0.1, I_33=0.1, r_CM_1=0.0, r_CM_2=0.0, r_CM_3=0.0)
    body2 = Body(m=1.0, I_11=0.1, I_22=0.1, I_33=0.1, r_CM_1=0.0, r_CM_2=0.0, r_CM_3=0.0)
    freeMotion1 = _released([0.0, 0.6, 0.0], [1.0, 0.0, 0.0])
    freeMotion2 = _released([0.6, 0.6, 0.0], [0.6, 0.0, 0.0])

    def equations(self):
        return [ac.connect(self.world.frame_b, self.freeMotion1.frame_a,
                           self.freeMotion2.frame_a),
                ac.connect(self.freeMotion1.frame_b, self.body1.frame_a),
                ac.connect(self.freeMotion2.frame_b, self.body2.frame_a)]
