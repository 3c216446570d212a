"""Electromechanical converters and motors (Egeland & Gravdahl ch. 3)."""
from .motors import EMF, DCMotor

__all__ = ["EMF", "DCMotor"]
