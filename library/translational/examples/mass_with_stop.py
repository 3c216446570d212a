"""A mass pushed into a hard stop by a sinusoidal force.

    m s'' = F0 sin(omega t) + f_stop,   s_min <= s <= s_max

From rest at s = 0 the force drives the mass into the stop at s_max = 0.1 m (t = 0.61 s),
where it rests (v = 0, the stop carrying the force) until the force reverses at
t = pi/omega = 1 s.  From then on it swings from stop to stop, arriving each time when
the force already pulls it back: the plastic impact stops it and it leaves at once.
"""
import numpy as np

import acausal as ac
from acausal.library.blocks import Sine
from acausal.library.translational import Force, MassWithStop

__all__ = ["MassAgainstStop"]


class MassAgainstStop(ac.Component):
    """m = 1 kg, F0 = 1 N at 0.5 Hz (omega = pi rad/s), stops at -0.3 m and 0.1 m,
    plastic impacts (e = 0)."""

    stop_time = 6.0
    mass = MassWithStop(m=1.0, s_min=-0.3, s_max=0.1, s={"start": 0.0, "fixed": True},
                        v={"start": 0.0, "fixed": True})
    push = Force()
    sine = Sine(amplitude=1.0, f=0.5)

    def equations(self):
        return [ac.connect(self.sine.y, self.push.f),
                ac.connect(self.push.flange, self.mass.flange_b)]


if __name__ == "__main__":
    res = ac.simulate(MassAgainstStop(), t_end=MassAgainstStop.stop_time, rtol=1e-8)
    print(f"{len(res.events)} events at {np.round(res.events, 6).tolist()}; "
          f"s in [{res['mass.s'].min():.12f}, {res['mass.s'].max():.12f}] m")
