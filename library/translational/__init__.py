"""1-D translational mechanics."""
from .components import Damper, Fixed, Mass, Spring, SpringDamper
from .interfaces import PartialCompliant, PartialElementaryOneFlange, PartialTwoFlanges
from .sources import ConstantForce

__all__ = ["PartialTwoFlanges", "PartialCompliant", "PartialElementaryOneFlange", "Fixed",
           "Mass", "Spring", "Damper", "SpringDamper", "ConstantForce"]
