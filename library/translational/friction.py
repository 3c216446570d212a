"""Translational elements with Coulomb friction that sticks
(Modelica.Mechanics.Translational.Interfaces.PartialFriction, Components.Brake,
SupportFriction, MassWithStopAndFriction).

The modes, their events and the way the stuck force is found are those of
:class:`acausal.library.friction.modes.FrictionModes` (its module docstring tells the
whole story); :class:`PartialFriction` names the speed ``v_relfric``, its derivative
``a_relfric`` and the friction force ``f`` and makes the path parameter ``sa`` a force.
"""
from __future__ import annotations

from acausal._sympy import sympy as sp

import acausal as ac
from acausal.ports import RealInput

from ..friction.modes import FrictionModes, friction_table, table_at_zero, table_value
from .interfaces import PartialElementaryTwoFlangesAndSupport, PartialRigid

__all__ = ["PartialFriction", "Brake", "SupportFriction", "MassWithStopAndFriction"]


class PartialFriction(FrictionModes):
    """Modes of a translational element with Coulomb friction that sticks
    (Modelica.Mechanics.Translational.Interfaces.PartialFriction).

    A subclass declares ``v_relfric`` (relative velocity of the rubbing surfaces),
    ``a_relfric`` = der(v_relfric) and ``f`` (friction force, positive against
    v_relfric > 0), and the methods ``free()`` (a relation, or None), ``f0()``,
    ``f0_max()`` (the force at v = 0 sliding, the most it holds at rest) and
    ``sliding_force(v)`` (while sliding forwards at v >= 0; backwards it is
    -sliding_force(-v)).
    """

    sa = ac.Variable(start=0.0, unit="N",
                     description="path parameter: force held while locked, else 0 "
                                 "or the acceleration past break-away")
    # sa is a force; past break-away it also measures an acceleration, 1 N for 1 m/s2
    # (the MSL's unitForce and unitAcceleration)
    unit_a = ac.Parameter(1.0, unit="m/s2", min=0,
                          description="1 m/s2: the unit of sa as an acceleration")
    unit_f = ac.Parameter(1.0, unit="N", min=0, description="1 N: the unit of sa")
    unit_v = ac.Parameter(1.0, unit="m/s", min=0,
                          description="1 m/s: the unit of the speed in the tables")

    def relfric(self) -> tuple:
        return self.v_relfric, self.a_relfric, self.f

    def per(self):
        return self.unit_a / self.unit_f

    def break_away(self) -> tuple:
        return self.f0_max(), -self.f0_max()

    def sliding_laws(self) -> tuple:
        return self.sliding_force(self.v_relfric), -self.sliding_force(-self.v_relfric)


class _SlideOnSupport(PartialElementaryTwoFlangesAndSupport):
    """A rod through the element (flange_a = flange_b) rubbing on the support (fixed
    unless ``useSupport=True``):

        s = flange_a.s - s_support = flange_b.s - s_support,   v = der(s),   a = der(v)
        0 = flange_a.f + flange_b.f - f          (support.f = -f)
    """

    s = ac.Variable(start=0.0, unit="m", description="position of the flanges to the support")
    v = ac.Variable(start=0.0, unit="m/s", description="velocity of the flanges to the support")
    a = ac.Variable(unit="m/s2", description="acceleration of the flanges to the support")
    f = ac.Variable(unit="N", description="friction force (against v > 0)")

    @property
    def v_relfric(self):
        return self.v

    @property
    def a_relfric(self):
        return self.a

    def equations(self):
        return [ac.Eq(self.s, self.flange_a.s - self.s_support()),
                ac.Eq(self.flange_b.s, self.flange_a.s),
                ac.Eq(self.v, ac.der(self.s)),
                ac.Eq(self.a, ac.der(self.v)),
                ac.Eq(0, self.flange_a.f + self.flange_b.f - self.f)]


class Brake(_SlideOnSupport, PartialFriction):
    """Brake based on Coulomb friction (MSL Translational.Components.Brake): friction
    between the flanges (flange_a = flange_b) and the support, pressed by the normal
    force fn = fn_max f_normalized:

        free while fn <= 0
        f = cgeo fn mu(v) sliding forwards (-cgeo fn mu(-v) backwards)
        |f| <= peak cgeo mu(0) fn stuck (a = 0, f from the force balance)

    ``mu_pos``: rows [v, mu] for v >= 0 (one row: a constant), interpolated linearly.
    """

    peak = ac.Parameter(1.0, min=1, description="stiction: most held force / f0")
    cgeo = ac.Parameter(1.0, min=0, description="geometry constant, friction force / "
                                                "normal force")
    fn_max = ac.Parameter(1.0, unit="N", min=0, description="maximum normal force")
    fn = ac.Variable(unit="N", description="normal force fn_max f_normalized")
    f_normalized = RealInput()

    def __init__(self, mu_pos=((0.0, 0.5),), *, useSupport=False, **mods):
        super().__init__(useSupport=useSupport, **mods)
        self.mu_pos = friction_table(mu_pos, type(self).__name__, speed="v_rel")
        self.mu0 = table_at_zero(self.mu_pos)

    def free(self):
        return self.fn <= 0

    def f0(self):
        return self.mu0 * self.cgeo * self.fn

    def f0_max(self):
        return self.peak * self.f0()

    def sliding_force(self, v):
        return self.cgeo * self.fn * table_value(self.mu_pos, v / self.unit_v)

    def equations(self):
        return [ac.Eq(self.fn, self.fn_max * self.f_normalized)]


