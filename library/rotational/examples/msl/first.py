"""Modelica.Mechanics.Rotational.Examples.First (MSL v4.0.0): a simple drive train.

A sine torque drives the motor inertia against the housing; an ideal gear (ratio 10,
also mounted in the housing) turns a second inertia, which drives the load inertia
through a spring, with a damper between the gear's output and the housing.
"""
import acausal as ac
from acausal.library.blocks import Sine
from acausal.library.rotational import (Damper, Fixed, IdealGear, Inertia, Spring,
                                        Torque)

__all__ = ["First"]


class First(ac.Component):
    """amplitude = 10 N.m, f = 5 Hz, Jmotor = 0.1, Jload = 2 kg.m2, ratio = 10,
    damping = 10 N.m.s/rad."""

    msl_name = "Modelica.Mechanics.Rotational.Examples.First"
    stop_time = 1.0
    tolerance = 1e-6

    fixed = Fixed()
    torque = Torque(useSupport=True)
    inertia1 = Inertia(J=0.1)
    idealGear = IdealGear(ratio=10.0, useSupport=True)
    inertia2 = Inertia(J=2.0, phi={"start": 0.0, "fixed": True},
                       w={"start": 0.0, "fixed": True})
    spring = Spring(c=1.0e4, phi_rel={"fixed": True})
    inertia3 = Inertia(J=2.0, w={"start": 0.0, "fixed": True})
    damper = Damper(d=10.0)
    sine = Sine(amplitude=10.0, f=5.0)

    def equations(self):
        return [ac.connect(self.inertia1.flange_b, self.idealGear.flange_a),
                ac.connect(self.idealGear.flange_b, self.inertia2.flange_a),
                ac.connect(self.inertia2.flange_b, self.spring.flange_a),
                ac.connect(self.spring.flange_b, self.inertia3.flange_a),
                ac.connect(self.damper.flange_a, self.inertia2.flange_b),
                ac.connect(self.damper.flange_b, self.fixed.flange),
                ac.connect(self.sine.y, self.torque.tau),
                ac.connect(self.torque.support, self.fixed.flange),
                ac.connect(self.idealGear.support, self.fixed.flange),
                ac.connect(self.torque.flange, self.inertia1.flange_a)]


if __name__ == "__main__":
    res = ac.simulate(First(), t_end=First.stop_time, rtol=First.tolerance)
    print(f"inertia3.w at {res.t[-1]:g} s: {res['inertia3.w'][-1]:.6g} rad/s")
