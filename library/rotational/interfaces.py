"""Partial models of 1-D rotational mechanics (Modelica.Mechanics.Rotational.Interfaces).

Flanges carry the absolute angle phi and the cut torque tau (positive into the
component), so rigid couplings are position constraints.
"""
import acausal as ac
from acausal.ports import RotationalFlange, TranslationalFlange

from ..relative_states import RelativeStatesMixin

__all__ = ["PartialTwoFlanges", "PartialCompliant", "PartialCompliantWithRelativeStates",
           "PartialElementaryOneFlange",
           "PartialAbsoluteSensor", "PartialRelativeSensor",
           "PartialElementaryOneFlangeAndSupport", "PartialElementaryTwoFlangesAndSupport",
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


class PartialCompliantWithRelativeStates(RelativeStatesMixin, PartialTwoFlanges):
    """A compliant connection whose relative angle and speed may be chosen as states
    (MSL PartialCompliantWithRelativeStates):

        phi_rel = flange_b.phi - flange_a.phi,   w_rel = der(phi_rel),
        flange_b.tau = tau,   flange_a.tau = -tau
        acc.a_rel = der(w_rel)          (only with stateSelect "prefer" or "always")

    ``stateSelect`` is the state priority of phi_rel and w_rel: "prefer" for a stiff
    shaft (the MSL's default); by default ("default") the model keeps the states it
    would have with ``PartialCompliant`` (see ``acausal.library.relative_states``).
    ``phi_nominal`` (1e-4 rad) is the nominal value of phi_rel, which scales its error
    tolerance.
    """

    phi_rel = ac.Variable(start=0.0, unit="rad", nominal=1e-4,
                          description="relative rotation angle flange_b.phi - flange_a.phi")
    w_rel = ac.Variable(start=0.0, unit="rad/s",
                        description="relative angular velocity der(phi_rel)")
    tau = ac.Variable(unit="N.m", description="torque between the flanges")

    _relative_states = ("phi_rel", "w_rel")

    def __init__(self, *, stateSelect="default", phi_nominal=1e-4, **modifications):
        super().__init__(**modifications)
        self._select(stateSelect, phi_nominal)

    def equations(self):
        return [ac.Eq(self.phi_rel, self.flange_b.phi - self.flange_a.phi),
                ac.Eq(self.w_rel, ac.der(self.phi_rel)),
                *self.acceleration_equations(),
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


class PartialElementaryOneFlangeAndSupport(PartialElementaryOneFlange):
    """One flange acting against a support (MSL PartialElementaryOneFlangeAndSupport2):

        support.tau = -flange.tau          (the reaction goes into the housing)

    ``useSupport=True`` creates the flange ``support`` (it must then be connected);
    without it the housing is fixed, phi_support = 0 (an ``ac.Conditional`` port).
    ``phi_support()`` is the support's angle for the component's equations.
    """

    useSupport = ac.Parameter(False, structural=True,
                              description="use the support flange, else it is fixed")
    support = ac.Conditional(RotationalFlange(), "useSupport")

    def phi_support(self):
        return self.support.phi if self.useSupport else 0

    def equations(self):
        if not self.useSupport:
            return []
        return [ac.Eq(self.support.tau, -self.flange.tau)]


class PartialElementaryTwoFlangesAndSupport(PartialTwoFlanges):
    """Two flanges acting against a support (MSL PartialElementaryTwoFlangesAndSupport2),
    torque-free as a whole:

        support.tau = -flange_a.tau - flange_b.tau

    ``useSupport=True`` creates the flange ``support``; without it phi_support = 0.
    """

    useSupport = ac.Parameter(False, structural=True,
                              description="use the support flange, else it is fixed")
    support = ac.Conditional(RotationalFlange(), "useSupport")

    def phi_support(self):
        return self.support.phi if self.useSupport else 0

    def equations(self):
        if not self.useSupport:
            return []
        return [ac.Eq(self.support.tau, -self.flange_a.tau - self.flange_b.tau)]


class PartialElementaryRotationalToTranslational(ac.Component):
    """A rotational flange flangeR and a translational flange flangeT (an ideal,
    massless converter between the two domains), each acting against its own support
    (MSL PartialElementaryRotationalToTranslational):

        supportR.tau = -flangeR.tau,   supportT.f = -flangeT.f

    ``useSupportR=True`` / ``useSupportT=True`` create the rotational support
    ``supportR`` / the translational support ``supportT``; an unused support is fixed
    at 0 (``phi_supportR()``, ``s_supportT()``).
    """

    flangeR = RotationalFlange()
    flangeT = TranslationalFlange()
    useSupportR = ac.Parameter(False, structural=True,
                               description="use the rotational support, else it is fixed")
    useSupportT = ac.Parameter(False, structural=True,
                               description="use the translational support, else it is fixed")
    supportR = ac.Conditional(RotationalFlange(), "useSupportR")
    supportT = ac.Conditional(TranslationalFlange(), "useSupportT")

    def phi_supportR(self):
        return self.supportR.phi if self.useSupportR else 0

    def s_supportT(self):
        return self.supportT.s if self.useSupportT else 0

    def equations(self):
        eqs = []
        if self.useSupportR:
            eqs.append(ac.Eq(self.supportR.tau, -self.flangeR.tau))
        if self.useSupportT:
            eqs.append(ac.Eq(self.supportT.f, -self.flangeT.f))
        return eqs