class SupportFriction(_SlideOnSupport, PartialFriction):
    """Coulomb friction in the support (MSL Translational.Components.SupportFriction),
    always engaged, given as a force table:

        f = f_pos(v) sliding forwards (-f_pos(-v) backwards)
        |f| <= peak f_pos(0) stuck (a = 0, f from the force balance)

    ``f_pos``: rows [v, f] for v >= 0 [m/s, N] (one row: a constant force),
    interpolated linearly, extrapolated from the last two rows.
    """

    peak = ac.Parameter(1.0, min=1, description="stiction: most held force / f_pos(0)")

    def __init__(self, f_pos=((0.0, 1.0),), *, useSupport=False, **mods):
        super().__init__(useSupport=useSupport, **mods)
        self.f_pos = friction_table(f_pos, type(self).__name__, "f_pos", "f", "v")
        self.f_at_rest = table_at_zero(self.f_pos)

    def f0(self):
        return self.f_at_rest * self.unit_f

    def f0_max(self):
        return self.peak * self.f0()

    def sliding_force(self, v):
        return table_value(self.f_pos, v / self.unit_v) * self.unit_f


class MassWithStopAndFriction(PartialRigid, PartialFriction):
    """Sliding mass with hard stops and Stribeck friction (MSL
    Translational.Components.MassWithStopAndFriction): a rigid mass of length L, its
    centre at s, between stops that its ends meet at smin and smax:

        v = der(s),   a = der(v),   m a = flange_a.f + flange_b.f - f
        f = F_prop v + F_Coulomb + F_Stribeck exp(-fexp |v|)   sliding, sign of v
        |f| <= 1.001 (F_Coulomb + F_Stribeck)                  stuck (a = 0)

    Reaching a stop (s = smax - L/2 or smin + L/2) is an event that sets v = 0 (a
    plastic impact) and s on the stop; there the mass is stuck (the stop's force is
    part of f) and can only break away from the stop.  As for ``MassWithStop`` the
    contact is a band of width ``eps`` inside each stop, so that the relation is
    clearly non-zero while the mass rests on the stop (atan((s + L/2 - smax)/eps + 1)
    > 0, mirrored at smin).  The mass must start between the stops.  F_Coulomb +
    F_Stribeck > 0 (there is no free mode).
    """

    m = ac.Parameter(1.0, unit="kg", min=0, description="mass")
    smax = ac.Parameter(25.0, unit="m", description="right stop for the right end")
    smin = ac.Parameter(-25.0, unit="m", description="left stop for the left end")
    F_prop = ac.Parameter(1.0, unit="N.s/m", min=0, description="velocity dependent friction")
    F_Coulomb = ac.Parameter(5.0, unit="N", description="constant friction: Coulomb force")
    F_Stribeck = ac.Parameter(10.0, unit="N", description="Stribeck effect")
    fexp = ac.Parameter(2.0, unit="s/m", min=0, description="exponential decay")
    eps = ac.Parameter(1e-10, unit="m", min=0, description="width of the contact band")
    # states, because the stops reinitialize them
    s = ac.Variable(start=0.0, unit="m", state_select="always",
                    description="absolute position of the centre")
    v = ac.Variable(start=0.0, unit="m/s", state_select="always",
                    description="absolute velocity")
    a = ac.Variable(unit="m/s2", description="absolute acceleration")
    f = ac.Variable(unit="N", description="friction force (against v > 0)")

    @property
    def v_relfric(self):
        return self.v

    @property
    def a_relfric(self):
        return self.a

    def at_max(self):
        """Relation: in the contact band of the right stop."""
        return sp.atan((self.s + self.L / 2 - self.smax) / self.eps + 1) > 0

    def at_min(self):
        """Relation: in the contact band of the left stop."""
        return sp.atan((self.smin + self.L / 2 - self.s) / self.eps + 1) > 0

    def f0(self):
        return self.F_Coulomb + self.F_Stribeck

    def f0_max(self):
        return 1.001 * self.f0()

    def sliding_force(self, v):
        return self.F_prop * v + self.F_Coulomb + self.F_Stribeck * ac.exp(-self.fexp * v)

    def mode_relations(self) -> dict:
        """The friction modes, with the stops: no forward motion on the right stop, no
        backward motion on the left one."""
        rel = super().mode_relations()
        right, left = sp.Not(self.at_max()), sp.Not(self.at_min())
        for mode, side in (("forward", right), ("start forward", right),
                           ("backward", left), ("start backward", left)):
            rel[mode] = sp.And(rel[mode], side)
        return rel

    def stored_energy(self):
        return self.m * self.v**2 / 2

    def equations(self):
        return [ac.Eq(self.v, ac.der(self.s)),
                ac.Eq(self.a, ac.der(self.v)),
                ac.Eq(self.m * self.a, self.flange_a.f + self.flange_b.f - self.f),
                ac.when(self.at_max(), ac.reinit(self.s, self.smax - self.L / 2),
                        ac.reinit(self.v, 0)),
                ac.when(self.at_min(), ac.reinit(self.s, self.smin + self.L / 2),
                        ac.reinit(self.v, 0))]
