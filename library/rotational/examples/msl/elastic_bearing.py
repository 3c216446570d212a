"""Modelica.Mechanics.Rotational.Examples.ElasticBearing (MSL v4.0.0): a gearbox on an
elastic mount.

A ramped torque drives the shaft against the ground; an ideal gear (ratio 3) turns the
load through a spring.  The gear's housing is an inertia held to the ground by a stiff
spring-damper (the bearing), through a multi-sensor that measures the bearing torque.
"""
import acausal as ac
from acausal.library.blocks import Ramp
from acausal.library.rotational import (Fixed, IdealGear, Inertia, MultiSensor, Spring,
                                        SpringDamper, Torque)

__all__ = ["ElasticBearing"]


class ElasticBearing(ac.Component):
    """Shaft 1, load 50, housing 5 kg.m2; spring 1e3 N.m/rad; bearing c = 1e5 N.m/rad,
    d = 5 N.m.s/rad; the torque ramps to 100 N.m in 5 s."""

    msl_name = "Modelica.Mechanics.Rotational.Examples.ElasticBearing"
    stop_time = 10.0
    tolerance = 1e-6

    shaft = Inertia(J=1.0, phi={"start": 0.0, "fixed": True},
                    w={"start": 0.0, "fixed": True})
    load = Inertia(J=50.0, w={"start": 0.0, "fixed": True})
    spring = Spring(c=1e3, phi_rel={"fixed": True})
    fixed = Fixed()
    # stateSelect="prefer" is the MSL's default: the bearing's twist and twist rate are
    # states, w_rel integrated on its own scale (nominal 1e-4)
    springDamper = SpringDamper(c=1e5, d=5.0, stateSelect="prefer", phi_rel={"fixed": True},
                                w_rel={"fixed": True, "nominal": 1e-4})
    torque = Torque(useSupport=True)
    ramp = Ramp(duration=5.0, height=100.0)
    idealGear = IdealGear(ratio=3.0, useSupport=True)
    housing = Inertia(J=5.0)
    multiSensor = MultiSensor()

    def equations(self):
        return [ac.connect(self.torque.flange, self.shaft.flange_a),
                ac.connect(self.spring.flange_b, self.load.flange_a),
                ac.connect(self.springDamper.flange_a, self.fixed.flange),
                ac.connect(self.shaft.flange_b, self.idealGear.flange_a),
                ac.connect(self.idealGear.flange_b, self.spring.flange_a),
                ac.connect(self.idealGear.support, self.housing.flange_b),
                ac.connect(self.ramp.y, self.torque.tau),
                ac.connect(self.fixed.flange, self.torque.support),
                ac.connect(self.housing.flange_a, self.multiSensor.flange_b),
                ac.connect(self.multiSensor.flange_a, self.springDamper.flange_b)]


if __name__ == "__main__":
    res = ac.simulate(ElasticBearing(), t_end=ElasticBearing.stop_time,
                      rtol=ElasticBearing.tolerance)
    print(f"load.w at {res.t[-1]:g} s: {res['load.w'][-1]:.6g} rad/s")
