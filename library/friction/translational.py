"""Translational friction elements (Egeland & Gravdahl ch. 5).

Each element sits between flange_a and flange_b like a damper: with flange_a on a
``Fixed`` housing it is friction against the ground.  The friction force f acts on
flange_b against the relative velocity v (f v >= 0 for the static laws), and -f on
flange_a.
"""
from acausal._sympy import sympy as sp

import acausal as ac

from ._models import _Dahl, _ElastoPlastic, _Karnopp, _LuGre, _Stribeck
from .interfaces import PartialTranslationalFriction

__all__ = ["StribeckFriction", "KarnoppFriction", "DahlFriction", "LuGreFriction",
           "ElastoPlasticFriction"]


class StribeckFriction(_Stribeck, PartialTranslationalFriction):
    """Coulomb, viscous and Stribeck friction, a static map (Egeland & Gravdahl (5.13)):

        f = [F_c + (F_s - F_c) exp(-(v/v_s)^2)] sgn(v) + F_v v

    F_s = F_c gives Coulomb + viscous friction (5.12).  sgn(0) = 0: a body that should
    stick chatters about v = 0 (5.18)-(5.19); use ``KarnoppFriction`` for sticking.
    """

    F_c = ac.Parameter(1.0, unit="N", min=0, description="Coulomb friction level")
    F_s = ac.Parameter(1.5, unit="N", min=0, description="static (break-away) friction")
    v_s = ac.Parameter(0.01, unit="m/s", min=0, description="Stribeck velocity")
    F_v = ac.Parameter(0.0, unit="N.s/m", min=0, description="viscous coefficient")

    def loss_power(self):
        """f v >= 0: friction opposes the relative motion (stuck: v = 0)."""
        return self.f * self.v


class KarnoppFriction(_Karnopp, PartialTranslationalFriction):
    """Karnopp's stick-slip friction (Egeland & Gravdahl 5.2.3, 5.2.5-5.2.6, (5.14),
    (5.22)-(5.23)) with a zero-velocity band |v| < dv:

        |v| >= dv:  f = [F_c + (F_s - F_c) exp(-(v/v_s)^2)] sgn(v) + F_v v
        |v| <  dv:  f = sat(F_a, F_s)     (stuck while |F_a| <= F_s)

    F_a, the force the rest of the system applies, is found by a curve parameter sa:
    inside the band f = sat(sa, F_s) and der(v) = sa - sat(sa, F_s), outside
    der(v) = sa.  A body that enters the band is stopped there (reinit of v to 0),
    so it sticks with v = 0 exactly, and breaks away when |F_a| exceeds F_s.  Band
    edges and |sa| = F_s are events; no chattering.

    The band is not free.  Every breakaway starts at v = 0 inside it, and the body
    leaves it only when v reaches dv, pushed by the net force F_a - F_s, which grows
    from zero at the rate F' at which the applied force passes F_s: m der(v) = F' t,
    so each breakaway is late by about sqrt(2 m dv / F') (m the inertia it
    moves; 1 kg, dv = 1e-6 m/s and F' = 1e3 N/s: 45 us, which a stick-slip
    cycle repeats, and which adds up over many cycles).  Keep dv small against the
    speeds that matter, and the absolute tolerance of v (atol times its nominal
    value) below dv: the integrator must resolve the band to stop in it.
    """

    F_c = ac.Parameter(1.0, unit="N", min=0, description="Coulomb friction level")
    F_s = ac.Parameter(1.5, unit="N", min=0, description="static (break-away) friction")
    v_s = ac.Parameter(0.01, unit="m/s", min=0, description="Stribeck velocity")
    F_v = ac.Parameter(0.0, unit="N.s/m", min=0, description="viscous coefficient")
    dv = ac.Parameter(1e-6, unit="m/s", min=0, description="half width of the sticking band")
    a = ac.Variable(unit="m/s2", description="relative acceleration")
    sa = ac.Variable(start=0.0, unit="1",
                     description="curve parameter (applied force when stuck, in unit_f)")
    unit_f = ac.Parameter(1.0, unit="N", min=0, description="1 N: the unit of sa as a force")
    unit_a = ac.Parameter(1.0, unit="m/s2", min=0,
                          description="1 m/s2: the unit of sa as an acceleration")

    def loss_power(self):
        """f v >= 0: friction opposes the relative motion (stuck: v = 0)."""
        return self.f * self.v


