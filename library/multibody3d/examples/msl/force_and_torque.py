"""Modelica.Mechanics.MultiBody.Examples.Elementary.ForceAndTorque (MSL v4.0.0): a steel
cylinder 1 m long on two revolute joints (about z, then y) hanging from a fixed point
0.5 m below the world's origin, pulled by a constant force (0, 1000, 0) N and twisted
by a constant torque (-100, 100, 0) N.m from a fixed point, both resolved in a frame
turned by 30 degrees about z."""
import acausal as ac
from acausal.library.blocks import Constant
from acausal.library.multibody3d import (BodyCylinder, Fixed, FixedRotation, ForceAndTorque,
                                         Revolute, World)

from . import MSLNames

__all__ = ["ForceAndTorqueExample"]


class ForceAndTorqueExample(ac.Component):
    """Demonstrate usage of the ForceAndTorque element."""

    msl_name = "Modelica.Mechanics.MultiBody.Examples.Elementary.ForceAndTorque"
    stop_time = 1.01
    tolerance = 1e-6
    msl_signals = MSLNames()

    world = World()
    body = BodyCylinder(r_1=1.0, r_2=0.0, r_3=0.0)
    fixed1 = Fixed(r_1=0.0, r_2=-0.5, r_3=0.0)
    fixedRotation = FixedRotation(n_1=0.0, n_2=0.0, n_3=1.0, angle=30.0)
    forceAndTorque = ForceAndTorque(resolveInFrame="frame_resolve")
    revolute2 = Revolute(n_1=0.0, n_2=1.0, n_3=0.0, phi={"fixed": True}, w={"fixed": True})
    revolute1 = Revolute(phi={"fixed": True}, w={"fixed": True})
    fixed2 = Fixed(r_1=1.5, r_2=0.25, r_3=0.0)

    def build(self):
        self.torque = [Constant(k=k) for k in (-100.0, 100.0, 0.0)]
        self.force = [Constant(k=k) for k in (0.0, 1000.0, 0.0)]

    def equations(self):
        return [ac.connect(self.revolute2.frame_b, self.body.frame_a),
                ac.connect(self.forceAndTorque.frame_b, self.body.frame_b),
                ac.connect(self.fixed1.frame_b, self.revolute1.frame_a),
                ac.connect(self.revolute1.frame_b, self.revolute2.frame_a),
                ac.connect(self.fixed2.frame_b, self.forceAndTorque.frame_a),
                ac.connect(self.fixedRotation.frame_a, self.fixed1.frame_b),
                ac.connect(self.forceAndTorque.frame_resolve, self.fixedRotation.frame_b),
                *(ac.connect(f.y, u) for f, u in zip(self.force, self.forceAndTorque.force)),
                *(ac.connect(t.y, u) for t, u in zip(self.torque, self.forceAndTorque.torque))]
