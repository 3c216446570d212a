"""Modelica.Mechanics.Rotational.Examples.SimpleGearShift (MSL v4.0.0): a two-speed gear
shift with a planetary gear, a clutch and a brake.

The engine drives the sun of a planetary gear whose carrier drives the load (a fan-like
torque quadratic in speed).  First the brake holds the ring: a reduction; from 2 s a
ramp closes the clutch between sun and ring and opens the brake (f = 1 - clutch), so
the planetary turns as a block: direct drive.

Not yet compared with its reference: MAP-LIB compares the clutch's and brake's ``mode``
(Integer) and ``startForward``/``startBackward`` (Boolean) besides their Real signals,
and the language has no Integer or Boolean variables yet.
"""
import acausal as ac
from acausal.library.blocks import Constant, Feedback, Ramp
from acausal.library.rotational import (Brake, Clutch, IdealPlanetary, Inertia,
                                        QuadraticSpeedDependentTorque, TorqueStep)

__all__ = ["SimpleGearShift"]


class SimpleGearShift(ac.Component):
    """Engine 1 kg.m2 with a 20 N.m step at 0.5 s; planetary ratio 75/50; load
    10 kg.m2, -20 N.m at 100 rpm; clutch and brake cgeo 2 m, fn_max 100 N."""

    stop_time = 5.0
    tolerance = 1e-6

    torqueStep = TorqueStep(offsetTorque=0.0, startTime=0.5, stepTorque=20.0)
    engine = Inertia(J=1.0)
    idealPlanetary = IdealPlanetary(ratio=75 / 50)
    load = Inertia(J=10.0, phi={"fixed": True, "start": 0.0}, w={"fixed": True, "start": 0.0})
    quadraticSpeedDependentTorque = QuadraticSpeedDependentTorque(w_nominal=10.471975511966,
                                                                  tau_nominal=-20.0)
    clutch = Clutch(cgeo=2.0, fn_max=100.0, phi_rel={"fixed": True}, w_rel={"fixed": True})
    brake = Brake(cgeo=2.0, fn_max=100.0)
    feedback = Feedback()
    const1 = Constant(k=1.0)
    ramp = Ramp(height=1.0, offset=0.0, startTime=2.0, duration=0.1)

    def equations(self):
        return [ac.connect(self.torqueStep.flange, self.engine.flange_a),
                ac.connect(self.quadraticSpeedDependentTorque.flange, self.load.flange_b),
                ac.connect(self.feedback.y, self.brake.f_normalized),
                ac.connect(self.engine.flange_b, self.idealPlanetary.sun),
                ac.connect(self.idealPlanetary.sun, self.clutch.flange_a),
                ac.connect(self.idealPlanetary.ring, self.clutch.flange_b),
                ac.connect(self.idealPlanetary.ring, self.brake.flange_a),
                ac.connect(self.idealPlanetary.carrier, self.load.flange_a),
                ac.connect(self.const1.y, self.feedback.u1),
                ac.connect(self.feedback.u2, self.clutch.f_normalized),
                ac.connect(self.ramp.y, self.clutch.f_normalized)]


if __name__ == "__main__":
    res = ac.simulate(SimpleGearShift(), t_end=SimpleGearShift.stop_time,
                      rtol=SimpleGearShift.tolerance)
    print(f"load.w at {res.t[-1]:g} s: {res['load.w'][-1]:.6g} rad/s")
