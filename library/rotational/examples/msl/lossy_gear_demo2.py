"""Modelica.Mechanics.Rotational.Examples.LossyGearDemo2 (MSL v4.0.0): a lossy gear and
bearing friction together.

LossyGearDemo1 with bearing friction (0.5 N.m at rest, rising 0.5 N.m per rad/s)
between the drive and Inertia1: two friction elements that stick and slip in turn.
While both are at rest (0.0636 .. 0.2304 s and 0.3083 .. 0.4727 s) the split of the
torque between them (gear.sa against bearingFriction.sa) is indeterminate: together
they carry tau1 + tau2/ratio (tau1 = torque1.tau, tau2 = torque2.tau; -1.03 N.m at
0.0636 s), and any bearing torque in [max(-0.5, tau1 - 2 c), min(0.5, tau1 - c/2)],
c = -tau2/ratio, keeps the gear within its limits [-flange_a.tau, 0.5 flange_a.tau]
(flange_a.tau > 0 there).  The initialization at events and the integrator take the
minimum-norm solution of the singular, consistent system
(:mod:`acausal.runtime.indeterminate`, :mod:`acausal.solvers.linalg`).  The motion
does not depend on the split: it starts forward at 0.230374 s (tau1 - 2 c = 0.5) and
backward at 0.472738 s (tau1 - c/2 = -0.5), as in the reference.
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
        "Inertia2.w 4.8e-7 x amplitude), the mode signals cannot.  While the gear holds "
        "the motion (w_a = 0) the MSL's mode equation gives Stuck whatever the split of "
        "the torque between gear and bearing; the reference has bearingFriction.mode = "
        "Forward on 0.0636 .. 0.2304 s (163 instants) and gear.mode = Backward on "
        "0.4562 .. 0.4727 s (14), from the speed its event location leaves past each "
        "stop (Inertia2.w = +5.0e-11, then -5.0e-11 rad/s).  Its split, read from its "
        "modes, holds the bearing at +0.5 N.m until the gear reaches a limit (0.0636 .. "
        "0.2304 s, 0.3083 .. 0.4562 s), at 0.0636 s against the -1.03 N.m the pair "
        "carries (any bearing torque in [-0.5, 0.5] is admissible there); "
        "startForward follows the split: here the minimum-norm one (the bearing breaks "
        "away from 0.0758 s: 153 instants), the complementarity rule (stuck while a "
        "split holds both) gives 146")
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
