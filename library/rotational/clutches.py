"""Clutch, brake, one-way clutch and bearing friction with Coulomb friction that sticks
(Modelica.Mechanics.Rotational.Components.Clutch, Brake, OneWayClutch, BearingFriction).

Each element presses its friction surfaces together with the normal force
fn = fn_max f_normalized (f_normalized in [0, 1], an input signal) and rubs with

    tau = cgeo fn mu(|w|) sgn(w)      sliding,   mu(w) from the table mu_pos (w >= 0)
    |tau| <= peak cgeo mu(0) fn        stuck, tau from the torque balance (a = 0)

``cgeo`` [m] turns the normal force into a torque (N (r_o + r_i)/2 for N friction
interfaces between radii r_i and r_o, uniform wear).  The modes, their events and the
way the stuck torque is found are those of
:class:`acausal.library.friction.modes.FrictionModes` (through
:class:`acausal.library.rotational.friction_modes.PartialFriction`).
"""
from acausal._sympy import sympy as sp

import acausal as ac
from acausal.ports import BooleanInput, RealInput

from .friction_modes import PartialFriction, friction_table, table_at_zero, table_value
from .interfaces import PartialElementaryTwoFlangesAndSupport, PartialTwoFlanges

__all__ = ["Clutch", "Brake", "OneWayClutch", "BearingFriction"]


class _PressedFriction(PartialFriction, PartialTwoFlanges):
    """The parameters of a friction element pressed by a normal force, the force
    fn = fn_max f_normalized and the sliding law cgeo fn mu(w).  With
    ``booleanControl=True`` a ``BooleanInput`` ``engaged`` replaces the Real input
    ``f_normalized``: fn = fn_max while it is true, 0 while it is false."""

    peak = ac.Parameter(1.0, min=1, description="stiction: most held torque / tau0")
    cgeo = ac.Parameter(1.0, unit="m", min=0,
                        description="geometry constant, torque per normal force")
    fn_max = ac.Parameter(1.0, unit="N", min=0, description="maximum normal force (> 0)")
    fn = ac.Variable(unit="N", description="normal force fn_max f_normalized")
    booleanControl = ac.Parameter(False, structural=True,
                                  description="engaged by a BooleanInput (else by the Real "
                                              "f_normalized)")
    f_normalized = ac.Conditional(RealInput(), "booleanControl", when=False)
    engaged = ac.Conditional(BooleanInput(), "booleanControl")

    def __init__(self, mu_pos=((0.0, 0.5),), **mods):
        super().__init__(**mods)
        self.mu_pos = friction_table(mu_pos, type(self).__name__)
        self.mu0 = table_at_zero(self.mu_pos)

    def free(self):
        return self.fn <= 0

    def tau0(self):
        return self.mu0 * self.cgeo * self.fn

    def tau0_max(self):
        return self.peak * self.tau0()

    def sliding_torque(self, w):
        return self.cgeo * self.fn * table_value(self.mu_pos, w / self.unit_w)

    def equations(self):
        _check_positive(self, "fn_max")
        if self.booleanControl:
            return [ac.Eq(self.fn, ac.if_else(self.engaged, self.fn_max, 0))]
        return [ac.Eq(self.fn, self.fn_max * self.f_normalized)]


def _check_positive(comp, name):
    """A parameter that divides the modes (fn_max: no force, no friction) must be > 0;
    min = 0 in its declaration admits 0, so 0 is refused here."""
    value = comp.parameter_value(name)
    if isinstance(value, (int, float)) or (isinstance(value, sp.Basic) and value.is_number):
        if float(value) <= 0:
            raise ac.InvalidValue(f"{comp._describe()}: parameter {name} = {value} must be "
                                  "> 0 (the normal force at f_normalized = 1)")


class Clutch(_PressedFriction):
    """Clutch (Modelica.Mechanics.Rotational.Components.Clutch): friction between
    flange_a and flange_b, with the relative motion as states:

        phi_rel = flange_b.phi - flange_a.phi,  w_rel = der(phi_rel),  a_rel = der(w_rel)
        flange_b.tau = tau,  flange_a.tau = -tau
        fn = fn_max f_normalized,   free while fn <= 0
        tau = cgeo fn mu(w_rel) sgn(w_rel) sliding,  |tau| <= peak cgeo mu0 fn stuck

    ``mu_pos``: rows [w_rel, mu] of the friction coefficient for w_rel >= 0 (one row: a
    constant coefficient), interpolated linearly.
    """

    phi_rel = ac.Variable(start=0.0, unit="rad", state_select="prefer",
                          description="relative angle flange_b.phi - flange_a.phi")
    w_rel = ac.Variable(start=0.0, unit="rad/s", state_select="prefer",
                        description="relative speed der(phi_rel)")
    a_rel = ac.Variable(unit="rad/s2", description="relative acceleration der(w_rel)")
    tau = ac.Variable(unit="N.m", description="friction torque on flange_b")

    @property
    def w_relfric(self):
        return self.w_rel

    @property
    def a_relfric(self):
        return self.a_rel

    def equations(self):
        return [ac.Eq(self.phi_rel, self.flange_b.phi - self.flange_a.phi),
                ac.Eq(self.w_rel, ac.der(self.phi_rel)),
                ac.Eq(self.a_rel, ac.der(self.w_rel)),
                ac.Eq(self.flange_b.tau, self.tau),
                ac.Eq(self.flange_a.tau, -self.tau)]


