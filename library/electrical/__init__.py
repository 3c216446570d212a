"""Electrical domain: pins, one-ports, basic components, sources and sensors."""
from .basic import (Capacitor, Ground, HeatingResistor, IdealOpAmp, IdealTransformer,
                    Inductor, Resistor)
from .interfaces import OnePort, TwoPin, TwoPort
from .semiconductors import Diode
from .sensors import CurrentSensor, PotentialSensor, PowerSensor, VoltageSensor
from .sources import (ConstantCurrent, ConstantVoltage, PulseCurrent, PulseVoltage,
                      RampCurrent, RampVoltage, SignalCurrent, SignalVoltage, SineCurrent,
                      SineVoltage, StepCurrent, StepVoltage)

__all__ = ["OnePort", "TwoPin", "TwoPort", "Ground", "Resistor", "Capacitor", "Inductor",
           "HeatingResistor", "IdealTransformer", "IdealOpAmp", "Diode",
           "ConstantVoltage", "StepVoltage", "RampVoltage", "SineVoltage", "PulseVoltage",
           "SignalVoltage", "ConstantCurrent", "StepCurrent", "RampCurrent", "SineCurrent",
           "PulseCurrent", "SignalCurrent", "PotentialSensor", "VoltageSensor",
           "CurrentSensor", "PowerSensor"]
