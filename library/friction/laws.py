"""Friction laws of Egeland & Gravdahl ch. 5 as expressions, shared by the translational
and the rotational components (force and torque alike).

Every function returns a sympy expression; ``ac.sign`` and ``ac.if_else`` make the
places where a law switches (v = 0, the edges of a band) events.
"""
from acausal._sympy import sympy as sp

import acausal as ac

__all__ = ["stribeck", "saturation", "stribeck_level", "direction", "elastoplastic_alpha"]

# direction() switches at v = -1e-300 rather than at 0: a relation whose function is
# exactly 0 when the solver (re)arms its events, as v of a body at rest after an event,
# is not switched when v leaves 0; |v| = v direction(v) is then off by < 1e-300.
_AT_REST = 1e-300


def direction(v):
    """+1 for v >= 0, -1 for v < 0 (so that |v| = v direction(v)), as an event."""
    return ac.if_else(v >= -_AT_REST, 1, -1)


def stribeck_level(v, F_c, F_s, v_s):
    """g(v) = F_c + (F_s - F_c) exp(-(v/v_s)^2): the sliding friction level of (5.10),
    and g(v) of the LuGre and elasto-plastic models.

    Egeland & Gravdahl print (5.43) as sigma_0 g(v) = F_c + ... and (5.48) as
    z_ss = g(v) sgn(v), which contradict (5.42): (5.42) with g = F_c is the Dahl model
    (5.35), and z_max = g/sigma_0 (5.58), so g is the force level itself, as in
    Canudas de Wit et al. (1995), and z_ss = g(v) sgn(v) / sigma_0.
    """
    # (v/v_s)^2 spelled ((v + v_s)/v_s - 1)^2: sympy keeps it a square of a sum, and the
    # code printer emits v^2/v_s^2 wrongly, as v*v/v_s*v_s
    ratio = (v + v_s) / v_s - 1
    return F_c + (F_s - F_c) * sp.exp(-ratio**2)


def stribeck(v, F_c, F_s, v_s, F_v):
    """Coulomb + viscous + Stribeck friction (Egeland & Gravdahl (5.13)):

        F = [F_c + (F_s - F_c) exp(-(v/v_s)^2)] sgn(v) + F_v v

    With F_s = F_c it is Coulomb + viscous friction (5.12).

    Parameters
    ----------
    v : sympy expression
        Sliding velocity.
    F_c, F_s, v_s, F_v : float or sympy expression
        Coulomb level, static (break-away) level, Stribeck velocity, viscous coefficient.

    Returns
    -------
    sympy expression
        The friction force, with sgn(0) = 0 as an event.
    """
    return stribeck_level(v, F_c, F_s, v_s) * ac.sign(v) + F_v * v


def saturation(x, limit):
    """sat(x, limit) = x clipped to [-limit, limit] (Karnopp's sticking force (5.22)).

    The relations are non-strict: an event that finds x exactly at the limit (a
    break-away, located where the applied force reaches F_s) then starts the slip.
    """
    return ac.if_else(x >= limit, limit, ac.if_else(x <= -limit, -limit, x))


def elastoplastic_alpha(z, v, z_b, z_max):
    """alpha(z, v) of the elasto-plastic model (Dupont et al.; Egeland & Gravdahl (5.57)):

        0                                                       |z| <= z_b or sgn v != sgn z
        1/2 sin(pi (z - (z_max + z_b)/2) / (z_max - z_b)) + 1/2  z_b < |z| < z_max
        1                                                       |z| >= z_max

    written for z >= 0 and mirrored (alpha is even in (z, v) -> (-z, -v)).
    """
    za = z * direction(v)   # |z| when z and v have the same sign, negative otherwise
    ramp = sp.sin(sp.pi * (za - (z_max + z_b) / 2) / (z_max - z_b)) / 2 + sp.Rational(1, 2)
    return ac.if_else(za <= z_b, 0, ac.if_else(za >= z_max, 1, ramp))
