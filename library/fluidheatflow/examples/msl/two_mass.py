"""Modelica.Thermal.FluidHeatFlow.Examples.TwoMass (MSL v4.0.0): cooling of two hot
masses.

Two capacities of 0.1 J/K at 40 degC and 60 degC are cooled through conductors of 1 W/K
by two parallel pipes, which join into pipe3; the pump's flow starts at zero, ramps up
to 1 m3/s from 0.2 s and reverses to -1 m3/s from 0.6 s (a DoubleRamp), so that the
coolant then enters from ambient2 and leaves through the pump.
"""
import acausal as ac
from acausal.library.fluidheatflow import Ambient, Medium, Pipe, VolumeFlow
from acausal.library.thermal import HeatCapacitor, ThermalConductor

from .utilities import DoubleRamp

__all__ = ["TwoMass"]

TAmb = 293.15     # K, ambient temperature
TMass1 = 313.15   # K, initial temperature of mass1
TMass2 = 333.15   # K, initial temperature of mass2


def _pipe(**extra):
    return Pipe(medium=Medium(), m=0.1, T0=TAmb, V_flowLaminar=0.1, dpLaminar=0.1,
                V_flowNominal=1.0, dpNominal=1.0, h_g=0.0, T0fixed=True, **extra)


class TwoMass(ac.Component):
    """Masses 0.1 J/K at 40 and 60 degC, conductors 1 W/K, flow 0 -> 1 -> -1 m3/s."""

    msl_name = "Modelica.Thermal.FluidHeatFlow.Examples.TwoMass"
    stop_time = 1.0
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
    heatCapacitor1 = HeatCapacitor(C=0.1, T={"start": TMass1, "fixed": True})
    thermalConductor1 = ThermalConductor(G=1.0)
    heatCapacitor2 = HeatCapacitor(C=0.1, T={"start": TMass2, "fixed": True})
    thermalConductor2 = ThermalConductor(G=1.0)
    volumeFlow = DoubleRamp(offset=0.0, height_1=1.0, height_2=-2.0)

    def equations(self):
        return [ac.connect(self.ambient1.flowPort, self.pump.flowPort_a),
                ac.connect(self.pump.flowPort_b, self.pipe1.flowPort_a),
                ac.connect(self.pump.flowPort_b, self.pipe2.flowPort_a),
                ac.connect(self.pipe2.flowPort_b, self.pipe3.flowPort_a),
                ac.connect(self.pipe1.flowPort_b, self.pipe3.flowPort_a),
                ac.connect(self.pipe3.flowPort_b, self.ambient2.flowPort),
                ac.connect(self.heatCapacitor2.port, self.thermalConductor2.port_a),
                ac.connect(self.thermalConductor2.port_b, self.pipe2.heatPort),
                ac.connect(self.pipe1.heatPort, self.thermalConductor1.port_b),
                ac.connect(self.thermalConductor1.port_a, self.heatCapacitor1.port),
                ac.connect(self.volumeFlow.y, self.pump.volumeFlow)]


if __name__ == "__main__":
    res = ac.simulate(TwoMass(), t_end=TwoMass.stop_time, rtol=TwoMass.tolerance)
    print(f"heatCapacitor1.T, heatCapacitor2.T at {res.t[-1]:g} s: "
          f"{res['heatCapacitor1.T'][-1]:.6g}, {res['heatCapacitor2.T'][-1]:.6g} K")
