"""Simple incompressible coolant flows with heat transport (Modelica.Thermal.
FluidHeatFlow): a ``FlowPort`` carries pressure, mass flow, specific enthalpy and
enthalpy flow; pipes, valves, tanks and cylinders, ambients, pumps and sensors; media
records (``media``).  The library guide says how enthalpy is carried at a flow reversal."""
from ... import _lazy_exports

__all__ = ["Medium", "Water", "Water_10degC", "Water_90degC", "Air_30degC", "Air_70degC",
           "Gylcol20_20degC", "Gylcol50_20degC", "MineralOil", "TwoPort", "SinglePort",
           "SimpleFriction", "semi_linear", "Pipe", "HeatedPipe", "Valve", "OneWayValve",
           "OpenTank", "Cylinder", "Ambient", "AbsolutePressure", "VolumeFlow",
           "PressureIncrease", "IdealPump", "PressureSensor", "TemperatureSensor",
           "RelPressureSensor", "RelTemperatureSensor", "MassFlowSensor",
           "VolumeFlowSensor", "EnthalpyFlowSensor"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".media": ("Medium", "Water", "Water_10degC", "Water_90degC", "Air_30degC",
               "Air_70degC", "Gylcol20_20degC", "Gylcol50_20degC", "MineralOil"),
    ".base_classes": ("TwoPort", "SinglePort", "SimpleFriction", "semi_linear"),
    ".components": ("Pipe", "HeatedPipe", "Valve", "OneWayValve", "OpenTank", "Cylinder"),
    ".sources": ("Ambient", "AbsolutePressure", "VolumeFlow", "PressureIncrease",
                 "IdealPump"),
    ".sensors": ("PressureSensor", "TemperatureSensor", "RelPressureSensor",
                 "RelTemperatureSensor", "MassFlowSensor", "VolumeFlowSensor",
                 "EnthalpyFlowSensor"),
})
