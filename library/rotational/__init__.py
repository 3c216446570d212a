"""1-D rotational mechanics."""
from .components import Damper, Fixed, IdealGear, Inertia, Spring, SpringDamper
from .interfaces import PartialCompliant, PartialElementaryOneFlange, PartialTwoFlanges
from .sources import ConstantTorque

__all__ = ["PartialTwoFlanges", "PartialCompliant", "PartialElementaryOneFlange", "Fixed",
           "Inertia", "Spring", "Damper", "SpringDamper", "IdealGear", "ConstantTorque"]
