"""Lumped heat transfer (Modelica.Thermal.HeatTransfer): capacities, conductors,
convection, boundary conditions, sensors, the Celsius helpers (``thermal.celsius``) and
the signal adaptors of a heat port."""
from ... import _lazy_exports

__all__ = ["Element1D", "PartialElementaryOnePort", "HeatCapacitor", "ThermalConductor",
           "ThermalResistor", "Convection", "ConvectiveResistor", "ThermalCollector",
           "FixedTemperature", "PrescribedTemperature", "FixedHeatFlow", "PrescribedHeatFlow",
           "TemperatureSensor", "RelTemperatureSensor", "HeatFlowSensor",
           "GeneralHeatFlowToTemperatureAdaptor", "GeneralTemperatureToHeatFlowAdaptor",
           "PartialElementaryConditionalHeatPort",
           "PartialElementaryConditionalHeatPortWithoutT", "PartialConditionalHeatPort"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".adaptors": ("GeneralHeatFlowToTemperatureAdaptor", "GeneralTemperatureToHeatFlowAdaptor"),
    ".components": ("Convection", "ConvectiveResistor", "HeatCapacitor", "ThermalCollector",
                    "ThermalConductor", "ThermalResistor"),
    ".interfaces": ("Element1D", "PartialElementaryOnePort"),
    ".conditional": ("PartialElementaryConditionalHeatPort",
                     "PartialElementaryConditionalHeatPortWithoutT",
                     "PartialConditionalHeatPort"),
    ".sensors": ("HeatFlowSensor", "RelTemperatureSensor", "TemperatureSensor"),
    ".sources": ("FixedHeatFlow", "FixedTemperature", "PrescribedHeatFlow",
                 "PrescribedTemperature"),
}, submodules=("celsius",))
