"""Partial models of 1-D rotational mechanics (Modelica.Mechanics.Rotational.Interfaces).

Flanges carry the absolute angle phi and the cut torque tau (positive into the
component), so rigid couplings are position constraints.
"""
import acausal as ac
from acausal.ports import RotationalFlange, TranslationalFlange

__all__ = ["PartialTwoFlanges", "PartialCompliant", "PartialElementaryOneFlange",
           "PartialAbsoluteSensor", "PartialRelativeSensor",
           "PartialElementaryRotationalToTranslational"]


class PartialTwoFlanges(ac.Component):
    """Two flanges, flange_a and flange_b."""

    flange_a = RotationalFlange()
    flange_b = RotationalFlange()


class PartialCompliant(PartialTwoFlanges):
    """A compliant connection (spring, damper):

        phi_rel = flange_b.phi - flange_a.phi,   flange_b.tau = tau,   flange_a.tau = -tau
    """

    phi_rel = ac.Variable(start=0.0, unit="rad", description="relative rotation angle")
    tau = ac.Variable(unit="N.m", description="torque between the flanges")

    def equations(self):
        return [ac.Eq(self.phi_rel, self.flange_b.phi - self.flange_a.phi),
                ac.Eq(self.flange_b.tau, self.tau),
                ac.Eq(self.flange_a.tau, -self.tau)]


class PartialElementaryOneFlange(ac.Component):
    """One flange, named flange."""

    flange = RotationalFlange()


class PartialAbsoluteSensor(PartialElementaryOneFlange):
    """Measures an absolute quantity of one flange and exerts no torque:  flange.tau = 0."""

    energy_role = "lossless"  # an ideal sensor takes no power

    def equations(self):
        return [ac.Eq(self.flange.tau, 0)]


class PartialRelativeSensor(PartialTwoFlanges):
    """Measures between two flanges and is torque-free as a whole:

        0 = flange_a.tau + flange_b.tau
    """

    energy_role = "lossless"  # an ideal sensor takes no power

    def equations(self):
        return [ac.Eq(0, self.flange_a.tau + self.flange_b.tau)]


class PartialElementaryRotationalToTranslational(ac.Component):
    """A rotational flange flangeR and a translational flange flangeT (an ideal,
    massless converter between the two domains)."""

    flangeR = RotationalFlange()
    flangeT = TranslationalFlange()
