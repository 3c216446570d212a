"""Hydraulics (Egeland & Gravdahl ch. 4, 11.2.9): volumes, orifices, valves, motors,
pumps, cylinders, transmission lines, and a penstock with a Pelton turbine."""
from ... import _lazy_exports

__all__ = ["PartialOnePort", "PartialTwoPort", "F_tr", "orifice_flow", "Volume",
           "PistonVolume", "LaminarOrifice", "TurbulentOrifice", "VariableOrifice", "ReliefValve",
           "HydraulicMotor", "Pump", "VariablePump", "Cylinder", "SingleActingCylinder",
           "FourWayValve", "CriticalCentreValve", "OpenCentreValve",
           "PressureCompensatedValve", "BalanceValve", "FixedPressure", "PressureSource",
           "ConstantFlow", "FlowSource", "PressureSensor", "RelativePressureSensor",
           "FlowSensor", "LumpedLine", "ModalLine", "Penstock", "PeltonTurbine"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".components": ("Cylinder", "HydraulicMotor", "LaminarOrifice", "PistonVolume", "Pump",
                    "ReliefValve", "SingleActingCylinder", "TurbulentOrifice",
                    "VariableOrifice", "VariablePump", "Volume"),
    ".interfaces": ("F_tr", "PartialOnePort", "PartialTwoPort", "orifice_flow"),
    ".lines": ("LumpedLine", "ModalLine"),
    ".sensors": ("FlowSensor", "PressureSensor", "RelativePressureSensor"),
    ".sources": ("ConstantFlow", "FixedPressure", "FlowSource", "PressureSource"),
    ".turbines": ("PeltonTurbine", "Penstock"),
    ".valves": ("BalanceValve", "CriticalCentreValve", "FourWayValve", "OpenCentreValve",
                "PressureCompensatedValve"),
})
