"""Modelica.Thermal.FluidHeatFlow.Examples.PumpDropOut (MSL v4.0.0): cooling circuit with
drop out of the pump.

SimpleCooling with the pump's flow from a DoubleRamp: 1 m3/s, down to 0 from 0.2 s to
0.4 s, held at 0 until 0.6 s, back to 1 m3/s at 0.8 s.  Without flow the pipe holds
its heat, and the capacity heats up.
"""
import acausal as ac
from acausal.library.blocks import Constant
from acausal.library.fluidheatflow import Ambient, Medium, Pipe, VolumeFlow
from acausal.library.thermal import Convection, HeatCapacitor, PrescribedHeatFlow

from .utilities import DoubleRamp

__all__ = ["PumpDropOut"]

TAmb = 293.15   # K, ambient temperature


class PumpDropOut(ac.Component):
    """Losses 10 W, convection 1 W/K, flow 1 -> 0 -> 1 m3/s."""

    msl_name = "Modelica.Thermal.FluidHeatFlow.Examples.PumpDropOut"
    stop_time = 2.0
    tolerance = 1e-6

    ambient1 = Ambient(constantAmbientTemperature=TAmb, medium=Medium(),
                       constantAmbientPressure=0.0)
    pump = VolumeFlow(medium=Medium(), m=0.0, T0=TAmb, useVolumeFlowInput=True,
                      constantVolumeFlow=1.0)
    pipe = Pipe(medium=Medium(), T0=TAmb, m=0.1, V_flowLaminar=0.1, dpLaminar=0.1,
                V_flowNominal=1.0, dpNominal=1.0, h_g=0.0, T0fixed=True, useHeatPort=True)
    ambient2 = Ambient(constantAmbientTemperature=TAmb, medium=Medium(),
                       constantAmbientPressure=0.0)
    heatCapacitor = HeatCapacitor(C=0.1, T={"start": TAmb, "fixed": True})
    prescribedHeatFlow = PrescribedHeatFlow()
    volumeFlow = DoubleRamp()
    heatFlow = Constant(k=10.0)
    convection = Convection()
    thermalConductance = Constant(k=1.0)

    def equations(self):
        return [ac.connect(self.ambient1.flowPort, self.pump.flowPort_a),
                ac.connect(self.pump.flowPort_b, self.pipe.flowPort_a),
                ac.connect(self.pipe.flowPort_b, self.ambient2.flowPort),
                ac.connect(self.heatFlow.y, self.prescribedHeatFlow.Q_flow),
                ac.connect(self.convection.solid, self.prescribedHeatFlow.port),
                ac.connect(self.convection.solid, self.heatCapacitor.port),
                ac.connect(self.pipe.heatPort, self.convection.fluid),
                ac.connect(self.thermalConductance.y, self.convection.Gc),
                ac.connect(self.volumeFlow.y, self.pump.volumeFlow)]


if __name__ == "__main__":
    res = ac.simulate(PumpDropOut(), t_end=PumpDropOut.stop_time, rtol=PumpDropOut.tolerance)
    print(f"heatCapacitor.T, pipe.T at {res.t[-1]:g} s: {res['heatCapacitor.T'][-1]:.6g}, "
          f"{res['pipe.T'][-1]:.6g} K")