class OneWayClutch(Clutch):
    """One-way clutch (Modelica.Mechanics.Rotational.Components.OneWayClutch): a clutch
    in parallel with a freewheel, with one constraint torque for both.

    w_rel > 0: the clutch slides, tau = cgeo fn mu(w_rel) (0 while fn = 0).  w_rel = 0:
    the freewheel holds any torque that pushes w_rel negative, the clutch up to
    peak cgeo mu0 fn the other way; beyond that it breaks away forwards.  There is no
    backward sliding: start with w_rel >= 0.  Since it is locked even at fn = 0, the
    break-away torque has a floor of 1e-4 cgeo mu0 fn_max (the MSL's eps0), so that
    an open clutch is not at its threshold for ever.
    """

    backward = False

    def free(self):
        return None                       # the freewheel acts whatever fn is

    def tau0_max(self):
        floor = 1e-4 * self.mu0 * self.cgeo * self.fn_max
        return ac.max(self.peak * self.tau0(), floor)


class _ShaftOnHousing(PartialElementaryTwoFlangesAndSupport):
    """A shaft through the element (flange_a = flange_b) rubbing on the housing, which
    is the ``support`` flange with ``useSupport=True`` (else fixed):

        phi = flange_a.phi - phi_support = flange_b.phi - phi_support,
        w = der(phi),  a = der(w),  0 = flange_a.tau + flange_b.tau - tau
        (support.tau = -flange_a.tau - flange_b.tau = -tau)
    """

    phi = ac.Variable(start=0.0, unit="rad", description="angle of the shaft to the housing")
    w = ac.Variable(start=0.0, unit="rad/s", description="speed of the shaft to the housing")
    a = ac.Variable(unit="rad/s2", description="acceleration of the shaft to the housing")
    tau = ac.Variable(unit="N.m", description="friction torque (against w > 0)")

    @property
    def w_relfric(self):
        return self.w

    @property
    def a_relfric(self):
        return self.a

    def equations(self):
        return [ac.Eq(self.phi, self.flange_a.phi - self.phi_support()),
                ac.Eq(self.flange_b.phi, self.flange_a.phi),
                ac.Eq(self.w, ac.der(self.phi)),
                ac.Eq(self.a, ac.der(self.w)),
                ac.Eq(0, self.flange_a.tau + self.flange_b.tau - self.tau)]


class Brake(_ShaftOnHousing, _PressedFriction):
    """Brake (Modelica.Mechanics.Rotational.Components.Brake): friction between the
    shaft (flange_a = flange_b) and the housing (the ``support`` with
    ``useSupport=True``):

        phi = flange_a.phi - phi_support = flange_b.phi - phi_support,
        w = der(phi),  a = der(w)
        0 = flange_a.tau + flange_b.tau - tau
        tau = cgeo fn mu(w) sgn(w) sliding,  |tau| <= peak cgeo mu0 fn stuck (a = 0)
    """


class BearingFriction(_ShaftOnHousing, PartialFriction):
    """Bearing friction (Modelica.Mechanics.Rotational.Components.BearingFriction):
    Coulomb friction of a shaft in its housing (the ``support`` with
    ``useSupport=True``) given as a torque table, always engaged:

        phi = flange_a.phi - phi_support = flange_b.phi - phi_support,
        w = der(phi),  a = der(w)
        0 = flange_a.tau + flange_b.tau - tau
        tau = tau_pos(|w|) sgn(w) sliding,  |tau| <= peak tau_pos(0) stuck (a = 0)

    ``tau_pos``: rows [w, tau] for w >= 0 [rad/s, N.m] (one row: a constant torque),
    interpolated linearly, extrapolated from the last two rows.
    """

    peak = ac.Parameter(1.0, min=1, description="stiction: most held torque / tau_pos(0)")

    def __init__(self, tau_pos=((0.0, 1.0),), **mods):
        super().__init__(**mods)
        self.tau_pos = friction_table(tau_pos, type(self).__name__, "tau_pos", "tau")
        self.tau_at_rest = table_at_zero(self.tau_pos)

    def free(self):
        return None

    def tau0(self):
        return self.tau_at_rest * self.unit_tau

    def tau0_max(self):
        return self.peak * self.tau0()

    def sliding_torque(self, w):
        return table_value(self.tau_pos, w / self.unit_w) * self.unit_tau
