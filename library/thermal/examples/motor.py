"""Modelica.Thermal.HeatTransfer.Examples.Motor (MSL v4.0.0): second order thermal model
of a motor.

Periodic losses from a table (winding: 100 W for 360 s, then 1000 W for 240 s; core:
500 W) heat the winding (2500 J/K) and the core (25000 J/K), coupled by 10 W/K; the
core is cooled by forced convection (Gc = 25 W/K) to the environment at 20 degC.  The
winding losses grow with the winding's temperature, (1 + alpha (T - T_ref)).

MAP-LIB's reference result of this example (v4.0.0) is not in the copy this library is
checked against, so it is not among the examples under ``examples.msl``; its test
(``tests/library/test_thermal.py``) solves the same two equations independently.
"""
import acausal as ac
from acausal.library.blocks import CombiTimeTable, Constant
from acausal.library.thermal import (Convection, FixedTemperature, HeatCapacitor,
                                     PrescribedHeatFlow, ThermalConductor, celsius)

__all__ = ["Motor"]

TAmb = 293.15   # K, ambient temperature


class Motor(ac.Component):
    """C_winding = 2500 J/K, C_core = 25000 J/K, G = 10 W/K, Gc = 25 W/K, alpha =
    3.03e-3 1/K at T_ref = 95 degC."""

    stop_time = 7200.0

    lossTable = CombiTimeTable(table=[[0, 100, 500], [360, 1000, 500], [600, 100, 500]],
                               smoothness="constant", extrapolation="periodic")
    windingLosses = PrescribedHeatFlow(T_ref=368.15, alpha=3.03e-3)
    winding = HeatCapacitor(C=2500.0, T={"start": TAmb, "fixed": True})
    Twinding = celsius.TemperatureSensor()
    winding2core = ThermalConductor(G=10.0)
    coreLosses = PrescribedHeatFlow()
    core = HeatCapacitor(C=25000.0, T={"start": TAmb, "fixed": True})
    Tcore = celsius.TemperatureSensor()
    convectionConstant = Constant(k=25.0)
    convection = Convection()
    environment = FixedTemperature(T=TAmb)

    def equations(self):
        return [ac.connect(self.windingLosses.port, self.winding.port),
                ac.connect(self.coreLosses.port, self.core.port),
                ac.connect(self.winding.port, self.winding2core.port_a),
                ac.connect(self.winding2core.port_b, self.core.port),
                ac.connect(self.winding.port, self.Twinding.port),
                ac.connect(self.core.port, self.Tcore.port),
                ac.connect(self.winding2core.port_b, self.convection.solid),
                ac.connect(self.convection.fluid, self.environment.port),
                ac.connect(self.convectionConstant.y, self.convection.Gc),
                ac.connect(self.lossTable.y[0], self.windingLosses.Q_flow),
                ac.connect(self.lossTable.y[1], self.coreLosses.Q_flow)]


if __name__ == "__main__":
    res = ac.simulate(Motor(), t_end=Motor.stop_time, rtol=1e-6)
    print(f"winding, core at {res.t[-1]:g} s: {res['Twinding.T'][-1]:.4f}, "
          f"{res['Tcore.T'][-1]:.4f} degC")
