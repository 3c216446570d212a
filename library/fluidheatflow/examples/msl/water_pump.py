"""Modelica.Thermal.FluidHeatFlow.Examples.WaterPump (MSL v4.0.0): water pumping station.

An ideal pump (0.18 m3/s and 5 bar at 1000 rpm) lifts water by 25 m through a one-way
valve and a pipe; its speed follows a trapezoid (0 to 1.2 x nominal over 0.6 s from
0.1 s, held 0.6 s, back to 0 over 0.6 s).  Below the speed that makes up the height the
check valve holds the column.

The MSL's trapezoid has ``nperiod = 1``; the library's Trapezoid repeats endlessly, and
its second period (from 2.1 s) lies after the experiment's end.
"""
import acausal as ac
from acausal.library.blocks import Gain, Trapezoid
from acausal.library.fluidheatflow import (Ambient, IdealPump, OneWayValve, Pipe,
                                           PressureSensor, VolumeFlowSensor, Water)
from acausal.library.rotational import MultiSensor, Speed

__all__ = ["WaterPump"]


class WaterPump(ac.Component):
    """Pump 0.18 m3/s, 5 bar at 104.7 rad/s; height 25 m; water (Media.Water)."""

    msl_name = "Modelica.Thermal.FluidHeatFlow.Examples.WaterPump"
    stop_time = 2.0
    tolerance = 1e-7

    trapezoid = Trapezoid(period=2.0, offset=0.0, rising=0.6, width=0.6, falling=0.6,
                          startTime=0.1, amplitude=1.2)
    gain = Gain(k=104.71975511966)
    speed = Speed()
    multiSensor = MultiSensor()
    ambient1 = Ambient(medium=Water(), constantAmbientPressure=100000.0,
                       constantAmbientTemperature=293.15)
    idealPump = IdealPump(medium=Water(), m=0.0, V_flow0=0.18, T0=293.15,
                          wNominal=104.71975511966, dp0=500000.0)
    volumeFlowSensor = VolumeFlowSensor(medium=Water())
    pressureSensor = PressureSensor(medium=Water())
    oneWayValve = OneWayValve(medium=Water(), m=0.0, frictionLoss=0.0, T0=293.15,
                              V_flowNominal=0.18, dpForward=10000.0, dpNominal=500000.0,
                              V_flowBackward=1e-6)
    pipe = Pipe(m=0.0, V_flowLaminar=0.09, V_flowNominal=0.18, h_g=25.0, medium=Water(),
                T0=293.15, dpLaminar=10000.0, dpNominal=30000.0)
    ambient2 = Ambient(medium=Water(), constantAmbientPressure=100000.0,
                       constantAmbientTemperature=293.15)

    def equations(self):
        return [ac.connect(self.idealPump.flowPort_a, self.ambient1.flowPort),
                ac.connect(self.speed.flange, self.multiSensor.flange_a),
                ac.connect(self.oneWayValve.flowPort_a, self.volumeFlowSensor.flowPort_b),
                ac.connect(self.volumeFlowSensor.flowPort_a, self.idealPump.flowPort_b),
                ac.connect(self.ambient2.flowPort, self.pipe.flowPort_b),
                ac.connect(self.pipe.flowPort_a, self.oneWayValve.flowPort_b),
                ac.connect(self.multiSensor.flange_b, self.idealPump.flange_a),
                ac.connect(self.oneWayValve.flowPort_a, self.pressureSensor.flowPort),
                ac.connect(self.gain.y, self.speed.w_ref),
                ac.connect(self.trapezoid.y, self.gain.u)]


if __name__ == "__main__":
    res = ac.simulate(WaterPump(), t_end=WaterPump.stop_time, rtol=WaterPump.tolerance)
    print(f"max volume flow {res['volumeFlowSensor.y.signal'].max():.6g} m3/s")
