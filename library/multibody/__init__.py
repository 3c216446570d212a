"""Planar multibody mechanics (shaped like Modelica PlanarMechanics)."""
from .forces import Damper, Spring, SpringDamper
from .interfaces import PartialLineForce, PartialOneFrame, PartialTwoFrames
from .joints import Prismatic, Revolute
from .parts import Body, FixedFrame, FixedTranslation

__all__ = ["PartialOneFrame", "PartialTwoFrames", "PartialLineForce", "FixedFrame", "Body",
           "FixedTranslation", "Revolute", "Prismatic", "Spring", "Damper", "SpringDamper"]
