"""Modelica.Mechanics.Rotational.Examples.HeatLosses (MSL v4.0.0): the losses of a drive
train leave through heat ports.

A 20 N.m, 5 Hz sine torque drives a chain of inertias through a damper to the housing, a
spring-damper, an elastic backlash, bearing friction, a spring, a lossy gear, a clutch, a
one-way clutch and a brake (the last three pressed by a slow sine, negative half of the
time: free then); every dissipating element's heat port meets the others at a
convection element (Gc = 20 W/K) to an ambient at 25 degC, whose heat flow is the total
loss.

MAP-LIB's reference result of this example is not in the copy this library is checked
against (v4.0.0: the CSV is absent; v3.2.3, the same model, keeps only a Git LFS pointer
to its result file), so it is not among the examples under ``examples.msl``; its test
(``tests/library/test_mech_heat_ports.py``) checks it against the energy balance of the
whole train.  At t0 the lossy gear, the clutch, the one-way clutch and the brake are all
stuck on motions that they over-determine together (four lock constraints on three
inertias): the split of the torques between them is indeterminate, and the
initialization and the integrator take the minimum-norm solution of the consistent
singular system (:mod:`acausal.runtime.indeterminate`), as in LossyGearDemo2.
"""
import acausal as ac
from acausal.library.blocks import Constant, Sine
from acausal.library.rotational import (BearingFriction, Brake, Clutch, Damper,
                                        ElastoBacklash, Fixed, Inertia, LossyGear,
                                        OneWayClutch, Spring, SpringDamper, Torque)
from acausal.library.thermal import Convection
from acausal.library.thermal.celsius import FixedTemperature

__all__ = ["HeatLosses"]

_AT_REST = {"phi": {"fixed": True, "start": 0.0}, "w": {"fixed": True, "start": 0.0}}


class HeatLosses(ac.Component):
    """Inertias of 2 kg.m2; damper d = 10; springDamper c = 1e4, d = 20; elastoBacklash
    c = 1e5, d = 100, b = 1 mrad; lossyGear ratio 2 with efficiencies 0.8 -> 0.7 and
    bearing friction 1 -> 2 N.m over 0..1 rad/s; clutch fn_max = 10 N, oneWayClutch 1 N,
    brake 2 N."""

    stop_time = 1.0
    tolerance = 1e-6

    sine = Sine(f=5.0, amplitude=20.0)
    torque = Torque()
    inertia1 = Inertia(J=2.0, **_AT_REST)
    damper = Damper(useHeatPort=True, d=10.0)
    fixed = Fixed()
    convection = Convection()
    TAmbient = FixedTemperature(T=25.0)
    const = Constant(k=20.0)
    springDamper = SpringDamper(c=1e4, d=20.0, useHeatPort=True)
    inertia2 = Inertia(J=2.0, **_AT_REST)
    elastoBacklash = ElastoBacklash(c=1e5, d=100.0, useHeatPort=True, b=0.001)
    inertia3 = Inertia(J=2.0, **_AT_REST)
    bearingFriction = BearingFriction(useHeatPort=True)
    spring3 = Spring(c=1e4)
    inertia4 = Inertia(J=2.0, **_AT_REST)
    lossyGear = LossyGear(ratio=2.0, lossTable=[[0, 0.8, 0.8, 1, 1], [1, 0.7, 0.7, 2, 2]],
                          useHeatPort=True)
    clutch = Clutch(useHeatPort=True, fn_max=10.0, phi_rel={"fixed": True},
                    w_rel={"fixed": True})
    inertia5 = Inertia(J=2.0)
    sine2 = Sine(f=0.2, amplitude=1.0)
    inertia6 = Inertia(J=2.0)
    oneWayClutch = OneWayClutch(phi_rel={"fixed": True}, w_rel={"fixed": True}, fn_max=1.0,
                                useHeatPort=True)
    brake = Brake(fn_max=2.0, useHeatPort=True)

    def equations(self):
        solid = self.convection.solid
        return [ac.connect(self.sine.y, self.torque.tau),
                ac.connect(self.torque.flange, self.inertia1.flange_a),
                ac.connect(self.inertia1.flange_b, self.damper.flange_b),
                ac.connect(self.damper.flange_a, self.fixed.flange),
                ac.connect(self.inertia1.flange_b, self.springDamper.flange_a),
                ac.connect(self.springDamper.flange_b, self.inertia2.flange_a),
                ac.connect(self.elastoBacklash.flange_a, self.inertia2.flange_b),
                ac.connect(self.elastoBacklash.flange_b, self.inertia3.flange_a),
                ac.connect(self.inertia3.flange_b, self.bearingFriction.flange_a),
                ac.connect(self.bearingFriction.flange_b, self.spring3.flange_a),
                ac.connect(self.spring3.flange_b, self.inertia4.flange_a),
                ac.connect(self.inertia4.flange_b, self.lossyGear.flange_a),
                ac.connect(self.lossyGear.flange_b, self.clutch.flange_a),
                ac.connect(self.clutch.flange_b, self.inertia5.flange_a),
                ac.connect(self.inertia5.flange_b, self.oneWayClutch.flange_a),
                ac.connect(self.oneWayClutch.flange_b, self.inertia6.flange_a),
                ac.connect(self.inertia6.flange_b, self.brake.flange_a),
                ac.connect(self.sine2.y, self.brake.f_normalized),
                ac.connect(self.sine2.y, self.clutch.f_normalized),
                ac.connect(self.sine2.y, self.oneWayClutch.f_normalized),
                ac.connect(self.const.y, self.convection.Gc),
                ac.connect(self.TAmbient.port, self.convection.fluid),
                ac.connect(self.damper.heatPort, solid),
                ac.connect(self.springDamper.heatPort, solid),
                ac.connect(self.elastoBacklash.heatPort, solid),
                ac.connect(self.bearingFriction.heatPort, solid),
                ac.connect(self.lossyGear.heatPort, solid),
                ac.connect(self.clutch.heatPort, solid),
                ac.connect(self.oneWayClutch.heatPort, solid),
                ac.connect(self.brake.heatPort, solid)]


if __name__ == "__main__":
    res = ac.simulate(HeatLosses(), t_end=HeatLosses.stop_time, rtol=HeatLosses.tolerance)
    print(f"convection.Q_flow at {res.t[-1]:g} s: {res['convection.Q_flow'][-1]:.6g} W")
