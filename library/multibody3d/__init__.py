"""Spatial multibody mechanics (shaped like Modelica.Mechanics.MultiBody).  See the
module docstring of ``acausal.ports.spatial`` and the library guide for how the
overdetermined orientation is carried."""
from ... import _lazy_exports

__all__ = ["World", "Body", "BodyBox", "BodyCylinder", "FixedTranslation", "FixedRotation",
           "Revolute", "Prismatic", "Spherical", "FreeMotion", "Universal", "Spring", "Damper",
           "SpringDamper", "WorldForce", "WorldTorque", "AbsolutePosition",
           "AbsoluteVelocity", "AbsoluteAngularVelocity", "RelativePosition",
           "CutForceAndTorque"]

__getattr__, __dir__ = _lazy_exports(globals(), {
    ".parts": ("World", "Body", "BodyBox", "BodyCylinder", "FixedTranslation",
               "FixedRotation"),
    ".joints": ("Revolute", "Prismatic", "Spherical", "FreeMotion", "Universal"),
    ".forces": ("Spring", "Damper", "SpringDamper", "WorldForce", "WorldTorque"),
    ".sensors": ("AbsolutePosition", "AbsoluteVelocity", "AbsoluteAngularVelocity",
                 "RelativePosition", "CutForceAndTorque"),
}, submodules=("frames", "interfaces"))
