"""Rotational friction elements (Egeland & Gravdahl ch. 5).

Each element sits between flange_a and flange_b like a damper: with flange_a on a
``Fixed`` housing it is friction against the ground.  The friction torque tau acts on
flange_b against the relative angular velocity w (f v >= 0 for the static laws), and -tau on
flange_a.
"""
from acausal._sympy import sympy as sp

import acausal as ac

from ._models import _Dahl, _ElastoPlastic, _Karnopp, _LuGre, _Stribeck
from .interfaces import PartialRotationalFriction

__all__ = ["StribeckFriction", "KarnoppFriction", "DahlFriction", "LuGreFriction",
           "ElastoPlasticFriction"]


class StribeckFriction(_Stribeck, PartialRotationalFriction):
    """Coulomb, viscous and Stribeck friction, a static map (Egeland & Gravdahl (5.13)):

        tau = [F_c + (F_s - F_c) exp(-(w/v_s)^2)] sgn(w) + F_v w

    F_s = F_c gives Coulomb + viscous friction (5.12).  sgn(0) = 0: a body that should
    stick chatters about w = 0 (5.18)-(5.19); use ``KarnoppFriction`` for sticking.
    """

    F_c = ac.Parameter(1.0, unit="N.m", min=0, description="Coulomb friction level")
    F_s = ac.Parameter(1.5, unit="N.m", min=0, description="static (break-away) friction")
    v_s = ac.Parameter(0.01, unit="rad/s", min=0, description="Stribeck velocity")
    F_v = ac.Parameter(0.0, unit="N.m.s/rad", min=0, description="viscous coefficient")

    def loss_power(self):
        """tau w >= 0: friction opposes the relative motion (stuck: w = 0)."""
        return self.tau * self.w


class KarnoppFriction(_Karnopp, PartialRotationalFriction):
    """Karnopp's stick-slip friction (Egeland & Gravdahl 5.2.3, 5.2.5-5.2.6, (5.14),
    (5.22)-(5.23)) with a zero-velocity band |w| < dv:

        |w| >= dv:  tau = [F_c + (F_s - F_c) exp(-(w/v_s)^2)] sgn(w) + F_v w
        |w| <  dv:  tau = sat(F_a, F_s)     (stuck while |F_a| <= F_s)

    F_a, the torque the rest of the system applies, is found by a curve parameter sa:
    inside the band tau = sat(sa, F_s) and der(w) = sa - sat(sa, F_s), outside
    der(w) = sa.  A body that enters the band is stopped there (reinit of w to 0),
    so it sticks with w = 0 exactly, and breaks away when |F_a| exceeds F_s.  Band
    edges and |sa| = F_s are events; no chattering.

    The band is not free.  Every breakaway starts at w = 0 inside it, and the body
    leaves it only when w reaches dv, pushed by the net torque F_a - F_s, which grows
    from zero at the rate F' at which the applied torque passes F_s: J der(w) = F' t,
    so each breakaway is late by about sqrt(2 J dv / F') (J the inertia it
    moves; 1 kg.m2, dv = 1e-6 rad/s and F' = 1e3 N.m/s: 45 us, which a stick-slip
    cycle repeats, and which adds up over many cycles).  Keep dv small against the
    speeds that matter, and the absolute tolerance of w (atol times its nominal
    value) below dv: the integrator must resolve the band to stop in it.
    """

    F_c = ac.Parameter(1.0, unit="N.m", min=0, description="Coulomb friction level")
    F_s = ac.Parameter(1.5, unit="N.m", min=0, description="static (break-away) friction")
    v_s = ac.Parameter(0.01, unit="rad/s", min=0, description="Stribeck velocity")
    F_v = ac.Parameter(0.0, unit="N.m.s/rad", min=0, description="viscous coefficient")
    dv = ac.Parameter(1e-6, unit="rad/s", min=0, description="half width of the sticking band")
    a = ac.Variable(unit="rad/s2", description="relative acceleration")
    sa = ac.Variable(start=0.0, unit="1",
                     description="curve parameter (applied torque when stuck, in unit_f)")
    unit_f = ac.Parameter(1.0, unit="N.m", min=0, description="1 N.m: the unit of sa as a torque")
    unit_a = ac.Parameter(1.0, unit="rad/s2", min=0,
                          description="1 rad/s2: the unit of sa as an acceleration")

    def loss_power(self):
        """tau w >= 0: friction opposes the relative motion (stuck: w = 0)."""
        return self.tau * self.w


