"""Lumped heat transfer: capacities, conductors, convection, boundary conditions."""
from .components import Convection, HeatCapacitor, ThermalConductor, ThermalResistor
from .interfaces import Element1D, PartialElementaryOnePort
from .sensors import HeatFlowSensor, TemperatureSensor
from .sources import FixedHeatFlow, FixedTemperature, PrescribedHeatFlow, PrescribedTemperature

__all__ = ["Element1D", "PartialElementaryOnePort", "HeatCapacitor", "ThermalConductor",
           "ThermalResistor", "Convection", "FixedTemperature", "PrescribedTemperature",
           "FixedHeatFlow", "PrescribedHeatFlow", "TemperatureSensor", "HeatFlowSensor"]
