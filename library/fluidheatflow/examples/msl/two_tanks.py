"""Modelica.Thermal.FluidHeatFlow.Examples.TwoTanks (MSL v4.0.0): two connected open
tanks.

Tank 1 (level 0.9 m, 40 degC) drains through a pipe into tank 2 (level 0.1 m, 20 degC)
until the levels are equal; the pipe holds no medium (m = 0).
"""
import acausal as ac
from acausal.library.fluidheatflow import OpenTank, Pipe

__all__ = ["TwoTanks"]


class TwoTanks(ac.Component):
    """Tanks of 1 m2 under 1 bar, g = 10 m/s2; pipe laminar 10 Pa at 2 m3/s."""

    msl_name = "Modelica.Thermal.FluidHeatFlow.Examples.TwoTanks"
    stop_time = 1.5
    tolerance = 1e-6

    openTank1 = OpenTank(ATank=1.0, hTank=1.0, useHeatPort=False, g=10.0,
                         level={"signal": {"fixed": True, "start": 0.9}}, T0=313.15,
                         T0fixed=True, pAmbient=100000.0)
    openTank2 = OpenTank(ATank=1.0, hTank=1.0, useHeatPort=False, g=10.0,
                         level={"signal": {"fixed": True, "start": 0.1}}, T0=293.15,
                         T0fixed=True, pAmbient=100000.0)
    pipe = Pipe(m=0.0, h_g=0.0, T0=293.15, V_flowLaminar=2.0, dpLaminar=10.0,
                V_flowNominal=4.0, dpNominal=30.0)

    def equations(self):
        return [ac.connect(self.openTank1.flowPort, self.pipe.flowPort_a),
                ac.connect(self.pipe.flowPort_b, self.openTank2.flowPort)]


if __name__ == "__main__":
    res = ac.simulate(TwoTanks(), t_end=TwoTanks.stop_time, rtol=TwoTanks.tolerance)
    print(f"openTank1.level, openTank2.level at {res.t[-1]:g} s: "
          f"{res['openTank1.level.signal'][-1]:.6g}, {res['openTank2.level.signal'][-1]:.6g}")
