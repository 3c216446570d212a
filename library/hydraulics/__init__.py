"""Hydraulics (Egeland & Gravdahl ch. 4): volumes, orifices, valves, motors, pumps,
cylinders and transmission lines."""
from ... import _lazy_exports

__all__ = ["PartialOnePort", "PartialTwoPort", "F_tr", "orifice_flow", "Volume",
           "PistonVolume", "LaminarOrifice", "TurbulentOrifice", "VariableOrifice", "ReliefValve",
           "HydraulicMotor", "Pump", "VariablePump", "Cylinder", "SingleActingCylinder",
           "FourWayValve", "CriticalCentreValve", "OpenCentreValve",
           "PressureCompensatedValve", "BalanceValve", "FixedPressure", "PressureSource",
           "ConstantFlow", "FlowSource", "PressureSensor", "RelativePressureSensor",
           "FlowSensor", "LumpedLine", "ModalLine"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".components": ("Cylinder", "HydraulicMotor", "LaminarOrifice", "PistonVolume", "Pump",
                    "ReliefValve", "SingleActingCylinder", "TurbulentOrifice",
                    "VariableOrifice", "VariablePump", "Volume"),
    ".interfaces": ("F_tr", "PartialOnePort", "PartialTwoPort", "orifice_flow"),
    ".lines": ("LumpedLine", "ModalLine"),
    ".sensors": ("FlowSensor", "PressureSensor", "RelativePressureSensor"),
    ".sources": ("ConstantFlow", "FixedPressure", "FlowSource", "PressureSource"),
    ".valves": ("BalanceValve", "CriticalCentreValve", "FourWayValve", "OpenCentreValve",
                "PressureCompensatedValve"),
})
