"""Planar multibody mechanics (shaped like Modelica PlanarMechanics)."""
from .forces import Damper, Rod, Spring, SpringDamper
from .interfaces import PartialLineForce, PartialOneFrame, PartialTwoFrames
from .joints import Prismatic, Revolute
from .parts import Body, FixedFrame, FixedTranslation, PointMass

__all__ = ["PartialOneFrame", "PartialTwoFrames", "PartialLineForce", "FixedFrame", "Body",
           "PointMass", "FixedTranslation", "Revolute", "Prismatic", "Rod", "Spring", "Damper",
           "SpringDamper"]
