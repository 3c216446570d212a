"""Modelica.Mechanics.Rotational.Examples.OneWayClutchDisengaged (MSL v4.0.0): a drive
train with a one-way clutch that is never engaged.

A sine torque (around the load torque) drives the input inertia; the output inertia,
loaded by a constant torque, is driven only through the freewheel, which holds when
the input would overtake the output (w_rel = w_out - w_in would turn negative).
"""
import acausal as ac
from acausal.library.blocks import Constant, Sine
from acausal.library.rotational import ConstantTorque, Inertia, OneWayClutch, Torque

__all__ = ["OneWayClutchDisengaged"]


class OneWayClutchDisengaged(ac.Component):
    """J = 1 kg.m2 each, input at -0.5 rad/s, output at rest; load -0.3 N.m; the sine
    has amplitude 10 N.m at 2 Hz; the clutch (peak 25, fn_max 3 N) is open."""

    msl_name = "Modelica.Mechanics.Rotational.Examples.OneWayClutchDisengaged"
    stop_time = 2.0
    tolerance = 1e-6

    inertiaIn = Inertia(J=1.0, phi={"start": 0.0, "fixed": True},
                        w={"start": -0.5, "fixed": True})
    inertiaOut = Inertia(J=1.0, phi={"start": 0.0, "fixed": True},
                         w={"start": 0.0, "fixed": True})
    oneWayClutch = OneWayClutch(peak=25.0, fn_max=3.0)
    torque = Torque()
    torqueLoad = ConstantTorque(tau_constant=-0.3)
    signalTorque = Sine(amplitude=10.0, offset=0.3, f=2.0)   # offset = -torqueLoad.tau_constant
    signalEngagement = Constant(k=0.0)

    def equations(self):
        return [ac.connect(self.torque.flange, self.inertiaIn.flange_a),
                ac.connect(self.signalTorque.y, self.torque.tau),
                ac.connect(self.inertiaIn.flange_b, self.oneWayClutch.flange_a),
                ac.connect(self.oneWayClutch.flange_b, self.inertiaOut.flange_a),
                ac.connect(self.signalEngagement.y, self.oneWayClutch.f_normalized),
                ac.connect(self.inertiaOut.flange_b, self.torqueLoad.flange)]


if __name__ == "__main__":
    res = ac.simulate(OneWayClutchDisengaged(), t_end=OneWayClutchDisengaged.stop_time,
                      rtol=OneWayClutchDisengaged.tolerance)
    print(f"inertiaIn.w at {res.t[-1]:g} s: {res['inertiaIn.w'][-1]:.6g} rad/s")
