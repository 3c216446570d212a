"""Partial models of 1-D translational mechanics (Modelica.Mechanics.Translational)."""
import acausal as ac
from acausal.ports import TranslationalFlange

__all__ = ["PartialTwoFlanges", "PartialCompliant", "PartialElementaryOneFlange",
           "PartialAbsoluteSensor", "PartialRelativeSensor"]


class PartialTwoFlanges(ac.Component):
    """Two flanges, flange_a and flange_b."""

    flange_a = TranslationalFlange()
    flange_b = TranslationalFlange()


class PartialCompliant(PartialTwoFlanges):
    """A compliant connection (spring, damper):

        s_rel = flange_b.s - flange_a.s,   flange_b.f = f,   flange_a.f = -f
    """

    s_rel = ac.Variable(start=0.0, unit="m", description="relative distance")
    f = ac.Variable(unit="N", description="force between the flanges")

    def equations(self):
        return [ac.Eq(self.s_rel, self.flange_b.s - self.flange_a.s),
                ac.Eq(self.flange_b.f, self.f),
                ac.Eq(self.flange_a.f, -self.f)]


class PartialElementaryOneFlange(ac.Component):
    """One flange, named flange."""

    flange = TranslationalFlange()


class PartialAbsoluteSensor(PartialElementaryOneFlange):
    """Measures an absolute quantity of one flange and exerts no force:  flange.f = 0."""

    energy_role = "lossless"  # an ideal sensor takes no power

    def equations(self):
        return [ac.Eq(self.flange.f, 0)]


class PartialRelativeSensor(PartialTwoFlanges):
    """Measures between two flanges and is force-free as a whole:  0 = flange_a.f + flange_b.f."""

    energy_role = "lossless"  # an ideal sensor takes no power

    def equations(self):
        return [ac.Eq(0, self.flange_a.f + self.flange_b.f)]
