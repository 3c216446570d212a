"""Electromechanical converters and motors (Egeland & Gravdahl ch. 3)."""
from .motors import EMF, CurrentControlledDCMotor, DCMotor

__all__ = ["EMF", "DCMotor", "CurrentControlledDCMotor"]
