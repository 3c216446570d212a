"""Rotational examples."""
from .backlash import GearWithDeadzone
from .rack_and_pinion import RackAndPinionDrive

__all__ = ["RackAndPinionDrive", "GearWithDeadzone"]
