"""Modelica.Mechanics.MultiBody.Examples.Elementary.DoublePendulum (MSL v4.0.0): two
steel boxes 0.5 m long and 0.06 m wide on revolute joints about z, the first joint
damped (0.1 N.m.s/rad), released at rest from the horizontal."""
import acausal as ac
from acausal.library.multibody3d import BodyBox, Revolute, World
from acausal.library.rotational import Damper

from . import MSLNames

__all__ = ["DoublePendulum"]


class DoublePendulum(ac.Component):
    """Simple double pendulum with two revolute joints and two bodies."""

    msl_name = "Modelica.Mechanics.MultiBody.Examples.Elementary.DoublePendulum"
    stop_time = 3.0
    tolerance = 1e-6
    msl_signals = MSLNames()

    world = World()
    revolute1 = Revolute(phi={"fixed": True}, w={"fixed": True})
    damper = Damper(d=0.1)
    boxBody1 = BodyBox(r_1=0.5, r_2=0.0, r_3=0.0, width=0.06)
    revolute2 = Revolute(phi={"fixed": True}, w={"fixed": True})
    boxBody2 = BodyBox(r_1=0.5, r_2=0.0, r_3=0.0, width=0.06)

    def equations(self):
        return [ac.connect(self.damper.flange_b, self.revolute1.axis),
                ac.connect(self.revolute1.support, self.damper.flange_a),
                ac.connect(self.revolute1.frame_b, self.boxBody1.frame_a),
                ac.connect(self.revolute2.frame_b, self.boxBody2.frame_a),
                ac.connect(self.boxBody1.frame_b, self.revolute2.frame_a),
                ac.connect(self.world.frame_b, self.revolute1.frame_a)]
