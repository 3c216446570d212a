"""A line open to a tank at one end and closed at the other, the tank pressure stepped
(Egeland & Gravdahl 4.5.8, 4.6.6-4.6.7).

The step travels to the closed end in T = L/c and is reflected there (G_L = 1), so the
closed-end pressure of the distributed line is a square wave: 2 p_step for
L/c < t < 3L/c, 0 until 5L/c, and so on, of period 4L/c: the quarter-wave resonance
(pi/2) c/L of (4.309).  The chain of n resonators in hybrid form (port_a on a pipe at the
tank, port_b on the closed volume, L = (n + 1/2) h) has the first natural frequency
2 (c/h) sin(pi/(2(2n + 1))), 1.5 c/L for n = 1 (4.308).
"""
import acausal as ac
from acausal.library.blocks import Ramp

from ..lines import LumpedLine
from ..sources import PressureSource

__all__ = ["LineClosedAtOneEnd"]


class LineClosedAtOneEnd(ac.Component):
    """L = 20 m of oil (rho = 870 kg/m3, c = 1400 m/s, T = 14.3 ms), 20 resonators; the
    tank pressure rises by 10 bar in 2 ms from t = 1 ms (a ramp rather than a step, which
    would ring in every mode of the undamped chain)."""

    stop_time = 0.08
    step = Ramp(height=1e6, duration=2e-3, startTime=1e-3)
    tank = PressureSource()

    def __init__(self, n=20, **mods):
        super().__init__(**mods)
        self.line = LumpedLine(n=n, form="hybrid", L=20.0, rho=870.0, beta=870.0 * 1400.0**2)

    def equations(self):
        return [ac.connect(self.step.y, self.tank.p_ref),
                ac.connect(self.tank.port, self.line.port_a)]


if __name__ == "__main__":
    res = ac.simulate(LineClosedAtOneEnd(), t_end=LineClosedAtOneEnd.stop_time, rtol=1e-5)
    print(f"closed-end pressure peak {res['line.port_b.p'].max() / 1e5:.2f} bar")
