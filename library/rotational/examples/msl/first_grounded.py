"""Modelica.Mechanics.Rotational.Examples.FirstGrounded (MSL v4.0.0): the drive train of
``First`` with its torque source and gear grounded (``useSupport=false``).

A sine torque drives the motor inertia; an ideal gear (ratio 10) turns a second
inertia, which drives the load inertia through a spring, with a damper between the
gear's output and the housing.
"""
import acausal as ac
from acausal.library.blocks import Sine
from acausal.library.rotational import Damper, Fixed, IdealGear, Inertia, Spring, Torque

__all__ = ["FirstGrounded"]


class FirstGrounded(ac.Component):
    """amplitude = 10 N.m, f = 5 Hz, Jmotor = 0.1, Jload = 2 kg.m2, ratio = 10,
    damping = 10 N.m.s/rad."""

    msl_name = "Modelica.Mechanics.Rotational.Examples.FirstGrounded"
    stop_time = 1.0
    tolerance = 1e-6

    amplitude = ac.Parameter(10.0, unit="N.m", description="amplitude of driving torque")
    f = ac.Parameter(5.0, unit="Hz", description="frequency of driving torque")
    Jmotor = ac.Parameter(0.1, unit="kg.m2", min=0, description="motor inertia")
    Jload = ac.Parameter(2.0, unit="kg.m2", min=0, description="load inertia")
    ratio = ac.Parameter(10.0, description="gear ratio")
    damping = ac.Parameter(10.0, unit="N.m.s/rad", description="damping in bearing of gear")

    fixed = Fixed()
    torque = Torque(useSupport=False)
    inertia1 = Inertia(J=ac.ref("Jmotor"))
    idealGear = IdealGear(ratio=ac.ref("ratio"), useSupport=False)
    inertia2 = Inertia(J=2.0, phi={"start": 0.0, "fixed": True},
                       w={"start": 0.0, "fixed": True})
    spring = Spring(c=1.0e4, phi_rel={"fixed": True})
    inertia3 = Inertia(J=ac.ref("Jload"), w={"start": 0.0, "fixed": True})
    damper = Damper(d=ac.ref("damping"))
    sine = Sine(amplitude=ac.ref("amplitude"), f=ac.ref("f"))

    def equations(self):
        return [ac.connect(self.inertia1.flange_b, self.idealGear.flange_a),
                ac.connect(self.idealGear.flange_b, self.inertia2.flange_a),
                ac.connect(self.inertia2.flange_b, self.spring.flange_a),
                ac.connect(self.spring.flange_b, self.inertia3.flange_a),
                ac.connect(self.damper.flange_a, self.inertia2.flange_b),
                ac.connect(self.damper.flange_b, self.fixed.flange),
                ac.connect(self.sine.y, self.torque.tau),
                ac.connect(self.torque.flange, self.inertia1.flange_a)]


if __name__ == "__main__":
    res = ac.simulate(FirstGrounded(), t_end=FirstGrounded.stop_time,
                      rtol=FirstGrounded.tolerance)
    print(f"inertia3.w at {res.t[-1]:g} s: {res['inertia3.w'][-1]:.6g} rad/s")
