"""Electrical domain: pins, one-ports, basic components and sources."""
from .basic import Capacitor, Ground, Inductor, Resistor
from .interfaces import OnePort, TwoPin
from .sources import ConstantCurrent, ConstantVoltage, SineVoltage, StepVoltage

__all__ = ["OnePort", "TwoPin", "Ground", "Resistor", "Capacitor", "Inductor",
           "ConstantVoltage", "StepVoltage", "SineVoltage", "ConstantCurrent"]
