"""Modelica.Thermal.FluidHeatFlow.Examples.OneMass (MSL v4.0.0): cooling of one hot mass.

A heat capacity of 0.1 J/K at 40 degC is cooled through a conductor of 1 W/K by the
coolant of a pipe (0.1 kg of the default medium); the pump's flow starts at zero, ramps
up to 1 m3/s from 0.2 s, and reverses to -1 m3/s from 0.6 s (a DoubleRamp).
"""
import acausal as ac
from acausal.library.fluidheatflow import Ambient, Medium, Pipe, VolumeFlow
from acausal.library.thermal import HeatCapacitor, ThermalConductor

from .utilities import DoubleRamp

__all__ = ["OneMass"]

TAmb = 293.15    # K, ambient temperature
TMass = 313.15   # K, initial temperature of the mass


class OneMass(ac.Component):
    """Mass 0.1 J/K at 40 degC, conductor 1 W/K, flow 0 -> 1 -> -1 m3/s."""

    msl_name = "Modelica.Thermal.FluidHeatFlow.Examples.OneMass"
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
    heatCapacitor = HeatCapacitor(C=0.1, T={"start": TMass, "fixed": True})
    thermalConductor = ThermalConductor(G=1.0)
    volumeFlow = DoubleRamp(offset=0.0, height_1=1.0, height_2=-2.0)

    def equations(self):
        return [ac.connect(self.ambient1.flowPort, self.pump.flowPort_a),
                ac.connect(self.pump.flowPort_b, self.pipe.flowPort_a),
                ac.connect(self.pipe.flowPort_b, self.ambient2.flowPort),
                ac.connect(self.thermalConductor.port_a, self.heatCapacitor.port),
                ac.connect(self.pipe.heatPort, self.thermalConductor.port_b),
                ac.connect(self.volumeFlow.y, self.pump.volumeFlow)]


if __name__ == "__main__":
    res = ac.simulate(OneMass(), t_end=OneMass.stop_time, rtol=OneMass.tolerance)
    print(f"heatCapacitor.T, pipe.T at {res.t[-1]:g} s: {res['heatCapacitor.T'][-1]:.6g}, "
          f"{res['pipe.T'][-1]:.6g} K")
