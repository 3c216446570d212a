"""Thermal examples."""
from .heated_resistor import HeatedResistor

__all__ = ["HeatedResistor"]
