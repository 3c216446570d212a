"""Friction (Egeland & Gravdahl ch. 5): static, Karnopp stick-slip and dynamic models,
for translational and rotational flanges."""
from ... import _lazy_exports

__all__ = ["laws", "translational", "rotational", "PartialTranslationalFriction",
           "PartialRotationalFriction"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".interfaces": ("PartialRotationalFriction", "PartialTranslationalFriction"),
}, submodules=("laws", "rotational", "translational"))
