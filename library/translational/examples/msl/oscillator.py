"""Modelica.Mechanics.Translational.Examples.Oscillator (MSL v4.0.0): a mass on a stiff
spring driven by a sine force at its natural frequency, undamped and damped.

w0 = sqrt(c/m) = 100 rad/s = 15.9155 Hz: the undamped oscillator resonates, its
amplitude growing linearly; the damped one settles.
"""
import acausal as ac
from acausal.library.blocks import Sine
from acausal.library.translational import Damper, Fixed, Force, Mass, Spring

__all__ = ["Oscillator"]

_START = {"s": {"start": -0.5, "fixed": True}, "v": {"start": 0.0, "fixed": True}}


class Oscillator(ac.Component):
    """m = 1 kg, L = 1 m, c = 1e4 N/m, s_rel0 = 1 m, d = 10 N.s/m, force 1 N at
    15.9155 Hz."""

    msl_name = "Modelica.Mechanics.Translational.Examples.Oscillator"
    stop_time = 1.0
    tolerance = 1e-6

    mass1 = Mass(L=1.0, m=1.0, **_START)
    spring1 = Spring(s_rel0=1.0, c=10000.0)
    fixed1 = Fixed(s0=1.0)
    force1 = Force()
    sine1 = Sine(f=15.9155)
    mass2 = Mass(L=1.0, m=1.0, **_START)
    spring2 = Spring(s_rel0=1.0, c=10000.0)
    fixed2 = Fixed(s0=1.0)
    force2 = Force()
    sine2 = Sine(f=15.9155)
    damper1 = Damper(d=10.0)

    def equations(self):
        return [ac.connect(self.mass1.flange_b, self.spring1.flange_a),
                ac.connect(self.spring2.flange_a, self.damper1.flange_a),
                ac.connect(self.mass2.flange_b, self.spring2.flange_a),
                ac.connect(self.damper1.flange_b, self.spring2.flange_b),
                ac.connect(self.sine1.y, self.force1.f),
                ac.connect(self.sine2.y, self.force2.f),
                ac.connect(self.spring1.flange_b, self.fixed1.flange),
                ac.connect(self.force2.flange, self.mass2.flange_a),
                ac.connect(self.force1.flange, self.mass1.flange_a),
                ac.connect(self.spring2.flange_b, self.fixed2.flange)]


if __name__ == "__main__":
    res = ac.simulate(Oscillator(), t_end=Oscillator.stop_time, rtol=Oscillator.tolerance)
    print(f"mass1.s at {res.t[-1]:g} s: {res['mass1.s'][-1]:.6g} m")
