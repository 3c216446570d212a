"""Modelica.Thermal.FluidHeatFlow.Examples.ParallelPumpDropOut (MSL v4.0.0): cooling
circuit with parallel branches and drop out of the pump.

ParallelCooling with the pump's flow from a DoubleRamp (1 m3/s, down to 0 between 0.2
s and 0.4 s, back up from 0.6 s to 0.8 s).  Its Convection1 is spelt with a capital C,
as in the MSL.
"""
import acausal as ac
from acausal.library.blocks import Constant
from acausal.library.fluidheatflow import Ambient, Medium, Pipe, VolumeFlow
from acausal.library.thermal import Convection, HeatCapacitor, PrescribedHeatFlow

from .utilities import DoubleRamp

__all__ = ["ParallelPumpDropOut"]

TAmb = 293.15   # K, ambient temperature


def _pipe(**extra):
    return Pipe(medium=Medium(), m=0.1, T0=TAmb, V_flowLaminar=0.1, dpLaminar=0.1,
                V_flowNominal=1.0, dpNominal=1.0, h_g=0.0, T0fixed=True, **extra)


class ParallelPumpDropOut(ac.Component):
    """Losses 5 W and 10 W, convections 1 W/K, flow 1 -> 0 -> 1 m3/s."""

    msl_name = "Modelica.Thermal.FluidHeatFlow.Examples.ParallelPumpDropOut"
    stop_time = 2.0
    tolerance = 1e-6

    ambient1 = Ambient(constantAmbientTemperature=TAmb, medium=Medium(),
                       constantAmbientPressure=0.0)
    pump = VolumeFlow(medium=Medium(), m=0.0, T0=TAmb, useVolumeFlowInput=True,
                      constantVolumeFlow=1.0)
    pipe1 = _pipe(useHeatPort=True)
    pipe2 = _pipe(useHeatPort=True)
    pipe3 = _pipe()
    ambient2 = Ambient(constantAmbientTemperature=TAmb, medium=Medium(),
                       constantAmbientPressure=0.0)
    heatCapacitor1 = HeatCapacitor(C=0.1, T={"start": TAmb, "fixed": True})
    prescribedHeatFlow1 = PrescribedHeatFlow()
    Convection1 = Convection()
    heatCapacitor2 = HeatCapacitor(C=0.1, T={"start": TAmb, "fixed": True})
    prescribedHeatFlow2 = PrescribedHeatFlow()
    convection2 = Convection()
    volumeFlow = DoubleRamp()
    heatFlow1 = Constant(k=5.0)
    heatFlow2 = Constant(k=10.0)
    thermalConductance1 = Constant(k=1.0)
    thermalConductance2 = Constant(k=1.0)

    def equations(self):
        return [ac.connect(self.ambient1.flowPort, self.pump.flowPort_a),
                ac.connect(self.pump.flowPort_b, self.pipe1.flowPort_a),
                ac.connect(self.pump.flowPort_b, self.pipe2.flowPort_a),
                ac.connect(self.heatFlow2.y, self.prescribedHeatFlow2.Q_flow),
                ac.connect(self.heatFlow1.y, self.prescribedHeatFlow1.Q_flow),
                ac.connect(self.thermalConductance2.y, self.convection2.Gc),
                ac.connect(self.thermalConductance1.y, self.Convection1.Gc),
                ac.connect(self.pipe1.heatPort, self.Convection1.fluid),
                ac.connect(self.convection2.fluid, self.pipe2.heatPort),
                ac.connect(self.convection2.solid, self.prescribedHeatFlow2.port),
                ac.connect(self.convection2.solid, self.heatCapacitor2.port),
                ac.connect(self.Convection1.solid, self.prescribedHeatFlow1.port),
                ac.connect(self.Convection1.solid, self.heatCapacitor1.port),
                ac.connect(self.pipe2.flowPort_b, self.pipe3.flowPort_a),
                ac.connect(self.pipe1.flowPort_b, self.pipe3.flowPort_a),
                ac.connect(self.pipe3.flowPort_b, self.ambient2.flowPort),
                ac.connect(self.volumeFlow.y, self.pump.volumeFlow)]


if __name__ == "__main__":
    res = ac.simulate(ParallelPumpDropOut(), t_end=ParallelPumpDropOut.stop_time,
                      rtol=ParallelPumpDropOut.tolerance)
    print(f"heatCapacitor1.T, heatCapacitor2.T at {res.t[-1]:g} s: "
          f"{res['heatCapacitor1.T'][-1]:.6g}, {res['heatCapacitor2.T'][-1]:.6g} K")
