"""Rotational components (Modelica.Mechanics.Rotational.Components; Egeland & Gravdahl 3.2)."""
import acausal as ac
from acausal.ports import RotationalFlange

from .interfaces import PartialCompliant, PartialElementaryOneFlange, PartialTwoFlanges

__all__ = ["Fixed", "Inertia", "Spring", "Damper", "SpringDamper", "IdealGear"]


class Fixed(PartialElementaryOneFlange):
    """Flange fixed in the housing:  flange.phi = phi0."""

    phi0 = ac.Parameter(0.0, unit="rad", description="fixed angle of the housing")

    def equations(self):
        return [ac.Eq(self.flange.phi, self.phi0)]


class Inertia(PartialTwoFlanges):
    """Rotating mass (Egeland & Gravdahl (3.30)):

        phi = flange_a.phi = flange_b.phi,   w = der(phi),
        J der(w) = flange_a.tau + flange_b.tau
    """

    J = ac.Parameter(1.0, unit="kg.m2", min=0, description="moment of inertia")
    phi = ac.Variable(start=0.0, unit="rad", description="absolute rotation angle")
    w = ac.Variable(start=0.0, unit="rad/s", description="absolute angular velocity")
    a = ac.Variable(unit="rad/s2", description="absolute angular acceleration")

    def equations(self):
        return [ac.Eq(self.phi, self.flange_a.phi),
                ac.Eq(self.phi, self.flange_b.phi),
                ac.Eq(self.w, ac.der(self.phi)),
                ac.Eq(self.a, ac.der(self.w)),
                ac.Eq(self.J * self.a, self.flange_a.tau + self.flange_b.tau)]


class Spring(PartialCompliant):
    """Linear torsional spring:  tau = c (phi_rel - phi_rel0)."""

    c = ac.Parameter(1.0e5, unit="N.m/rad", min=0, description="spring constant")
    phi_rel0 = ac.Parameter(0.0, unit="rad", description="unstretched spring angle")

    def equations(self):
        return [*super().equations(), ac.Eq(self.tau, self.c * (self.phi_rel - self.phi_rel0))]


class Damper(PartialCompliant):
    """Linear torsional damper:  tau = d der(phi_rel)."""

    d = ac.Parameter(0.0, unit="N.m.s/rad", min=0, description="damping constant")

    def equations(self):
        return [*super().equations(), ac.Eq(self.tau, self.d * ac.der(self.phi_rel))]


class SpringDamper(PartialCompliant):
    """Spring and damper in parallel:  tau = c (phi_rel - phi_rel0) + d der(phi_rel)."""

    c = ac.Parameter(1.0e5, unit="N.m/rad", min=0, description="spring constant")
    d = ac.Parameter(0.0, unit="N.m.s/rad", min=0, description="damping constant")
    phi_rel0 = ac.Parameter(0.0, unit="rad", description="unstretched spring angle")

    def equations(self):
        return [*super().equations(),
                ac.Eq(self.tau, self.c * (self.phi_rel - self.phi_rel0)
                      + self.d * ac.der(self.phi_rel))]


class IdealGear(PartialTwoFlanges):
    """Ideal gear without inertia (Egeland & Gravdahl 3.2.3, (3.1)-(3.4)):

        flange_a.phi = n flange_b.phi,   0 = n flange_a.tau + flange_b.tau

    With both flanges on inertias this is a position constraint between two states:
    index 3, which index reduction handles.
    """

    n = ac.Parameter(1.0, description="gear ratio flange_a.phi / flange_b.phi")

    def equations(self):
        return [ac.Eq(self.flange_a.phi, self.n * self.flange_b.phi),
                ac.Eq(0, self.n * self.flange_a.tau + self.flange_b.tau)]
