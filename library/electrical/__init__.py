"""Electrical domain: pins, one-ports, basic components, sources and sensors."""
from .basic import (Capacitor, Ground, HeatingResistor, IdealClosingSwitch, IdealOpAmp,
                    IdealOpeningSwitch, IdealTransformer, Inductor, Resistor)
from .interfaces import OnePort, TwoPin, TwoPort
from .semiconductors import Diode, IdealDiode
from .sensors import CurrentSensor, PotentialSensor, PowerSensor, VoltageSensor
from .sources import (ConstantCurrent, ConstantVoltage, PulseCurrent, PulseVoltage,
                      RampCurrent, RampVoltage, SignalCurrent, SignalVoltage, SineCurrent,
                      SineVoltage, StepCurrent, StepVoltage)

__all__ = ["OnePort", "TwoPin", "TwoPort", "Ground", "Resistor", "Capacitor", "Inductor",
           "HeatingResistor", "IdealTransformer", "IdealOpAmp", "IdealClosingSwitch",
           "IdealOpeningSwitch", "Diode", "IdealDiode",
           "ConstantVoltage", "StepVoltage", "RampVoltage", "SineVoltage", "PulseVoltage",
           "SignalVoltage", "ConstantCurrent", "StepCurrent", "RampCurrent", "SineCurrent",
           "PulseCurrent", "SignalCurrent", "PotentialSensor", "VoltageSensor",
           "CurrentSensor", "PowerSensor"]
