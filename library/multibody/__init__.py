"""Planar multibody mechanics (shaped like Modelica PlanarMechanics)."""
from ... import _lazy_exports

__all__ = ["PartialOneFrame", "PartialTwoFrames", "PartialLineForce", "FixedFrame", "Body",
           "PointMass", "FixedTranslation", "Revolute", "Prismatic", "Rod", "Spring", "Damper",
           "SpringDamper"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".forces": ("Damper", "Rod", "Spring", "SpringDamper"),
    ".interfaces": ("PartialLineForce", "PartialOneFrame", "PartialTwoFrames"),
    ".joints": ("Prismatic", "Revolute"),
    ".parts": ("Body", "FixedFrame", "FixedTranslation", "PointMass"),
})
