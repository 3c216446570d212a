"""Modelica.Mechanics.MultiBody.Examples.Elementary.Pendulum (MSL v4.0.0): a body of
1 kg, its centre of mass 0.5 m out, on a revolute joint about z, damped by a rotational
damper of 0.1 N.m.s/rad between the joint's axis and its support, released at rest."""
import acausal as ac
from acausal.library.multibody3d import Body, Revolute, World
from acausal.library.rotational import Damper

from . import MSLNames

__all__ = ["Pendulum"]


class Pendulum(ac.Component):
    """Simple pendulum with one revolute joint and one body."""

    msl_name = "Modelica.Mechanics.MultiBody.Examples.Elementary.Pendulum"
    stop_time = 5.0
    tolerance = 1e-6
    msl_signals = MSLNames()

    world = World(gravityType="UniformGravity")
    rev = Revolute(n_1=0.0, n_2=0.0, n_3=1.0, phi={"fixed": True}, w={"fixed": True})
    damper = Damper(d=0.1)
    body = Body(m=1.0, r_CM_1=0.5, r_CM_2=0.0, r_CM_3=0.0)

    def equations(self):
        return [ac.connect(self.world.frame_b, self.rev.frame_a),
                ac.connect(self.damper.flange_b, self.rev.axis),
                ac.connect(self.rev.support, self.damper.flange_a),
                ac.connect(self.body.frame_a, self.rev.frame_b)]
