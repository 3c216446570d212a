"""Modelica.Mechanics.MultiBody.Examples.Elementary.InitSpringConstant (MSL v4.0.0): a
pendulum (a 1 m BodyShape of 1 kg, its centre of mass at 0.5 m) on a damped revolute
joint about z, held by a spring (unstretched 0.1 m) from the fixed point (1, 0.2, 0) m to
its tip.  The spring constant c is found by initialization (``fixed=False``, start
100 N/m) such that the pendulum rests at phi = 0: phi, w and a are fixed at 0, three
conditions for two states and c.  At rest the spring, 0.2 m long and stretched by
0.1 m, carries the body's weight at its tip: c 0.1 m 1 m = 1 kg g 0.5 m, so
c = 5 g = 49.03325 N/m."""
import acausal as ac
from acausal.library.multibody3d import BodyShape, Fixed, Revolute, Spring, World
from acausal.library.rotational import Damper

from . import MSLNames

__all__ = ["InitSpringConstant"]


class InitSpringConstant(ac.Component):
    """Determine spring constant such that system is in steady state at given position."""

    msl_name = "Modelica.Mechanics.MultiBody.Examples.Elementary.InitSpringConstant"
    stop_time = 1.01
    tolerance = 1e-6
    msl_signals = MSLNames()

    world = World()
    rev = Revolute(n_1=0.0, n_2=0.0, n_3=1.0, phi={"fixed": True}, w={"fixed": True},
                   a={"fixed": True})
    damper = Damper(d=0.1)
    body = BodyShape(r_1=1.0, r_2=0.0, r_3=0.0, r_CM_1=0.5, r_CM_2=0.0, r_CM_3=0.0, m=1.0)
    fixed = Fixed(r_1=1.0, r_2=0.2, r_3=0.0)
    spring = Spring(s_unstretched=0.1, c={"fixed": False, "start": 100.0})

    def equations(self):
        return [ac.connect(self.world.frame_b, self.rev.frame_a),
                ac.connect(self.damper.flange_b, self.rev.axis),
                ac.connect(self.rev.support, self.damper.flange_a),
                ac.connect(self.rev.frame_b, self.body.frame_a),
                ac.connect(self.fixed.frame_b, self.spring.frame_a),
                ac.connect(self.body.frame_b, self.spring.frame_b)]
