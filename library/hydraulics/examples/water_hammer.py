"""Water hammer: fast closure of a valve at the end of a long line (Egeland & Gravdahl
11.2.10, Example 165).

Oil flows at v_0 from a tank through a line of length L to a valve.  Closed in a time
much shorter than the wave's round trip 2L/c, the valve stops the column; the kinetic
energy goes into compression, and the pressure at the valve rises by

    p_2 = rho c v_0                                                        (11.125)

(10 bar per m/s for oil with rho = 800 kg/m3, c = 1250 m/s) until the wave reflected
at the tank returns at 2L/c.  The line is a ``LumpedLine`` in hybrid form: a pipe at
the tank (pressure) end, a volume at the valve (flow) end.
"""
import acausal as ac
from acausal.library.blocks import Ramp

from ..components import VariableOrifice
from ..lines import LumpedLine
from ..sources import FixedPressure

__all__ = ["WaterHammer"]

RHO, C, L, A_LINE, P_0 = 800.0, 1250.0, 100.0, 1e-3, 2e5
A_VALVE, V_0 = 1e-4, 2.0           # the valve's open area, the flow speed in the line
Q_0 = V_0 * A_LINE
# the valve pressure drop that passes Q_0 through the open valve (turbulent branch)
DP_VALVE = RHO / 2 * (Q_0 / (0.6 * A_VALVE))**2


class WaterHammer(ac.Component):
    """L = 100 m (2L/c = 0.16 s), A = 10 cm2, v_0 = 2 m/s; the valve closes linearly in
    5 ms from t = 10 ms.  30 resonators: the pressure rings about rho c v_0 (peak +5 %)
    at the chain's highest frequencies, 2 c/h."""

    stop_time = 0.14
    tank = FixedPressure(p=P_0 + DP_VALVE)
    line = LumpedLine(n=30, form="hybrid", L=L, A=A_LINE, rho=RHO, beta=RHO * C**2,
                      p_start=P_0 + DP_VALVE, q_start=Q_0)
    valve = VariableOrifice(rho=RHO)
    outlet = FixedPressure(p=P_0)
    closing = Ramp(offset=A_VALVE, height=-A_VALVE, duration=5e-3, startTime=0.01)

    def equations(self):
        return [ac.connect(self.tank.port, self.line.port_a),
                ac.connect(self.line.port_b, self.valve.port_a),
                ac.connect(self.valve.port_b, self.outlet.port),
                ac.connect(self.closing.y, self.valve.A_in)]


if __name__ == "__main__":
    res = ac.simulate(WaterHammer(), t_end=WaterHammer.stop_time, rtol=1e-5)
    closed = res.t > 0.02
    rise = res["line.port_b.p"][closed] - (P_0 + DP_VALVE)
    print(f"pressure rise: mean {rise.mean() / 1e5:.2f} bar, peak {rise.max() / 1e5:.2f} bar; "
          f"rho c v0 = {RHO * C * V_0 / 1e5:.2f} bar")
