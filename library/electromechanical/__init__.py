"""Electromechanical converters and motors: the DC motor of Egeland & Gravdahl ch. 3
(``motors``), and the MSL's machines with their losses (``machines``,
Modelica.Electrical.Machines)."""
from ... import _lazy_exports

__all__ = ["EMF", "DCMotor", "CurrentControlledDCMotor"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".motors": ("EMF", "CurrentControlledDCMotor", "DCMotor"),
}, submodules=("machines",))
