"""The coefficients of the MSL's analog filters (Modelica.Blocks.Continuous.Internal.Filter),
as numbers.

A base filter is a low pass with cut-off angular frequency 1 rad/s, given as its real
poles' coefficients cr (factors s + cr) and its complex pairs' c0, c1 (factors s^2 + c1 s
+ c0).  ``base`` returns them for CriticalDamping, Bessel, Butterworth and ChebyshevI;
``roots`` transforms them to a low, high, band pass or band stop filter at the cut-off
frequency and returns what the block's differential equations need (the MSL's
Internal.Filter.roots): the real eigenvalues r, the complex ones a +- j b, the input
gains ku and the output gains k1, k2.

"normalized" moves the cut-off so that the amplitude there is -3 dB (10^(-3/20), as the
MSL, not 1/sqrt(2)).  Bessel's base polynomials are computed here from the reverse
Bessel polynomial (the MSL tabulates them): its roots, scaled to -3 dB at 1 rad/s,
real pole first, the complex pairs in the order of decreasing damping.
"""
from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

__all__ = ["ANALOG_FILTERS", "FILTER_TYPES", "base", "roots", "normalization_factor"]

ANALOG_FILTERS = ("CriticalDamping", "Bessel", "Butterworth", "ChebyshevI")
FILTER_TYPES = ("LowPass", "HighPass", "BandPass", "BandStop")
_BETA = 10 ** (-3 / 20)          # amplitude of -3 dB


def _highest_power_one(den1, den2):
    """(a p + 1) -> cr (p + cr); (b p^2 + a p + 1) -> (p^2 + c1 p + c0) (MSL
    Utilities.toHighestPowerOne)."""
    cr = np.array([1 / a for a in den1])
    c1 = np.array([a / b for b, a in den2])
    c0 = np.array([1 / b for b, _ in den2])
    return cr, c0, c1


def _amplitude_residue(den1, den2, alpha):
    """|G(j)| - beta of the filter with p replaced by alpha p (MSL
    Utilities.normalizationFactor.normalizationResidue)."""
    A2 = 1.0
    for a in den1:
        A2 *= 1 + (a * alpha)**2
    for b, a in den2:
        A2 *= 1 + (a * a - 2 * b) * alpha**2 + (b * alpha**2)**2
    return 1 / math.sqrt(A2) - _BETA


def normalization_factor(den1, den2) -> float:
    """alpha such that the filter with p -> alpha p has -3 dB at 1 rad/s."""
    hi = 1.0
    while _amplitude_residue(den1, den2, hi) >= 0:
        hi *= 1.1
    return brentq(lambda x: _amplitude_residue(den1, den2, x), 0.0, hi,
                  xtol=1e-15, rtol=4 * np.finfo(float).eps)


def _scaled(den1, den2, alpha):
    return [a * alpha for a in den1], [(b * alpha**2, a * alpha) for b, a in den2]


def _bessel(order: int, normalized: bool):
    """den1, den2 of the Bessel filter: the reverse Bessel polynomial
    theta_n(s) = sum_k (2n - k)! / (2^(n-k) k! (n-k)!) s^k (group delay 1 at s = 0),
    normalized to -3 dB at 1 rad/s if ``normalized``."""
    if not 1 <= order <= 20:
        raise ValueError(f"a Bessel filter of order {order}: orders 1 .. 20 are supported")
    n = order
    coeffs = [math.factorial(2 * n - k) / (2**(n - k) * math.factorial(k)
                                            * math.factorial(n - k)) for k in range(n + 1)]
    poles = np.roots(coeffs[::-1])
    den1 = [-1 / p.real for p in poles if abs(p.imag) < 1e-9 * abs(p)]
    pairs = sorted((p for p in poles if p.imag > 1e-9 * abs(p)),
                   key=lambda p: p.real / abs(p))       # most damped first
    den2 = [(1 / abs(p)**2, -2 * p.real / abs(p)**2) for p in pairs]
    if normalized:
        den1, den2 = _scaled(den1, den2, normalization_factor(den1, den2))
    return den1, den2


