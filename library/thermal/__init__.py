"""Lumped heat transfer: capacities, conductors, convection, boundary conditions."""
from ... import _lazy_exports

__all__ = ["Element1D", "PartialElementaryOnePort", "HeatCapacitor", "ThermalConductor",
           "ThermalResistor", "Convection", "FixedTemperature", "PrescribedTemperature",
           "FixedHeatFlow", "PrescribedHeatFlow", "TemperatureSensor", "HeatFlowSensor",
           "PartialElementaryConditionalHeatPort",
           "PartialElementaryConditionalHeatPortWithoutT", "PartialConditionalHeatPort"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".components": ("Convection", "HeatCapacitor", "ThermalConductor", "ThermalResistor"),
    ".interfaces": ("Element1D", "PartialElementaryOnePort"),
    ".conditional": ("PartialElementaryConditionalHeatPort",
                     "PartialElementaryConditionalHeatPortWithoutT",
                     "PartialConditionalHeatPort"),
    ".sensors": ("HeatFlowSensor", "TemperatureSensor"),
    ".sources": ("FixedHeatFlow", "FixedTemperature", "PrescribedHeatFlow",
                 "PrescribedTemperature"),
})
