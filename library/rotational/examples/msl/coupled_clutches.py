"""Modelica.Mechanics.Rotational.Examples.CoupledClutches (MSL v4.0.0): a drive train
with three dynamically coupled clutches.

A sine torque (10 N.m, 5 Hz) drives J1 (spinning at 10 rad/s); clutch1 couples it to J2,
clutch2 to J3 and clutch3 to J4.  clutch1 is pressed by a slow cosine (0.2 Hz), clutch2
from 0.4 s on, clutch3 from 0.9 s on.

Not yet compared with its reference: MAP-LIB compares the clutches' ``mode`` (Integer)
and ``startForward``/``startBackward`` (Boolean) besides their Real signals, and the
language has no Integer or Boolean variables yet.
"""
import acausal as ac
from acausal.library.blocks import Sine, Step
from acausal.library.rotational import Clutch, Fixed, Inertia, Torque

__all__ = ["CoupledClutches"]

_REST = {"phi": {"fixed": True, "start": 0.0}, "w": {"fixed": True, "start": 0.0}}


class CoupledClutches(ac.Component):
    """J = 1 kg.m2 each; clutches peak 1.1, fn_max 20 N; f = 0.2 Hz, T2 = 0.4 s,
    T3 = 0.9 s."""

    stop_time = 1.5
    tolerance = 1e-6

    f = ac.Parameter(0.2, unit="Hz", description="frequency of sine function to invoke clutch1")
    T2 = ac.Parameter(0.4, unit="s", description="time when clutch2 is invoked")
    T3 = ac.Parameter(0.9, unit="s", description="time when clutch3 is invoked")

    J1 = Inertia(J=1.0, phi={"fixed": True, "start": 0.0}, w={"start": 10.0, "fixed": True})
    torque = Torque(useSupport=True)
    clutch1 = Clutch(peak=1.1, fn_max=20.0)
    sin1 = Sine(amplitude=10.0, f=5.0)
    step1 = Step(startTime=ac.ref("T2"))
    J2 = Inertia(J=1.0, **_REST)
    clutch2 = Clutch(peak=1.1, fn_max=20.0)
    J3 = Inertia(J=1.0, **_REST)
    clutch3 = Clutch(peak=1.1, fn_max=20.0)
    J4 = Inertia(J=1.0, **_REST)
    sin2 = Sine(amplitude=1.0, f=ac.ref("f"), phase=1.570796326794897)
    step2 = Step(startTime=ac.ref("T3"))
    fixed = Fixed()

    def equations(self):
        return [ac.connect(self.torque.flange, self.J1.flange_a),
                ac.connect(self.J1.flange_b, self.clutch1.flange_a),
                ac.connect(self.clutch1.flange_b, self.J2.flange_a),
                ac.connect(self.J2.flange_b, self.clutch2.flange_a),
                ac.connect(self.clutch2.flange_b, self.J3.flange_a),
                ac.connect(self.J3.flange_b, self.clutch3.flange_a),
                ac.connect(self.clutch3.flange_b, self.J4.flange_a),
                ac.connect(self.sin1.y, self.torque.tau),
                ac.connect(self.sin2.y, self.clutch1.f_normalized),
                ac.connect(self.step1.y, self.clutch2.f_normalized),
                ac.connect(self.step2.y, self.clutch3.f_normalized),
                ac.connect(self.fixed.flange, self.torque.support)]


if __name__ == "__main__":
    res = ac.simulate(CoupledClutches(), t_end=CoupledClutches.stop_time,
                      rtol=CoupledClutches.tolerance)
    print(f"J1.w at {res.t[-1]:g} s: {res['J1.w'][-1]:.6g} rad/s")
