"""Translational components (Egeland & Gravdahl 2.1.2: the mass-spring-damper)."""
import acausal as ac

from .interfaces import PartialCompliant, PartialElementaryOneFlange, PartialTwoFlanges

__all__ = ["Fixed", "Mass", "Spring", "Damper", "SpringDamper"]


class Fixed(PartialElementaryOneFlange):
    """Flange fixed in the housing:  flange.s = s0."""

    s0 = ac.Parameter(0.0, unit="m", description="fixed position of the housing")

    def equations(self):
        return [ac.Eq(self.flange.s, self.s0)]


class Mass(PartialTwoFlanges):
    """Sliding mass (Newton's second law):

        s = flange_a.s = flange_b.s,   v = der(s),   m der(v) = flange_a.f + flange_b.f
    """

    m = ac.Parameter(1.0, unit="kg", min=0, description="mass")
    s = ac.Variable(start=0.0, unit="m", description="absolute position")
    v = ac.Variable(start=0.0, unit="m/s", description="absolute velocity")
    a = ac.Variable(unit="m/s2", description="absolute acceleration")

    def equations(self):
        return [ac.Eq(self.s, self.flange_a.s),
                ac.Eq(self.s, self.flange_b.s),
                ac.Eq(self.v, ac.der(self.s)),
                ac.Eq(self.a, ac.der(self.v)),
                ac.Eq(self.m * self.a, self.flange_a.f + self.flange_b.f)]


class Spring(PartialCompliant):
    """Linear spring:  f = c (s_rel - s_rel0)."""

    c = ac.Parameter(1.0, unit="N/m", min=0, description="spring constant")
    s_rel0 = ac.Parameter(0.0, unit="m", description="unstretched length")

    def equations(self):
        return [*super().equations(), ac.Eq(self.f, self.c * (self.s_rel - self.s_rel0))]


class Damper(PartialCompliant):
    """Linear damper:  f = d der(s_rel)."""

    d = ac.Parameter(0.0, unit="N.s/m", min=0, description="damping constant")

    def equations(self):
        return [*super().equations(), ac.Eq(self.f, self.d * ac.der(self.s_rel))]


class SpringDamper(PartialCompliant):
    """Spring and damper in parallel:  f = c (s_rel - s_rel0) + d der(s_rel)."""

    c = ac.Parameter(1.0, unit="N/m", min=0, description="spring constant")
    d = ac.Parameter(0.0, unit="N.s/m", min=0, description="damping constant")
    s_rel0 = ac.Parameter(0.0, unit="m", description="unstretched length")

    def equations(self):
        return [*super().equations(),
                ac.Eq(self.f, self.c * (self.s_rel - self.s_rel0) + self.d * ac.der(self.s_rel))]
