"""Analog filters (Modelica.Blocks.Continuous.Filter and CriticalDamping).

The filter's coefficients are numbers computed when the model is compiled
(``filter_design``); a low or high pass keeps its cut-off frequency ``f_cut`` as a
parameter (its eigenvalues scale with 2 pi f_cut), a band pass or band stop needs
``f_min`` and ``f_cut`` as numbers.
"""
from __future__ import annotations

import math
import numbers

from acausal._sympy import sympy as sp

import acausal as ac

from . import filter_design
from .interfaces import SISO

__all__ = ["Filter", "CriticalDamping"]


def _choice(block, name, value, choices):
    if value not in choices:
        import difflib
        close = difflib.get_close_matches(str(value), choices, n=1)
        hint = f" (did you mean '{close[0]}'?)" if close else ""
        raise ac.InvalidValue(f"{block}: {name} = {value!r} is not one of "
                              f"{', '.join(choices)}{hint}")
    return value


def _number(c, name):
    value = c.parameter_value(name)
    if not isinstance(value, numbers.Real):
        raise ac.InvalidValue(f"{c._describe()}: {name} must be a number for this filter "
                              f"(its coefficients are computed from it), not {value}")
    return float(value)


class Filter(SISO):
    """Low pass, high pass, band pass or band stop filter of type CriticalDamping, Bessel,
    Butterworth or ChebyshevI (MSL Blocks.Continuous.Filter), as real poles r and
    complex pole pairs a +- j b of the input scaled to uu[0] = u/u_nominal, in series:

        der(x[i]) = r[i] (x[i] - uu[i])                                 (real poles)
        der(x1) = a x1 - b x2 + ku uu,   der(x2) = b x1 + a x2          (complex pairs)
        low pass:   uu' = x (real),              uu' = x2 (pairs)
        high pass:  uu' = -x + uu (real),        uu' = k1 x1 + k2 x2 + uu (pairs)
        band pass:  uu' = k1 x1 + k2 x2,         band stop: uu' = k1 x1 + k2 x2 + uu
        y = gain u_nominal uu[last]

    The states x[0 .. nx-1] are the MSL's x[1 .. nx] (real poles first).  It starts in
    steady state, der(x) = 0, as the MSL's default initType = SteadyState; the other
    choices (``ac.Init``) as the MSL's, InitialState with every state at x_start.  ``analogFilter``, ``filterType``, ``order`` and
    ``normalized`` (amplitude -3 dB at f_cut) are given when the block is made;
    a band filter's pass band is f_min .. f_cut.
    """

    f_cut = ac.Parameter(1.0, unit="Hz", description="cut-off frequency")
    gain = ac.Parameter(1.0, description="amplitude of the frequency response at 0 "
                                         "(low pass) or infinity (high pass)")
    A_ripple = ac.Parameter(0.5, description="pass band ripple [dB] (ChebyshevI), > 0")
    f_min = ac.Parameter(0.0, unit="Hz", description="lower end of the band (band filters)")
    u_nominal = ac.Parameter(1.0, description="nominal value of the input (scales the states)")
    x = ac.Variable(shape="nx", start=0.0, description="filter states")
    initType = ac.Init.parameter("SteadyState")
    x_start = ac.Parameter(0.0, description="initial value of every state (InitialState)")
    y_start = ac.Parameter(0.0, description="initial value of the output (InitialOutput)")
    uu = ac.Variable(shape="n_uu", description="input and the outputs of the sections")

    def __init__(self, *, analogFilter: str = "CriticalDamping", filterType: str = "LowPass",
                 order: int = 2, normalized: bool = True, **modifications):
        self.analogFilter = _choice("Filter", "analogFilter", analogFilter,
                                    filter_design.ANALOG_FILTERS)
        self.filterType = _choice("Filter", "filterType", filterType,
                                  filter_design.FILTER_TYPES)
        if isinstance(order, bool) or not isinstance(order, int) or order < 1:
            raise ac.InvalidValue(f"Filter: order = {order!r} must be an integer >= 1")
        self.order, self.normalized = order, bool(normalized)
        band = filterType in ("BandPass", "BandStop")
        self.nx = 2 * order if band else order
        critical = analogFilter == "CriticalDamping"
        self.na = order if band else (0 if critical else order // 2)
        self.nr = 0 if band else (order if critical else order % 2)
        self.n_uu = self.na + self.nr + 1
        super().__init__(**modifications)

    def coefficients(self):
        """r, a, b, ku, k1, k2 (expressions: multiples of 2 pi f_cut for a low or high
        pass, numbers for a band filter)."""
        A = (_number(self, "A_ripple") if self.analogFilter == "ChebyshevI" else 0.5)
        cr, c0, c1 = filter_design.base(self.analogFilter, self.order, self.normalized, A)
        if self.filterType in ("LowPass", "HighPass"):
            # the eigenvalues at 1 rad/s, scaled by the (tunable) cut-off
            k = filter_design.roots(self.filterType, cr, c0, c1, 1 / (2 * math.pi))
            w = 2 * sp.pi * self.f_cut
            return {name: [v * w for v in k[name]] if name in ("r", "a", "b", "ku")
                    else list(k[name]) for name in k}
        k = filter_design.roots(self.filterType, cr, c0, c1, _number(self, "f_cut"),
                                _number(self, "f_min"))
        return {name: list(v) for name, v in k.items()}

    def initial_equations(self):
        """The MSL's initType (default SteadyState); InitialOutput holds der(x[0 ..
        nx-2]) = 0, the MSL's der(x[1:nx-1])."""
        x = list(self.x)
        return ac.Init.equations(self.initType, x, [self.x_start] * len(x), self.y,
                                 self.y_start, free_at_output=x[:-1])

    def equations(self):
        k = self.coefficients()
        x, uu, nr = list(self.x), list(self.uu), self.nr
        eqs = [ac.Eq(uu[0], self.u / self.u_nominal)]
        for i in range(nr):
            eqs.append(ac.Eq(ac.der(x[i]), k["r"][i] * (x[i] - uu[i])))
        for i in range(self.na):
            x1, x2 = x[nr + 2 * i], x[nr + 2 * i + 1]
            a, b = k["a"][i], k["b"][i]
            eqs += [ac.Eq(ac.der(x1), a * x1 - b * x2 + k["ku"][i] * uu[nr + i]),
                    ac.Eq(ac.der(x2), b * x1 + a * x2)]
        kind = self.filterType
        for i in range(nr):
            eqs.append(ac.Eq(uu[i + 1], x[i] if kind == "LowPass" else -x[i] + uu[i]))
        for i in range(self.na):
            x1, x2, before = x[nr + 2 * i], x[nr + 2 * i + 1], uu[nr + i]
            out = (x2 if kind == "LowPass"
                   else k["k1"][i] * x1 + k["k2"][i] * x2 + (0 if kind == "BandPass" else before))
            eqs.append(ac.Eq(uu[nr + i + 1], out))
        eqs.append(ac.Eq(self.y, self.gain * self.u_nominal * uu[-1]))
        return eqs


class CriticalDamping(SISO):
    """n first-order low passes in series, each with the same cut-off (MSL
    Blocks.Continuous.CriticalDamping):

        der(x[0]) = w (u - x[0]),   der(x[i]) = w (x[i-1] - x[i]),   y = x[n-1],
        w = 2 pi f / alpha,   alpha = sqrt(2^(1/n) - 1) if normalized, else 1

    (``normalized``: the amplitude at f is 1/sqrt(2)).  ``n`` and ``normalized`` are
    given when it is made.  Its states start from their start values (0; the MSL's
    default init = NoInit leaves them to the tool).
    """

    f = ac.Parameter(1.0, unit="Hz", description="cut-off frequency")
    x = ac.Variable(shape="n", start=0.0, description="filter states")

    def __init__(self, *, n: int = 2, normalized: bool = True, **modifications):
        if isinstance(n, bool) or not isinstance(n, int) or n < 1:
            raise ac.InvalidValue(f"CriticalDamping: n = {n!r} must be an integer >= 1")
        self.n, self.normalized = n, bool(normalized)
        super().__init__(**modifications)

    def equations(self):
        alpha = math.sqrt(2**(1 / self.n) - 1) if self.normalized else 1.0
        w = 2 * sp.pi * self.f / alpha
        x = list(self.x)
        inputs = [self.u.signal] + x[:-1]
        return [*(ac.Eq(ac.der(xi), (ui - xi) * w) for xi, ui in zip(x, inputs)),
                ac.Eq(self.y, x[-1])]