def base(analogFilter: str, order: int, normalized: bool = True, A_ripple: float = 0.5):
    """cr, c0, c1 of the base low pass (1 rad/s) (MSL Internal.Filter.base.*)."""
    if analogFilter == "CriticalDamping":
        alpha = math.sqrt(10**(3 / 10 / order) - 1) if normalized else 1.0
        return _highest_power_one([alpha] * order, [])
    if analogFilter == "Bessel":
        return _highest_power_one(*_bessel(order, normalized))
    if analogFilter == "Butterworth":
        # the MSL does not normalize the Butterworth filter (already -3.01 dB at 1 rad/s)
        den2 = [(1.0, -2 * math.cos(math.pi * (0.5 + (i - 0.5) / order)))
                for i in range(1, order // 2 + 1)]
        return _highest_power_one([1.0] * (order % 2), den2)
    if analogFilter == "ChebyshevI":
        eps = math.sqrt(10**(A_ripple / 10) - 1)
        fac = math.asinh(1 / eps) / order
        den1 = [1 / math.sinh(fac)] * (order % 2)
        angle = ((lambda i: (2 * i - 1) * math.pi / (2 * order)) if order % 2 == 0
                 else (lambda i: i * math.pi / order))
        den2 = []
        for i in range(1, order // 2 + 1):
            b = 1 / (math.cosh(fac)**2 - math.cos(angle(i))**2)
            den2.append((b, 2 * b * math.sinh(fac) * math.cos(angle(i))))
        if normalized:
            den1, den2 = _scaled(den1, den2, normalization_factor(den1, den2))
        return _highest_power_one(den1, den2)
    raise ValueError(f"analogFilter = {analogFilter!r} is not one of {ANALOG_FILTERS}")


def _band_alpha(a, b, w):
    """alpha of the band transformation of s^2 + a s + b with bandwidth w (MSL
    Utilities.bandPassAlpha): z = alpha^2 solves
    z^2 + (a w z/(1 + z))^2 - (2 + b w^2) z + 1 = 0 in (0, 1)."""
    if a * a / 4 - b > 0:
        raise ValueError("the band transformation of this filter has no complex poles")
    z = brentq(lambda z: z**2 + (a * w * z / (1 + z))**2 - (2 + b * w * w) * z + 1, 0.0, 1.0,
               xtol=1e-15, rtol=4 * np.finfo(float).eps)
    return math.sqrt(z)


def roots(filterType, cr, c0, c1, f_cut, f_min=0.0) -> dict:
    """r, a, b, ku, k1, k2 of the filter at f_cut (band: f_min .. f_cut) (MSL
    Internal.Filter.roots.* with coefficients.*)."""
    w = 2 * math.pi * f_cut
    if filterType == "LowPass":
        a = -w * c1 / 2
        b = np.sqrt(w * w * c0 - a * a)
        return dict(r=-w * cr, a=a, b=b, ku=w * w * c0 / b, k1=np.array([]), k2=np.array([]))
    if filterType == "HighPass":
        r = -w / cr
        C0, C1 = w * w / c0, w * c1 / c0
        a = -C1 / 2
        b = np.sqrt(C0 - a * a)
        ku = C0 / b
        ba2 = (b / a)**2
        return dict(r=r, a=a, b=b, ku=ku, k1=2 * a / ku, k2=(1 - ba2) / (1 + ba2))
    if filterType not in ("BandPass", "BandStop"):
        raise ValueError(f"filterType = {filterType!r} is not one of {FILTER_TYPES}")
    if not 0 < f_min < f_cut:
        raise ValueError(f"a band filter needs 0 < f_min < f_cut, got f_min = {f_min}, "
                         f"f_cut = {f_cut}")
    f0 = math.sqrt(f_min * f_cut)
    w_cut, w_band = 2 * math.pi * f0, (f_cut - f_min) / f0
    C0, C1 = [], []
    for c in cr:
        C1.append(w_cut * (c * w_band if filterType == "BandPass" else w_band / c))
        C0.append(w_cut**2)
    for q0, q1 in zip(c0, c1):
        ww = w_band if filterType == "BandPass" else w_band / q0
        alpha = _band_alpha(q1, q0, ww)
        c = q1 * ww / (alpha + 1 / alpha)
        C1 += [w_cut * c / alpha, w_cut * c * alpha]
        C0 += [w_cut**2 / alpha**2, w_cut**2 * alpha**2]
    C0, C1 = np.array(C0), np.array(C1)
    a = -C1 / 2
    bb = C0 - a * a
    if np.any(bb < 0):
        raise ValueError("the band transformation of this filter has no complex poles; "
                         "use another analog filter")
    b = np.sqrt(bb)
    ku = C0 / b
    if filterType == "BandPass":
        cn = w_band * w_cut
        return dict(r=np.array([]), a=a, b=b, ku=ku, k1=cn / ku, k2=cn * a / (b * ku))
    return dict(r=np.array([]), a=a, b=b, ku=ku, k1=2 * a / ku,
                k2=(C0 + a * a - b * b) / (b * ku))
