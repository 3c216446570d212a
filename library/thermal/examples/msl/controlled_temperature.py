"""Modelica.Thermal.HeatTransfer.Examples.ControlledTemperature (MSL v4.0.0): the
temperature of a heating resistor held by an on-off controller.

A constant 10 V heats a resistor of 10 Ohm (1 + (T - 20 degC)/255 K) whose losses v^2/R
heat its capacity of 1 J/K and leave through 0.1 W/K to the ambient at 20 degC.  An
OnOffController (bandwidth 2 K) compares the resistor's temperature with a reference of
25 degC that rises to 50 degC between 2 s and 8 s, and through a Not opens an ideal
switch (Boolean control) in series with the resistor whenever the temperature is above
the band.

The MSL's resistor is Analog.Basic.Resistor with useHeatPort = true; here the
electrical library's HeatingResistor, of the same law R = R_ref (1 + alpha (T - T_ref))
with its heat port always there.
"""
import acausal as ac
from acausal.library.blocks import Not, OnOffController, Ramp
from acausal.library.electrical import ConstantVoltage, Ground, HeatingResistor
from acausal.library.electrical.switches import IdealOpeningSwitch
from acausal.library.thermal import (FixedTemperature, HeatCapacitor, ThermalConductor,
                                     celsius)

__all__ = ["ControlledTemperature"]


class ControlledTemperature(ac.Component):
    """Control the temperature of a resistor."""

    msl_name = "Modelica.Thermal.HeatTransfer.Examples.ControlledTemperature"
    stop_time = 10.0
    tolerance = 1e-6

    TAmb = ac.Parameter(293.15, unit="K", description="ambient temperature")
    TDif = ac.Parameter(2.0, unit="K", description="error in temperature")
    TRes = ac.Variable(unit="K", description="resulting temperature")
    ground = Ground()
    constantVoltage = ConstantVoltage(V=10.0)
    heatCapacitor = HeatCapacitor(C=1.0, T={"start": 293.15, "fixed": True})
    resistor = HeatingResistor(R_ref=10.0, T_ref=293.15, alpha=1 / 255)
    fixedTemperature = FixedTemperature(T=ac.ref("TAmb"))
    temperatureSensor = celsius.TemperatureSensor()
    thermalConductor = ThermalConductor(G=0.1)
    idealSwitch = IdealOpeningSwitch(booleanControl=True)
    ramp = Ramp(height=25.0, duration=6.0, offset=25.0, startTime=2.0)
    onOffController = OnOffController(bandwidth=ac.ref("TDif"))
    logicalNot = Not()

    def equations(self):
        return [ac.Eq(self.TRes, self.resistor.heatPort.T),
                ac.connect(self.constantVoltage.n, self.resistor.n),
                ac.connect(self.constantVoltage.n, self.ground.p),
                ac.connect(self.resistor.heatPort, self.thermalConductor.port_a),
                ac.connect(self.thermalConductor.port_b, self.fixedTemperature.port),
                ac.connect(self.resistor.heatPort, self.temperatureSensor.port),
                ac.connect(self.resistor.heatPort, self.heatCapacitor.port),
                ac.connect(self.constantVoltage.p, self.idealSwitch.p),
                ac.connect(self.idealSwitch.n, self.resistor.p),
                ac.connect(self.ramp.y, self.onOffController.reference),
                ac.connect(self.temperatureSensor.T, self.onOffController.u),
                ac.connect(self.onOffController.y, self.logicalNot.u),
                ac.connect(self.logicalNot.y, self.idealSwitch.control)]


if __name__ == "__main__":
    res = ac.simulate(ControlledTemperature(), t_end=ControlledTemperature.stop_time,
                      rtol=ControlledTemperature.tolerance)
    print(f"heatCapacitor.T at {res.t[-1]:g} s: {res['heatCapacitor.T'][-1]:.6g} K, "
          f"{len(res.events)} events")
