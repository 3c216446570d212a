"""Modelica.Mechanics.Rotational.Examples.Friction (MSL v4.0.0): a drive train with a
clutch and a brake.

A sine torque (200 N.m, 50/pi Hz) drives inertia3 until 0.5 s; a clutch (always engaged)
couples it to inertia2, a spring-damper to inertia1 through a brake that is applied at
0.5 s.  The clutch and the brake slide, stick and break away.

Not yet compared with its reference: MAP-LIB compares the clutch's and brake's ``mode``
(Integer) and ``startForward``/``startBackward`` (Boolean) besides their Real signals,
and the language has no Integer or Boolean variables yet.
"""
import acausal as ac
from acausal.library.blocks import Constant, Product, Sine, Step
from acausal.library.rotational import Brake, Clutch, Fixed, Inertia, SpringDamper, Torque

__all__ = ["Friction"]


class Friction(ac.Component):
    """J = 1, 0.05, 1 kg.m2 at 100, 90, 90 rad/s; clutch fn_max 160 N, brake 1600 N;
    spring c = 160 N.m/rad, d = 1 N.m.s/rad."""

    stop_time = 3.0
    tolerance = 1e-6

    startTime = ac.Parameter(0.5, unit="s", description="start time of step")

    torque = Torque(useSupport=True)
    inertia3 = Inertia(J=1.0, phi={"start": 0.0, "fixed": True},
                       w={"start": 100.0, "fixed": True})
    clutch = Clutch(fn_max=160.0)
    inertia2 = Inertia(J=0.05, phi={"start": 0.0, "fixed": True},
                       w={"start": 90.0, "fixed": True})
    spring = SpringDamper(c=160.0, d=1.0)
    inertia1 = Inertia(J=1.0, phi={"start": 0.0, "fixed": True},
                       w={"start": 90.0, "fixed": True})
    brake = Brake(fn_max=1600.0, useSupport=True)
    const = Constant(k=1.0)
    step = Step(startTime=ac.ref("startTime"))
    step2 = Step(height=-1.0, offset=1.0, startTime=ac.ref("startTime"))
    sine = Sine(amplitude=200.0, f=15.915494309189533)        # 50/pi Hz
    product = Product()
    fixed = Fixed()

    def equations(self):
        return [ac.connect(self.torque.flange, self.inertia3.flange_a),
                ac.connect(self.inertia3.flange_b, self.clutch.flange_a),
                ac.connect(self.clutch.flange_b, self.inertia2.flange_a),
                ac.connect(self.inertia2.flange_b, self.spring.flange_a),
                ac.connect(self.spring.flange_b, self.brake.flange_a),
                ac.connect(self.brake.flange_b, self.inertia1.flange_a),
                ac.connect(self.sine.y, self.product.u1),
                ac.connect(self.step2.y, self.product.u2),
                ac.connect(self.product.y, self.torque.tau),
                ac.connect(self.const.y, self.clutch.f_normalized),
                ac.connect(self.step.y, self.brake.f_normalized),
                ac.connect(self.torque.support, self.fixed.flange),
                ac.connect(self.brake.support, self.fixed.flange)]


if __name__ == "__main__":
    res = ac.simulate(Friction(), t_end=Friction.stop_time, rtol=Friction.tolerance)
    print(f"inertia3.w at {res.t[-1]:g} s: {res['inertia3.w'][-1]:.6g} rad/s")
