"""Modelica.Thermal.FluidHeatFlow.Examples.ParallelCooling (MSL v4.0.0): cooling circuit
with parallel branches.

One pump (1 m3/s) feeds two parallel pipes, each cooling a capacity of 0.1 J/K heated by
5 W and 10 W through a convection of 1 W/K; they join into pipe3, which returns the
mixed coolant to the ambient.
"""
import acausal as ac
from acausal.library.blocks import Constant
from acausal.library.fluidheatflow import Ambient, Medium, Pipe, VolumeFlow
from acausal.library.thermal import Convection, HeatCapacitor, PrescribedHeatFlow

__all__ = ["ParallelCooling"]

TAmb = 293.15   # K, ambient temperature


def _pipe(**extra):
    return Pipe(medium=Medium(), m=0.1, T0=TAmb, V_flowLaminar=0.1, dpLaminar=0.1,
                V_flowNominal=1.0, dpNominal=1.0, h_g=0.0, T0fixed=True, **extra)


class ParallelCooling(ac.Component):
    """Losses 5 W and 10 W, convections 1 W/K, flow 1 m3/s."""

    msl_name = "Modelica.Thermal.FluidHeatFlow.Examples.ParallelCooling"
    stop_time = 1.0
    tolerance = 1e-6

    ambient1 = Ambient(constantAmbientTemperature=TAmb, medium=Medium(),
                       constantAmbientPressure=0.0)
    pump = VolumeFlow(medium=Medium(), m=0.0, T0=TAmb, useVolumeFlowInput=True,
                      constantVolumeFlow=1.0)
    pipe1 = _pipe(useHeatPort=True)
    pipe2 = _pipe(useHeatPort=True)
    pipe3 = _pipe(useHeatPort=False)
    ambient2 = Ambient(constantAmbientTemperature=TAmb, medium=Medium(),
                       constantAmbientPressure=0.0)
    heatCapacitor1 = HeatCapacitor(C=0.1, T={"start": TAmb, "fixed": True})
    prescribedHeatFlow1 = PrescribedHeatFlow()
    convection1 = Convection()
    heatCapacitor2 = HeatCapacitor(C=0.1, T={"start": TAmb, "fixed": True})
    prescribedHeatFlow2 = PrescribedHeatFlow()
    convection2 = Convection()
    volumeFlow = Constant(k=1.0)
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
                ac.connect(self.thermalConductance1.y, self.convection1.Gc),
                ac.connect(self.pipe1.heatPort, self.convection1.fluid),
                ac.connect(self.convection2.fluid, self.pipe2.heatPort),
                ac.connect(self.convection2.solid, self.prescribedHeatFlow2.port),
                ac.connect(self.convection2.solid, self.heatCapacitor2.port),
                ac.connect(self.convection1.solid, self.prescribedHeatFlow1.port),
                ac.connect(self.convection1.solid, self.heatCapacitor1.port),
                ac.connect(self.pipe2.flowPort_b, self.pipe3.flowPort_a),
                ac.connect(self.pipe1.flowPort_b, self.pipe3.flowPort_a),
                ac.connect(self.pipe3.flowPort_b, self.ambient2.flowPort),
                ac.connect(self.volumeFlow.y, self.pump.volumeFlow)]


if __name__ == "__main__":
    res = ac.simulate(ParallelCooling(), t_end=ParallelCooling.stop_time,
                      rtol=ParallelCooling.tolerance)
    print(f"heatCapacitor1.T, heatCapacitor2.T at {res.t[-1]:g} s: "
          f"{res['heatCapacitor1.T'][-1]:.6g}, {res['heatCapacitor2.T'][-1]:.6g} K")
