"""Modelica.Thermal.FluidHeatFlow.Examples.PumpAndValve (MSL v4.0.0): cooling circuit
with pump and valve.

An ideal pump, turned by a speed source (0.5 rad/s, ramped to 1 rad/s from 0.4 s to
0.5 s), pushes coolant through a valve with an exponential characteristic (opening 0.5,
ramped to 1 from 0.9 s to 1 s) and a pipe that cools a capacity of 0.1 J/K heated by
10 W through a convection of 1 W/K.
"""
import acausal as ac
from acausal.library.blocks import Constant, Ramp
from acausal.library.fluidheatflow import Ambient, IdealPump, Medium, Pipe, Valve
from acausal.library.rotational import Speed
from acausal.library.thermal import Convection, HeatCapacitor, PrescribedHeatFlow

__all__ = ["PumpAndValve"]

TAmb = 293.15   # K, ambient temperature


class PumpAndValve(ac.Component):
    """Pump dp0 = 2 Pa, V_flow0 = 2 m3/s at 1 rad/s; valve Kv1 = 1 m3/s, kv0 = 0.01."""

    msl_name = "Modelica.Thermal.FluidHeatFlow.Examples.PumpAndValve"
    stop_time = 2.0
    tolerance = 1e-6

    ambient1 = Ambient(constantAmbientTemperature=TAmb, medium=Medium(),
                       constantAmbientPressure=0.0)
    idealPump = IdealPump(medium=Medium(), m=0.0, T0=TAmb, V_flow0=2.0, wNominal=1.0,
                          dp0=2.0)
    valve = Valve(medium=Medium(), m=0.0, T0=TAmb, LinearCharacteristic=False, y1=1.0,
                  Kv1=1.0, kv0=0.01, dp0=1.0, rho0=10.0, frictionLoss=0.0)
    pipe = Pipe(medium=Medium(), T0=TAmb, m=0.1, V_flowLaminar=0.1, dpLaminar=0.1,
                V_flowNominal=1.0, dpNominal=1.0, h_g=0.0, T0fixed=True, useHeatPort=True)
    ambient2 = Ambient(constantAmbientTemperature=TAmb, medium=Medium(),
                       constantAmbientPressure=0.0)
    heatCapacitor = HeatCapacitor(C=0.1, T={"start": TAmb, "fixed": True})
    prescribedHeatFlow = PrescribedHeatFlow()
    heatFlow = Constant(k=10.0)
    convection = Convection()
    thermalConductance = Constant(k=1.0)
    speed = Speed()
    speedRamp = Ramp(height=0.5, offset=0.5, duration=0.1, startTime=0.4)
    valveRamp = Ramp(height=0.5, offset=0.5, duration=0.1, startTime=0.9)

    def equations(self):
        return [ac.connect(self.pipe.flowPort_b, self.ambient2.flowPort),
                ac.connect(self.heatFlow.y, self.prescribedHeatFlow.Q_flow),
                ac.connect(self.convection.solid, self.prescribedHeatFlow.port),
                ac.connect(self.convection.solid, self.heatCapacitor.port),
                ac.connect(self.pipe.heatPort, self.convection.fluid),
                ac.connect(self.thermalConductance.y, self.convection.Gc),
                ac.connect(self.ambient1.flowPort, self.idealPump.flowPort_a),
                ac.connect(self.idealPump.flowPort_b, self.valve.flowPort_a),
                ac.connect(self.valve.flowPort_b, self.pipe.flowPort_a),
                ac.connect(self.speedRamp.y, self.speed.w_ref),
                ac.connect(self.valveRamp.y, self.valve.y),
                ac.connect(self.speed.flange, self.idealPump.flange_a)]


if __name__ == "__main__":
    res = ac.simulate(PumpAndValve(), t_end=PumpAndValve.stop_time,
                      rtol=PumpAndValve.tolerance)
    print(f"heatCapacitor.T, pipe.T at {res.t[-1]:g} s: {res['heatCapacitor.T'][-1]:.6g}, "
          f"{res['pipe.T'][-1]:.6g} K")
