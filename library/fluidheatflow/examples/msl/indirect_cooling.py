"""Modelica.Thermal.FluidHeatFlow.Examples.IndirectCooling (MSL v4.0.0): indirect cooling
circuit.

A heat source of 10 W with a capacity of 0.05 J/K is cooled through 1 W/K by an inner
closed circuit (pipe1, a pump and innerPipe, its pressure level set by an
AbsolutePressure of 10 kPa), which is cooled in turn, through two convections of 2 W/K,
by an outer open circuit drawing coolant from the ambient.  Both pumps impose 1 m3/s;
both media are the default one.
"""
import acausal as ac
from acausal.library.blocks import Constant
from acausal.library.fluidheatflow import (AbsolutePressure, Ambient, Medium, Pipe,
                                           VolumeFlow)
from acausal.library.thermal import (Convection, HeatCapacitor, PrescribedHeatFlow,
                                     ThermalConductor)

__all__ = ["IndirectCooling"]

TAmb = 293.15   # K, ambient temperature


class IndirectCooling(ac.Component):
    """Losses 10 W; inner and outer flows 1 m3/s; convections 2 W/K."""

    msl_name = "Modelica.Thermal.FluidHeatFlow.Examples.IndirectCooling"
    stop_time = 1.5
    tolerance = 1e-6

    ambient1 = Ambient(constantAmbientTemperature=TAmb, medium=Medium(),
                       constantAmbientPressure=0.0)
    outerPump = VolumeFlow(medium=Medium(), m=0.0, T0=TAmb, useVolumeFlowInput=True,
                           constantVolumeFlow=1.0)
    ambient2 = Ambient(constantAmbientTemperature=TAmb, medium=Medium(),
                       constantAmbientPressure=0.0)
    thermalConductor = ThermalConductor(G=1.0)
    heatCapacitor = HeatCapacitor(C=0.05, T={"start": TAmb, "fixed": True})
    prescribedHeatFlow = PrescribedHeatFlow()
    pipe1 = Pipe(medium=Medium(), m=0.1, T0=TAmb, V_flowLaminar=1.0, V_flowNominal=2.0,
                 h_g=0.0, T0fixed=True, useHeatPort=True, dpLaminar=1000.0,
                 dpNominal=2000.0)
    absolutePressure = AbsolutePressure(p=10000.0, medium=Medium())
    innerPump = VolumeFlow(medium=Medium(), m=0.0, T0=TAmb, useVolumeFlowInput=True,
                           constantVolumeFlow=1.0)
    heatFlow = Constant(k=10.0)
    outerVolumeFlow = Constant(k=1.0)
    innerVolumeFlow = Constant(k=1.0)
    outerGc = Constant(k=2.0)
    innerGc = Constant(k=2.0)
    outerPipe = Pipe(medium=Medium(), m=0.1, T0=TAmb, V_flowLaminar=0.1, dpLaminar=0.1,
                     V_flowNominal=1.0, dpNominal=1.0, h_g=0.0, T0fixed=True,
                     useHeatPort=True)
    innerPipe = Pipe(medium=Medium(), m=0.1, T0=TAmb, V_flowLaminar=0.1, dpLaminar=0.1,
                     V_flowNominal=1.0, dpNominal=1.0, h_g=0.0, T0fixed=True,
                     useHeatPort=True)
    innerConvection = Convection()
    outerConvection = Convection()

    def equations(self):
        return [ac.connect(self.ambient1.flowPort, self.outerPump.flowPort_a),
                ac.connect(self.prescribedHeatFlow.port, self.thermalConductor.port_a),
                ac.connect(self.heatCapacitor.port, self.thermalConductor.port_a),
                ac.connect(self.pipe1.heatPort, self.thermalConductor.port_b),
                ac.connect(self.pipe1.flowPort_b, self.innerPump.flowPort_a),
                ac.connect(self.absolutePressure.flowPort, self.pipe1.flowPort_a),
                ac.connect(self.heatFlow.y, self.prescribedHeatFlow.Q_flow),
                ac.connect(self.innerPump.flowPort_b, self.innerPipe.flowPort_a),
                ac.connect(self.innerPipe.flowPort_b, self.absolutePressure.flowPort),
                ac.connect(self.outerPump.flowPort_b, self.outerPipe.flowPort_a),
                ac.connect(self.outerPipe.flowPort_b, self.ambient2.flowPort),
                ac.connect(self.outerPipe.heatPort, self.outerConvection.fluid),
                ac.connect(self.outerConvection.solid, self.innerConvection.solid),
                ac.connect(self.innerConvection.fluid, self.innerPipe.heatPort),
                ac.connect(self.innerGc.y, self.innerConvection.Gc),
                ac.connect(self.outerGc.y, self.outerConvection.Gc),
                ac.connect(self.outerVolumeFlow.y, self.outerPump.volumeFlow),
                ac.connect(self.innerVolumeFlow.y, self.innerPump.volumeFlow)]


if __name__ == "__main__":
    res = ac.simulate(IndirectCooling(), t_end=IndirectCooling.stop_time,
                      rtol=IndirectCooling.tolerance)
    print(f"heatCapacitor.T at {res.t[-1]:g} s: {res['heatCapacitor.T'][-1]:.6g} K")
