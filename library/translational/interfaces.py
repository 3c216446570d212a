"""Partial models of 1-D translational mechanics (Modelica.Mechanics.Translational)."""
import acausal as ac
from acausal.ports import TranslationalFlange

from ..relative_states import LinearAcceleration, RelativeStatesMixin

__all__ = ["PartialTwoFlanges", "PartialRigid", "PartialCompliant",
           "PartialCompliantWithRelativeStates", "PartialElementaryOneFlange",
           "PartialAbsoluteSensor", "PartialRelativeSensor",
           "PartialElementaryOneFlangeAndSupport", "PartialElementaryTwoFlangesAndSupport"]


class PartialTwoFlanges(ac.Component):
    """Two flanges, flange_a and flange_b."""

    flange_a = TranslationalFlange()
    flange_b = TranslationalFlange()


class PartialRigid(PartialTwoFlanges):
    """A rigid body of length L between its flanges, its centre at s (MSL Translational
    PartialRigid):

        flange_a.s = s - L/2,   flange_b.s = s + L/2
    """

    L = ac.Parameter(0.0, unit="m",
                     description="length of the component, flange_b.s - flange_a.s")
    s = ac.Variable(start=0.0, unit="m", description="absolute position of the centre")

    def equations(self):
        return [ac.Eq(self.flange_a.s, self.s - self.L / 2),
                ac.Eq(self.flange_b.s, self.s + self.L / 2)]


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


class PartialCompliantWithRelativeStates(RelativeStatesMixin, PartialTwoFlanges):
    """A compliant connection whose relative position and speed may be chosen as
    states (MSL Translational PartialCompliantWithRelativeStates):

        s_rel = flange_b.s - flange_a.s,   v_rel = der(s_rel),
        flange_b.f = f,   flange_a.f = -f
        acc.a_rel = der(v_rel)          (only with stateSelect "prefer" or "always")

    ``stateSelect`` is the state priority of s_rel and v_rel: "prefer" for a stiff
    coupling; by default ("default") the states of ``PartialCompliant`` (see
    ``acausal.library.relative_states``).  ``s_nominal`` (1e-4 m) is the nominal value
    of s_rel, which scales its error tolerance.
    """

    s_rel = ac.Variable(start=0.0, unit="m", nominal=1e-4,
                        description="relative distance flange_b.s - flange_a.s")
    v_rel = ac.Variable(start=0.0, unit="m/s", description="relative velocity der(s_rel)")
    f = ac.Variable(unit="N", description="force between the flanges")

    _relative_states = ("s_rel", "v_rel")
    _acceleration = LinearAcceleration
    _nominal_name = "s_nominal"

    def __init__(self, *, stateSelect="default", s_nominal=1e-4, **modifications):
        super().__init__(**modifications)
        self._select(stateSelect, s_nominal)

    def equations(self):
        return [ac.Eq(self.s_rel, self.flange_b.s - self.flange_a.s),
                ac.Eq(self.v_rel, ac.der(self.s_rel)),
                *self.acceleration_equations(),
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


class PartialElementaryOneFlangeAndSupport(PartialElementaryOneFlange):
    """One flange acting against a support (MSL Translational
    PartialElementaryOneFlangeAndSupport2):

        support.f = -flange.f              (the reaction goes into the housing)

    ``useSupport=True`` creates the flange ``support`` (it must then be connected);
    without it the housing is fixed, s_support = 0 (an ``ac.Conditional`` port).
    """

    useSupport = ac.Parameter(False, structural=True,
                              description="use the support flange, else it is fixed")
    support = ac.Conditional(TranslationalFlange(), "useSupport")

    def s_support(self):
        return self.support.s if self.useSupport else 0

    def equations(self):
        if not self.useSupport:
            return []
        return [ac.Eq(self.support.f, -self.flange.f)]


class PartialElementaryTwoFlangesAndSupport(PartialTwoFlanges):
    """Two flanges acting against a support (MSL Translational
    PartialElementaryTwoFlangesAndSupport2), force-free as a whole:

        support.f = -flange_a.f - flange_b.f

    ``useSupport=True`` creates the flange ``support``; without it s_support = 0.
    """

    useSupport = ac.Parameter(False, structural=True,
                              description="use the support flange, else it is fixed")
    support = ac.Conditional(TranslationalFlange(), "useSupport")

    def s_support(self):
        return self.support.s if self.useSupport else 0

    def equations(self):
        if not self.useSupport:
            return []
        return [ac.Eq(self.support.f, -self.flange_a.f - self.flange_b.f)]
