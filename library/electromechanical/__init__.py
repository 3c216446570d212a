"""Electromechanical converters and motors (Egeland & Gravdahl ch. 3)."""
from ... import _lazy_exports

__all__ = ["EMF", "DCMotor", "CurrentControlledDCMotor"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".motors": ("EMF", "CurrentControlledDCMotor", "DCMotor"),
})
