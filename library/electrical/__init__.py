"""Electrical domain: pins, one-ports, basic components, sources and sensors."""
from ... import _lazy_exports

__all__ = ["OnePort", "TwoPin", "TwoPort", "Ground", "Resistor", "Capacitor", "Inductor",
           "HeatingResistor", "IdealTransformer", "IdealOpAmp", "IdealClosingSwitch",
           "IdealOpeningSwitch", "Diode", "IdealDiode",
           "ConstantVoltage", "StepVoltage", "RampVoltage", "SineVoltage", "PulseVoltage",
           "SignalVoltage", "ConstantCurrent", "StepCurrent", "RampCurrent", "SineCurrent",
           "PulseCurrent", "SignalCurrent", "PotentialSensor", "VoltageSensor",
           "CurrentSensor", "PowerSensor"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".basic": ("Capacitor", "Ground", "HeatingResistor", "IdealClosingSwitch",
               "IdealOpAmp", "IdealOpeningSwitch", "IdealTransformer", "Inductor",
               "Resistor"),
    ".interfaces": ("OnePort", "TwoPin", "TwoPort"),
    ".semiconductors": ("Diode", "IdealDiode"),
    ".sensors": ("CurrentSensor", "PotentialSensor", "PowerSensor", "VoltageSensor"),
    ".sources": ("ConstantCurrent", "ConstantVoltage", "PulseCurrent", "PulseVoltage",
                 "RampCurrent", "RampVoltage", "SignalCurrent", "SignalVoltage",
                 "SineCurrent", "SineVoltage", "StepCurrent", "StepVoltage"),
})
