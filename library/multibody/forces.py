"""Force elements between two frames, along the line through their origins (Modelica
PlanarMechanics.Parts.Spring / Damper without their rotational part)."""
import acausal as ac

from .interfaces import PartialLineForce

__all__ = ["Spring", "Damper", "SpringDamper"]


class Spring(PartialLineForce):
    """Linear spring:  f = c (s - s_unstretched)."""

    c = ac.Parameter(1.0e3, unit="N/m", min=0, description="spring constant")
    s_unstretched = ac.Parameter(0.0, unit="m", min=0, description="unstretched length")

    def equations(self):
        return [*super().equations(), ac.Eq(self.f, self.c * (self.s - self.s_unstretched))]


class Damper(PartialLineForce):
    """Linear damper:  f = d der(s)."""

    d = ac.Parameter(1.0, unit="N.s/m", min=0, description="damping constant")

    def equations(self):
        return [*super().equations(), ac.Eq(self.f, self.d * ac.der(self.s))]


class SpringDamper(PartialLineForce):
    """Spring and damper in parallel:  f = c (s - s_unstretched) + d der(s)."""

    c = ac.Parameter(1.0e3, unit="N/m", min=0, description="spring constant")
    d = ac.Parameter(1.0, unit="N.s/m", min=0, description="damping constant")
    s_unstretched = ac.Parameter(0.0, unit="m", min=0, description="unstretched length")

    def equations(self):
        return [*super().equations(),
                ac.Eq(self.f, self.c * (self.s - self.s_unstretched) + self.d * ac.der(self.s))]
