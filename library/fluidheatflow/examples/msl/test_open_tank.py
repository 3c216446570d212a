"""Modelica.Thermal.FluidHeatFlow.Examples.TestOpenTank (MSL v4.0.0): the OpenTank.

A tank of 1 m2, half full at 40 degC, is drained at 1 m3/s from 0.5 s to 0.75 s and
refilled from the ambient at 20 degC from 0.75 s to 1 s (a volume flow source driven by
a table).
"""
import acausal as ac
from acausal.library.blocks import CombiTimeTable
from acausal.library.fluidheatflow import Ambient, OpenTank, VolumeFlow

__all__ = ["TestOpenTank"]


class TestOpenTank(ac.Component):
    """ATank = 1 m2, hTank = 1 m, g = 10 m/s2, level 0.5 m at 313.15 K."""

    msl_name = "Modelica.Thermal.FluidHeatFlow.Examples.TestOpenTank"
    stop_time = 1.5
    tolerance = 1e-6

    openTank = OpenTank(ATank=1.0, hTank=1.0, useHeatPort=False, pAmbient=0.0, g=10.0,
                        level={"signal": {"fixed": True, "start": 0.5}}, T0=313.15,
                        T0fixed=True)
    ambient = Ambient(constantAmbientPressure=0.0, constantAmbientTemperature=293.15)
    volumeFlow = VolumeFlow(m=0.0, useVolumeFlowInput=True, constantVolumeFlow=1.0,
                            T0=293.15)
    combiTimeTable = CombiTimeTable(table=[[0, 0], [0.5, 0], [0.5, -1], [0.75, -1],
                                           [0.75, 1], [1, 1], [1, 0], [1.5, 0]])

    def equations(self):
        return [ac.connect(self.combiTimeTable.y[0], self.volumeFlow.volumeFlow),
                ac.connect(self.openTank.flowPort, self.volumeFlow.flowPort_b),
                ac.connect(self.volumeFlow.flowPort_a, self.ambient.flowPort)]


if __name__ == "__main__":
    res = ac.simulate(TestOpenTank(), t_end=TestOpenTank.stop_time,
                      rtol=TestOpenTank.tolerance)
    print(f"openTank.m, openTank.H at {res.t[-1]:g} s: {res['openTank.m'][-1]:.6g}, "
          f"{res['openTank.H'][-1]:.6g}")
