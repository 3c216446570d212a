"""Modelica.Mechanics.Rotational.Examples.OneWayClutch (MSL v4.0.0): a drive train with
an actively engaged one-way clutch.

A sine torque drives the input inertia; the output inertia is driven through a one-way
clutch: its freewheel holds whenever the input would overtake the output, and a pulse
signal presses its clutch for half of every 1.3 s from 0.3 s on.
"""
import acausal as ac
from acausal.library.blocks import Pulse, Sine
from acausal.library import rotational as rot
from acausal.library.rotational import Inertia, Torque

__all__ = ["OneWayClutch"]


class OneWayClutch(ac.Component):
    """J = 1 kg.m2 each, input at -0.5 rad/s, output at rest; the sine has amplitude
    10 N.m at 3 Hz; the clutch (peak 25, fn_max 3 N) engages for 0.65 s every 1.3 s."""

    msl_name = "Modelica.Mechanics.Rotational.Examples.OneWayClutch"
    stop_time = 2.0
    tolerance = 1e-6

    inertiaIn = Inertia(J=1.0, phi={"start": 0.0, "fixed": True},
                        w={"start": -0.5, "fixed": True})
    inertiaOut = Inertia(J=1.0, phi={"start": 0.0, "fixed": True},
                         w={"start": 0.0, "fixed": True})
    oneWayClutch = rot.OneWayClutch(peak=25.0, fn_max=3.0)
    torque = Torque()
    signalTorque = Sine(amplitude=10.0, f=3.0)
    signalEngagement = Pulse(amplitude=1.0, width=50.0, period=1.3, startTime=0.3)

    def equations(self):
        return [ac.connect(self.torque.flange, self.inertiaIn.flange_a),
                ac.connect(self.signalTorque.y, self.torque.tau),
                ac.connect(self.inertiaIn.flange_b, self.oneWayClutch.flange_a),
                ac.connect(self.oneWayClutch.flange_b, self.inertiaOut.flange_a),
                ac.connect(self.signalEngagement.y, self.oneWayClutch.f_normalized)]


if __name__ == "__main__":
    res = ac.simulate(OneWayClutch(), t_end=OneWayClutch.stop_time,
                      rtol=OneWayClutch.tolerance)
    print(f"inertiaOut.w at {res.t[-1]:g} s: {res['inertiaOut.w'][-1]:.6g} rad/s")
