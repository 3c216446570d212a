"""Temperatures in degree Celsius (Modelica.Thermal.HeatTransfer.Celsius, MSL v4.0.0).

The classes keep the MSL's names, so they are used through the module, as the MSL's
package: ``celsius.TemperatureSensor()`` beside the Kelvin ``TemperatureSensor``.
The conversion is Modelica.Units.Conversions' ``to_degC``/``from_degC``:

    T_degC = T_K - 273.15
"""
import acausal as ac
from acausal.ports import RealInput, RealOutput

from .interfaces import PartialElementaryOnePort

__all__ = ["TemperatureSensor", "FixedTemperature", "PrescribedTemperature", "ToKelvin",
           "FromKelvin", "ZERO_CELSIUS"]

ZERO_CELSIUS = 273.15   # K, 0 degC (Modelica.Constants.T_zero = -273.15 degC)


class TemperatureSensor(PartialElementaryOnePort):
    """Absolute temperature in degC (Modelica.Thermal.HeatTransfer.Celsius.
    TemperatureSensor):

        T = port.T - 273.15,   port.Q_flow = 0
    """

    T = RealOutput()

    energy_role = "lossless"  # an ideal sensor takes no heat

    def equations(self):
        return [ac.Eq(self.T, self.port.T - ZERO_CELSIUS), ac.Eq(self.port.Q_flow, 0)]


class FixedTemperature(PartialElementaryOnePort):
    """Fixed temperature in degC (Modelica.Thermal.HeatTransfer.Celsius.FixedTemperature):

        port.T = T + 273.15
    """

    T = ac.Parameter(20.0, unit="degC",
                     description="fixed temperature at the port")

    energy_role = "source"  # an environment outside the model

    def equations(self):
        return [ac.Eq(self.port.T, self.T + ZERO_CELSIUS)]


class PrescribedTemperature(PartialElementaryOnePort):
    """Temperature in degC set by a signal (Modelica.Thermal.HeatTransfer.Celsius.
    PrescribedTemperature):

        port.T = T + 273.15
    """

    T = RealInput()

    energy_role = "source"  # an environment outside the model

    def equations(self):
        return [ac.Eq(self.port.T, self.T + ZERO_CELSIUS)]


class ToKelvin(ac.Component):
    """degC to K (Modelica.Thermal.HeatTransfer.Celsius.ToKelvin):
    Kelvin = Celsius + 273.15."""

    Celsius = RealInput()
    Kelvin = RealOutput()

    def equations(self):
        return [ac.Eq(self.Kelvin, self.Celsius + ZERO_CELSIUS)]


class FromKelvin(ac.Component):
    """K to degC (Modelica.Thermal.HeatTransfer.Celsius.FromKelvin):
    Celsius = Kelvin - 273.15."""

    Kelvin = RealInput()
    Celsius = RealOutput()

    def equations(self):
        return [ac.Eq(self.Celsius, self.Kelvin - ZERO_CELSIUS)]
