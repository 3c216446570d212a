"""Hydraulics (Egeland & Gravdahl ch. 4): volumes, orifices, valves, motors, pumps,
cylinders and transmission lines."""
from .components import (Cylinder, HydraulicMotor, LaminarOrifice, PistonVolume, Pump,
                         ReliefValve, SingleActingCylinder, TurbulentOrifice, VariableOrifice,
                         VariablePump, Volume)
from .interfaces import F_tr, PartialOnePort, PartialTwoPort, orifice_flow
from .lines import LumpedLine, ModalLine
from .sensors import FlowSensor, PressureSensor, RelativePressureSensor
from .sources import ConstantFlow, FixedPressure, FlowSource, PressureSource
from .valves import (BalanceValve, CriticalCentreValve, FourWayValve, OpenCentreValve,
                     PressureCompensatedValve)

__all__ = ["PartialOnePort", "PartialTwoPort", "F_tr", "orifice_flow", "Volume",
           "PistonVolume", "LaminarOrifice", "TurbulentOrifice", "VariableOrifice", "ReliefValve",
           "HydraulicMotor", "Pump", "VariablePump", "Cylinder", "SingleActingCylinder",
           "FourWayValve", "CriticalCentreValve", "OpenCentreValve",
           "PressureCompensatedValve", "BalanceValve", "FixedPressure", "PressureSource",
           "ConstantFlow", "FlowSource", "PressureSensor", "RelativePressureSensor",
           "FlowSensor", "LumpedLine", "ModalLine"]
