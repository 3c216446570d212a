"""Electrical domain: pins, one-ports, basic components, sources and sensors."""
from ... import _lazy_exports

__all__ = ["OnePort", "TwoPin", "TwoPort", "ConditionalHeatPort", "Ground", "Resistor", "Conductor", "Capacitor",
           "Inductor", "HeatingResistor", "VariableResistor", "VariableConductor",
           "VariableCapacitor", "VariableInductor", "Potentiometer", "Transformer",
           "Gyrator", "IdealTransformer", "VCV", "VCC", "CCV", "CCC", "IdealOpAmp",
           "IdealClosingSwitch", "IdealOpeningSwitch", "Diode", "IdealDiode",
           "ConstantVoltage", "StepVoltage", "RampVoltage", "SineVoltage", "CosineVoltage",
           "ExpSineVoltage", "PulseVoltage", "TrapezoidVoltage",
           "SignalVoltage", "ConstantCurrent", "StepCurrent", "RampCurrent", "SineCurrent",
           "PulseCurrent", "SignalCurrent", "PotentialSensor", "VoltageSensor",
           "CurrentSensor", "PowerSensor"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".basic": ("Capacitor", "Conductor", "Ground", "Gyrator", "HeatingResistor",
               "IdealClosingSwitch", "IdealOpAmp", "IdealOpeningSwitch", "IdealTransformer",
               "Inductor", "Potentiometer", "Resistor", "Transformer", "VariableCapacitor",
               "VariableConductor", "VariableInductor", "VariableResistor"),
    ".controlled": ("CCC", "CCV", "VCC", "VCV"),
    ".interfaces": ("OnePort", "TwoPin", "TwoPort", "ConditionalHeatPort"),
    ".semiconductors": ("Diode", "IdealDiode"),
    ".sensors": ("CurrentSensor", "PotentialSensor", "PowerSensor", "VoltageSensor"),
    ".sources": ("ConstantCurrent", "ConstantVoltage", "CosineVoltage", "ExpSineVoltage",
                 "PulseCurrent", "PulseVoltage",
                 "RampCurrent", "RampVoltage", "SignalCurrent", "SignalVoltage",
                 "SineCurrent", "SineVoltage", "StepCurrent", "StepVoltage",
                 "TrapezoidVoltage"),
})
