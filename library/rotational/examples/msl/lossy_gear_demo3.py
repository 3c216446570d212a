"""Modelica.Mechanics.Rotational.Examples.LossyGearDemo3 (MSL v4.0.0): the case where the
driving side is not obvious (it made the earlier LossyGear fail).

Two small inertias (1 g.m2) spinning at 10 rad/s on either side of a lossy gear
(ratio 1, efficiency 0.25 both ways, bearing friction 0.625 and 2.5 N.m) run down; at
0.5 s a torque of 1 N.m acts on the output side.

Not yet compared with its reference: MAP-LIB compares the gear's ``mode`` (an Integer)
besides its Real signals, and the language has no Integer variables yet.
"""
import acausal as ac
from acausal.library.blocks import Step
from acausal.library.rotational import Inertia, LossyGear, Torque

__all__ = ["LossyGearDemo3"]


class LossyGearDemo3(ac.Component):
    """J = 0.001 kg.m2 each at 10 rad/s; ratio 1, lossTable [0, 0.25, 0.25, 0.625, 2.5]."""

    stop_time = 1.0
    tolerance = 1e-6

    gear = LossyGear(ratio=1.0, lossTable=[[0, 0.25, 0.25, 0.625, 2.5]], useSupport=False)
    Inertia1 = Inertia(w={"start": 10.0}, J=0.001)
    torque1 = Torque(useSupport=False)
    torque2 = Torque(useSupport=False)
    step = Step(height=0.0)
    step1 = Step(startTime=0.5, height=1.0, offset=0.0)
    Inertia2 = Inertia(J=0.001, phi={"fixed": True, "start": 0.0},
                       w={"start": 10.0, "fixed": True})

    def equations(self):
        return [ac.connect(self.Inertia1.flange_b, self.gear.flange_a),
                ac.connect(self.torque1.flange, self.Inertia1.flange_a),
                ac.connect(self.step.y, self.torque1.tau),
                ac.connect(self.gear.flange_b, self.Inertia2.flange_a),
                ac.connect(self.Inertia2.flange_b, self.torque2.flange),
                ac.connect(self.step1.y, self.torque2.tau)]


if __name__ == "__main__":
    res = ac.simulate(LossyGearDemo3(), t_end=LossyGearDemo3.stop_time,
                      rtol=LossyGearDemo3.tolerance)
    print(f"Inertia2.w at {res.t[-1]:g} s: {res['Inertia2.w'][-1]:.6g} rad/s")
