"""Modelica.Mechanics.Rotational.Examples.LossyGearDemo1 (MSL v4.0.0): gear efficiency
may lead to stuck motion.

A sine torque (10 N.m, 1 Hz) drives Inertia1 against a load torque ramped from -10 to
-5 N.m on Inertia2, through a lossy gear (ratio 2, mesh efficiency 0.5 both ways, no
bearing friction).  When neither side can drive the other through the losses, the
gear locks.
"""
import acausal as ac
from acausal.library.blocks import Ramp, Sine
from acausal.library.rotational import Fixed, Inertia, LossyGear, Torque

__all__ = ["LossyGearDemo1"]


class LossyGearDemo1(ac.Component):
    """J1 = 1, J2 = 1.5 kg.m2 (at rest); ratio 2, lossTable [0, 0.5, 0.5, 0, 0]."""

    msl_name = "Modelica.Mechanics.Rotational.Examples.LossyGearDemo1"
    stop_time = 0.5
    tolerance = 1e-6

    PowerLoss = ac.Variable(unit="W", description="power lost in the gear")

    gear = LossyGear(ratio=2.0, lossTable=[[0, 0.5, 0.5, 0, 0]], useSupport=True)
    Inertia1 = Inertia(J=1.0)
    Inertia2 = Inertia(J=1.5, phi={"fixed": True, "start": 0.0, "nominal": 0.001},
                       w={"fixed": True, "start": 0.0, "nominal": 0.01})
    torque1 = Torque(useSupport=True)
    torque2 = Torque(useSupport=True)
    DriveSine = Sine(amplitude=10.0, f=1.0)
    load = Ramp(height=5.0, duration=2.0, offset=-10.0)
    fixed = Fixed()

    def equations(self):
        g = self.gear
        return [ac.Eq(self.PowerLoss, g.flange_a.tau * ac.der(g.flange_a.phi)
                      + g.flange_b.tau * ac.der(g.flange_b.phi)),
                ac.connect(self.Inertia1.flange_b, self.gear.flange_a),
                ac.connect(self.gear.flange_b, self.Inertia2.flange_a),
                ac.connect(self.torque1.flange, self.Inertia1.flange_a),
                ac.connect(self.torque2.flange, self.Inertia2.flange_b),
                ac.connect(self.DriveSine.y, self.torque1.tau),
                ac.connect(self.load.y, self.torque2.tau),
                ac.connect(self.fixed.flange, self.gear.support),
                ac.connect(self.fixed.flange, self.torque1.support),
                ac.connect(self.fixed.flange, self.torque2.support)]


if __name__ == "__main__":
    res = ac.simulate(LossyGearDemo1(), t_end=LossyGearDemo1.stop_time,
                      rtol=LossyGearDemo1.tolerance)
    print(f"Inertia2.w at {res.t[-1]:g} s: {res['Inertia2.w'][-1]:.6g} rad/s")
