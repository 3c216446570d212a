"""Translational examples."""
from .mass_spring_damper import MassSpringDamper

__all__ = ["MassSpringDamper"]
