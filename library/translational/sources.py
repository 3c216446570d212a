"""Force sources (Modelica.Mechanics.Translational.Sources)."""
import acausal as ac

from .interfaces import PartialElementaryOneFlange

__all__ = ["ConstantForce"]


class ConstantForce(PartialElementaryOneFlange):
    """Constant force pushing the flange in +s:  flange.f = -f_constant."""

    f_constant = ac.Parameter(1.0, unit="N", description="driving force")

    def equations(self):
        return [ac.Eq(self.flange.f, -self.f_constant)]