class DahlFriction(_Dahl, PartialRotationalFriction):
    """Dahl's friction model (Egeland & Gravdahl 5.3.2, (5.35)):

        der(F) = sigma (w - |w| F / F_c),   tau = F

    In forward motion from F = 0 at x = 0:  F = F_c (1 - exp(-sigma x / F_c))  (5.38).
    """

    F_c = ac.Parameter(1.0, unit="N.m", min=0, description="Coulomb friction level")
    sigma = ac.Parameter(1e3, unit="N.m/rad", min=0, description="rest stiffness")
    F = ac.Variable(start=0.0, unit="N.m", description="friction state")

    def stored_energy(self):
        """The bristles' elastic energy F^2 / (2 sigma)."""
        return self.F**2 / (2 * self.sigma)

    def loss_power(self):
        """tau w - d/dt F^2/(2 sigma) = |w| F^2 / F_c >= 0  (from (5.35))."""
        return sp.Abs(self.w) * self.F**2 / self.F_c


class LuGreFriction(_LuGre, PartialRotationalFriction):
    """LuGre friction (Canudas de Wit et al. 1995; Egeland & Gravdahl 5.3.4, (5.42)-(5.44)):

        der(z) = w - sigma_0 |w| z / g(w),   g = F_c + (F_s - F_c) exp(-(w/v_s)^2)
        tau = sigma_0 z + sigma_1 der(z) + sigma_2 w

    At constant w the force settles on the Stribeck curve g(w) sgn(w) + sigma_2 w
    ((5.48), with g the force level, see ``laws.stribeck_level``).  Passive from w to
    tau iff sigma_1 <= sigma_2 F_c / (F_s - F_c)  (5.54).
    """

    F_c = ac.Parameter(1.0, unit="N.m", min=0, description="Coulomb friction level")
    F_s = ac.Parameter(1.5, unit="N.m", min=0, description="static (break-away) friction")
    v_s = ac.Parameter(0.01, unit="rad/s", min=0, description="Stribeck velocity")
    sigma_0 = ac.Parameter(1e5, unit="N.m/rad", min=0, description="bristle stiffness")
    sigma_1 = ac.Parameter(300.0, unit="N.m.s/rad", min=0, description="bristle damping")
    sigma_2 = ac.Parameter(0.4, unit="N.m.s/rad", min=0, description="viscous coefficient")
    z = ac.Variable(start=0.0, unit="rad", description="mean bristle deflection")
    z_dot = ac.Variable(unit="rad/s", description="der(z)")

    def stored_energy(self):
        """The bristles' elastic energy sigma_0 z^2 / 2."""
        return self.sigma_0 * self.z**2 / 2

    def loss_power(self):
        """tau w - sigma_0 z der(z): >= 0 where the model is passive (for LuGre
        sigma_1 <= sigma_2 F_c / (F_s - F_c), (5.54))."""
        return self.tau * self.w - self.sigma_0 * self.z * self.z_dot


class ElastoPlasticFriction(_ElastoPlastic, PartialRotationalFriction):
    """Elasto-plastic friction (Dupont et al. 2002; Egeland & Gravdahl 5.3.6, (5.55)-(5.58),
    exponent i = 1):

        der(z) = w (1 - alpha(z, w) sigma_0 sgn(w) z / g(w))
        tau = sigma_0 z + sigma_1 der(z) + sigma_2 w,   z_max = g(w) / sigma_0

    alpha = 0 for |z| <= z_b (purely elastic: true stiction, no drift), a sine ramp up to
    1 at z_max, and 0 when z and w have opposite signs (``laws.elastoplastic_alpha``).
    """

    F_c = ac.Parameter(1.0, unit="N.m", min=0, description="Coulomb friction level")
    F_s = ac.Parameter(1.5, unit="N.m", min=0, description="static (break-away) friction")
    v_s = ac.Parameter(0.01, unit="rad/s", min=0, description="Stribeck velocity")
    sigma_0 = ac.Parameter(1e5, unit="N.m/rad", min=0, description="bristle stiffness")
    sigma_1 = ac.Parameter(300.0, unit="N.m.s/rad", min=0, description="bristle damping")
    sigma_2 = ac.Parameter(0.4, unit="N.m.s/rad", min=0, description="viscous coefficient")
    z_b = ac.Parameter(5e-6, unit="rad", min=0, description="break-away deflection, < F_c/sigma_0")
    z = ac.Variable(start=0.0, unit="rad", description="elastic (pre-sliding) deflection")
    z_dot = ac.Variable(unit="rad/s", description="der(z)")

    def stored_energy(self):
        """The bristles' elastic energy sigma_0 z^2 / 2."""
        return self.sigma_0 * self.z**2 / 2

    def loss_power(self):
        """tau w - sigma_0 z der(z): the port power less the bristles' storage rate
        (its sign over a run is what the energy audit checks; Dupont et al. 2002 give
        the conditions under which the elasto-plastic model is passive)."""
        return self.tau * self.w - self.sigma_0 * self.z * self.z_dot
