"""Friction (Egeland & Gravdahl ch. 5): static, Karnopp stick-slip and dynamic models,
for translational and rotational flanges."""
from . import laws, rotational, translational
from .interfaces import PartialRotationalFriction, PartialTranslationalFriction

__all__ = ["laws", "translational", "rotational", "PartialTranslationalFriction",
           "PartialRotationalFriction"]
