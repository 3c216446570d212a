"""The friction models of Egeland & Gravdahl ch. 5, written once over a relative
velocity v and a friction force f; ``translational`` and ``rotational`` bind them to
flanges and declare the parameters with their units."""
from acausal._sympy import sympy as sp

import acausal as ac

from .laws import direction, elastoplastic_alpha, saturation, stribeck, stribeck_level

__all__ = []


class _Stribeck:
    def law(self, v, f):
        return [ac.Eq(f, stribeck(v, self.F_c, self.F_s, self.v_s, self.F_v))]


class _Karnopp:
    """Karnopp stick-slip with a band |v| < dv (5.14), (5.22)-(5.23), see the classes.

    The band is a mode of a curve parameter sa (as the MSL's friction elements):
    inside, f = sat(sa, F_s) and a = sa - sat(sa, F_s), so a = 0 while the applied
    force (that sa takes) is at most F_s; outside, a = sa and f is the sliding law.
    Entering the band sets v to 0, so a stuck element has v = 0 exactly.
    """

    def law(self, v, f):
        # sa is a number; unit_f and unit_a (both 1) give it the force's and the
        # acceleration's unit where it stands for either (the MSL's unitForce and
        # unitAcceleration)
        sa, stuck = self.sa, ac.if_else(v >= self.dv, 0, ac.if_else(v <= -self.dv, 0, 1))
        held = saturation(sa * self.unit_f, self.F_s)
        # outside the band sgn(v) is read from the band's own relations: a relation on
        # v itself would be armed exactly at v = 0 whenever the body sticks
        direction = ac.if_else(v >= self.dv, 1, -1)
        sliding = stribeck_level(v, self.F_c, self.F_s, self.v_s) * direction + self.F_v * v
        return [ac.Eq(self.a, ac.der(v)),
                ac.Eq(f, ac.if_else(stuck > 0, held, sliding)),
                ac.Eq(self.a, self.unit_a * ac.if_else(stuck > 0, sa - held / self.unit_f,
                                                       sa)),
                ac.when(sp.And(v < self.dv, v > -self.dv), ac.reinit(v, 0))]


class _Dahl:
    def law(self, v, f):
        """dF/dt = sigma (v - |v| F / F_c)  (5.35)."""
        return [ac.Eq(f, self.F),
                ac.Eq(ac.der(self.F), self.sigma * (v - v * direction(v) * self.F / self.F_c))]


class _LuGre:
    def law(self, v, f):
        """dz/dt = v - sigma_0 |v| z / g(v),  f = sigma_0 z + sigma_1 dz/dt + sigma_2 v."""
        g = stribeck_level(v, self.F_c, self.F_s, self.v_s)
        return [ac.Eq(self.z_dot, v - self.sigma_0 * v * direction(v) * self.z / g),
                ac.Eq(ac.der(self.z), self.z_dot),
                ac.Eq(f, self.sigma_0 * self.z + self.sigma_1 * self.z_dot + self.sigma_2 * v)]


class _ElastoPlastic:
    def law(self, v, f):
        """dz/dt = v (1 - alpha(z, v) sigma_0 z sgn(v) / g(v)),  f as LuGre."""
        g = stribeck_level(v, self.F_c, self.F_s, self.v_s)
        z_max = g / self.sigma_0                                         # (5.58)
        alpha = elastoplastic_alpha(self.z, v, self.z_b, z_max)
        return [ac.Eq(self.z_dot, v * (1 - alpha * self.sigma_0 * self.z * direction(v) / g)),
                ac.Eq(ac.der(self.z), self.z_dot),
                ac.Eq(f, self.sigma_0 * self.z + self.sigma_1 * self.z_dot + self.sigma_2 * v)]