class DahlFriction(_Dahl, PartialTranslationalFriction):
    """Dahl's friction model (Egeland & Gravdahl 5.3.2, (5.35)):

        der(F) = sigma (v - |v| F / F_c),   f = F

    In forward motion from F = 0 at x = 0:  F = F_c (1 - exp(-sigma x / F_c))  (5.38).
    """

    F_c = ac.Parameter(1.0, unit="N", min=0, description="Coulomb friction level")
    sigma = ac.Parameter(1e3, unit="N/m", min=0, description="rest stiffness")
    F = ac.Variable(start=0.0, unit="N", description="friction state")

    def stored_energy(self):
        """The bristles' elastic energy F^2 / (2 sigma)."""
        return self.F**2 / (2 * self.sigma)

    def loss_power(self):
        """f v - d/dt F^2/(2 sigma) = |v| F^2 / F_c >= 0  (from (5.35))."""
        return sp.Abs(self.v) * self.F**2 / self.F_c


class LuGreFriction(_LuGre, PartialTranslationalFriction):
    """LuGre friction (Canudas de Wit et al. 1995; Egeland & Gravdahl 5.3.4, (5.42)-(5.44)):

        der(z) = v - sigma_0 |v| z / g(v),   g = F_c + (F_s - F_c) exp(-(v/v_s)^2)
        f = sigma_0 z + sigma_1 der(z) + sigma_2 v

    At constant v the force settles on the Stribeck curve g(v) sgn(v) + sigma_2 v
    ((5.48), with g the force level, see ``laws.stribeck_level``).  Passive from v to
    f iff sigma_1 <= sigma_2 F_c / (F_s - F_c)  (5.54).
    """

    F_c = ac.Parameter(1.0, unit="N", min=0, description="Coulomb friction level")
    F_s = ac.Parameter(1.5, unit="N", min=0, description="static (break-away) friction")
    v_s = ac.Parameter(0.01, unit="m/s", min=0, description="Stribeck velocity")
    sigma_0 = ac.Parameter(1e5, unit="N/m", min=0, description="bristle stiffness")
    sigma_1 = ac.Parameter(300.0, unit="N.s/m", min=0, description="bristle damping")
    sigma_2 = ac.Parameter(0.4, unit="N.s/m", min=0, description="viscous coefficient")
    z = ac.Variable(start=0.0, unit="m", description="mean bristle deflection")
    z_dot = ac.Variable(unit="m/s", description="der(z)")

    def stored_energy(self):
        """The bristles' elastic energy sigma_0 z^2 / 2."""
        return self.sigma_0 * self.z**2 / 2

    def loss_power(self):
        """f v - sigma_0 z der(z): >= 0 where the model is passive (for LuGre
        sigma_1 <= sigma_2 F_c / (F_s - F_c), (5.54))."""
        return self.f * self.v - self.sigma_0 * self.z * self.z_dot


class ElastoPlasticFriction(_ElastoPlastic, PartialTranslationalFriction):
    """Elasto-plastic friction (Dupont et al. 2002; Egeland & Gravdahl 5.3.6, (5.55)-(5.58),
    exponent i = 1):

        der(z) = v (1 - alpha(z, v) sigma_0 sgn(v) z / g(v))
        f = sigma_0 z + sigma_1 der(z) + sigma_2 v,   z_max = g(v) / sigma_0

    alpha = 0 for |z| <= z_b (purely elastic: true stiction, no drift), a sine ramp up to
    1 at z_max, and 0 when z and v have opposite signs (``laws.elastoplastic_alpha``).
    """

    F_c = ac.Parameter(1.0, unit="N", min=0, description="Coulomb friction level")
    F_s = ac.Parameter(1.5, unit="N", min=0, description="static (break-away) friction")
    v_s = ac.Parameter(0.01, unit="m/s", min=0, description="Stribeck velocity")
    sigma_0 = ac.Parameter(1e5, unit="N/m", min=0, description="bristle stiffness")
    sigma_1 = ac.Parameter(300.0, unit="N.s/m", min=0, description="bristle damping")
    sigma_2 = ac.Parameter(0.4, unit="N.s/m", min=0, description="viscous coefficient")
    z_b = ac.Parameter(5e-6, unit="m", min=0, description="break-away deflection, < F_c/sigma_0")
    z = ac.Variable(start=0.0, unit="m", description="elastic (pre-sliding) deflection")
    z_dot = ac.Variable(unit="m/s", description="der(z)")

    def stored_energy(self):
        """The bristles' elastic energy sigma_0 z^2 / 2."""
        return self.sigma_0 * self.z**2 / 2

    def loss_power(self):
        """f v - sigma_0 z der(z): the port power less the bristles' storage rate
        (its sign over a run is what the energy audit checks; Dupont et al. 2002 give
        the conditions under which the elasto-plastic model is passive)."""
        return self.f * self.v - self.sigma_0 * self.z * self.z_dot
