"""Modelica.Mechanics.MultiBody.Examples.Elementary.DoublePendulumInitTip (MSL v4.0.0):
the double pendulum of ``DoublePendulum`` started with its tip at (0.7, 0.3) m at rest,
the joint angles found from it (revolute2's guess pi/2): a FreeMotionScalarInit from
the World to the tip fixes the tip's position and velocity at the start."""
import math

import acausal as ac
from acausal.library.multibody3d import BodyBox, FreeMotionScalarInit, Revolute, World
from acausal.library.rotational import Damper

from . import MSLNames

__all__ = ["DoublePendulumInitTip"]


def _fixed(start=0.0):
    return {"signal": {"start": start, "fixed": True}}


class DoublePendulumInitTip(ac.Component):
    """Demonstrate how to initialize a double pendulum so that its tip starts at a
    predefined position."""

    msl_name = "Modelica.Mechanics.MultiBody.Examples.Elementary.DoublePendulumInitTip"
    stop_time = 5.0
    tolerance = 1e-6
    msl_signals = MSLNames()
    msl_known_failure = (
        "reference: a chaotic motion; after 4.9 s the reference differs by 4.3e-3 .. "
        "9.6e-3 of the amplitudes from the model solved at 1e-10 (acausal at the "
        "tolerance 1e-6: 0.7e-3 .. 2.6e-3); the start agrees to 8 digits")

    world = World()
    revolute1 = Revolute()
    damper = Damper(d=0.1)
    boxBody1 = BodyBox(r_1=0.5, r_2=0.0, r_3=0.0, width=0.06)
    revolute2 = Revolute(phi={"start": math.pi / 2})
    boxBody2 = BodyBox(r_1=0.5, r_2=0.0, r_3=0.0, width=0.06)
    freeMotionScalarInit = FreeMotionScalarInit(use_r=True, use_v=True,
                                                r_rel_a_1=_fixed(0.7), r_rel_a_2=_fixed(0.3),
                                                v_rel_a_1=_fixed(), v_rel_a_2=_fixed())

    def equations(self):
        return [ac.connect(self.damper.flange_b, self.revolute1.axis),
                ac.connect(self.revolute1.support, self.damper.flange_a),
                ac.connect(self.revolute1.frame_b, self.boxBody1.frame_a),
                ac.connect(self.revolute2.frame_b, self.boxBody2.frame_a),
                ac.connect(self.boxBody1.frame_b, self.revolute2.frame_a),
                ac.connect(self.world.frame_b, self.revolute1.frame_a),
                ac.connect(self.world.frame_b, self.freeMotionScalarInit.frame_a),
                ac.connect(self.freeMotionScalarInit.frame_b, self.boxBody2.frame_b)]
