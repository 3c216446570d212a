"""Modelica.Thermal.FluidHeatFlow.Examples.SimpleCooling (MSL v4.0.0): simple cooling
circuit.

A pump draws coolant (the default medium: rho = cp = cv = 1) from the ambient at 20 degC
through a pipe of 0.1 kg, which cools a heat capacity of 0.1 J/K heated by 10 W through
a convection of 1 W/K, and returns it to the ambient; the pump imposes 1 m3/s.
"""
import acausal as ac
from acausal.library.blocks import Constant
from acausal.library.fluidheatflow import Ambient, Medium, Pipe, VolumeFlow
from acausal.library.thermal import Convection, HeatCapacitor, PrescribedHeatFlow

__all__ = ["SimpleCooling"]

TAmb = 293.15   # K, ambient temperature


class SimpleCooling(ac.Component):
    """Volume flow 1 m3/s, losses 10 W, convection 1 W/K."""

    msl_name = "Modelica.Thermal.FluidHeatFlow.Examples.SimpleCooling"
    stop_time = 1.0
    tolerance = 1e-6

    ambient1 = Ambient(constantAmbientTemperature=TAmb, medium=Medium(),
                       constantAmbientPressure=0.0)
    pump = VolumeFlow(medium=Medium(), m=0.0, T0=TAmb, useVolumeFlowInput=True,
                      constantVolumeFlow=1.0)
    pipe = Pipe(medium=Medium(), m=0.1, T0=TAmb, V_flowLaminar=0.1, dpLaminar=0.1,
                V_flowNominal=1.0, dpNominal=1.0, h_g=0.0, T0fixed=True, useHeatPort=True)
    ambient2 = Ambient(constantAmbientTemperature=TAmb, medium=Medium(),
                       constantAmbientPressure=0.0)
    heatCapacitor = HeatCapacitor(C=0.1, T={"start": TAmb, "fixed": True})
    prescribedHeatFlow = PrescribedHeatFlow()
    volumeFlow = Constant(k=1.0)
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
    res = ac.simulate(SimpleCooling(), t_end=SimpleCooling.stop_time,
                      rtol=SimpleCooling.tolerance)
    print(f"heatCapacitor.T, pipe.T at {res.t[-1]:g} s: {res['heatCapacitor.T'][-1]:.6g}, "
          f"{res['pipe.T'][-1]:.6g} K")
