"""Modelica.Mechanics.Rotational.Examples.LossyGearDemo2 (MSL v4.0.0): a lossy gear and
bearing friction together.

LossyGearDemo1 with bearing friction (0.5 N.m at rest, rising 0.5 N.m per rad/s)
between the drive and Inertia1: two friction elements that stick and slip in turn.
From t = 0.0636 s both are stuck on one motion, so the split of the torque between them
(gear.sa against bearingFriction.sa) is indeterminate: the initialization at events and
the integrator take the minimum-norm solution of the singular, consistent system
(:mod:`acausal.runtime.indeterminate`, :mod:`acausal.solvers.linalg`).
"""
import acausal as ac
from acausal.library.blocks import Ramp, Sine
from acausal.library.rotational import BearingFriction, Fixed, Inertia, LossyGear, Torque

__all__ = ["LossyGearDemo2"]


class LossyGearDemo2(ac.Component):
    """J1 = 1, J2 = 1.5 kg.m2 (at rest); ratio 2, lossTable [0, 0.5, 0.5, 0, 0];
    bearing tau_pos [0, 0.5; 1, 1]."""

    msl_name = "Modelica.Mechanics.Rotational.Examples.LossyGearDemo2"
    stop_time = 0.5
    msl_known_failure = (
        "indeterminate (modes): the motion matches the reference (Inertia2.phi 2.1e-6, "
        "Inertia2.w 4.8e-7 x amplitude), but while the gear and the bearing are both "
        "stuck on one motion the split of the torque between them is not unique, and "
        "the mode signals follow the split: Dymola's has the bearing slide forward "
        "(mode 1) from the reversal at t = 0.0636 s, the minimum-norm split taken here "
        "only once its share reaches 0.5 N.m at t = 0.0758 s (bearingFriction.mode, 10 "
        "instants; likewise gear.mode on 0.456 .. 0.473 s, 14 instants)")
    tolerance = 1e-6

    PowerLoss = ac.Variable(unit="W", description="power lost in the gear")

    gear = LossyGear(ratio=2.0, lossTable=[[0, 0.5, 0.5, 0, 0]], useSupport=True)
    Inertia1 = Inertia(J=1.0)
    Inertia2 = Inertia(J=1.5, phi={"fixed": True, "start": 0.0, "nominal": 1e-4},
                       w={"fixed": True, "start": 0.0, "nominal": 0.001})
    torque1 = Torque(useSupport=True)
    torque2 = Torque(useSupport=True)
    DriveSine = Sine(amplitude=10.0, f=1.0)
    load = Ramp(height=5.0, duration=2.0, offset=-10.0)
    bearingFriction = BearingFriction(tau_pos=[[0, 0.5], [1, 1]], useSupport=True)
    fixed = Fixed()

    def equations(self):
        g = self.gear
        return [ac.Eq(self.PowerLoss, g.flange_a.tau * ac.der(g.flange_a.phi)
                      + g.flange_b.tau * ac.der(g.flange_b.phi)),
                ac.connect(self.torque2.flange, self.Inertia2.flange_b),
                ac.connect(self.Inertia2.flange_a, self.gear.flange_b),
                ac.connect(self.gear.flange_a, self.Inertia1.flange_b),
                ac.connect(self.Inertia1.flange_a, self.bearingFriction.flange_b),
                ac.connect(self.bearingFriction.flange_a, self.torque1.flange),
                ac.connect(self.DriveSine.y, self.torque1.tau),
                ac.connect(self.load.y, self.torque2.tau),
                ac.connect(self.gear.support, self.fixed.flange),
                ac.connect(self.fixed.flange, self.torque2.support),
                ac.connect(self.fixed.flange, self.bearingFriction.support),
                ac.connect(self.torque1.support, self.fixed.flange)]


if __name__ == "__main__":
    res = ac.simulate(LossyGearDemo2(), t_end=LossyGearDemo2.stop_time,
                      rtol=LossyGearDemo2.tolerance)
    print(f"Inertia2.w at {res.t[-1]:g} s: {res['Inertia2.w'][-1]:.6g} rad/s")
