"""Numeric values of incidence coefficients, for the checks of structural decisions.

The structural passes decide on integers; some decisions are only as good as the numbers
behind them (how a torn block amplifies errors, for one).  ``CoefficientValues`` gives the
value of the coefficient of variable v in equation e, ``d residual_e / d v``, at the
parameter values and start values the model was compiled with -- exact where the
coefficient is a number or an expression of parameters, a sample where it depends on the
variables.  Values are computed on demand and cached.
"""
from __future__ import annotations

import math

import sympy as sp

from ..components.symbols import time
from .derivative import partial

__all__ = ["CoefficientValues"]


class CoefficientValues:
    """``value(e, v)``: d residual_e / d symbol_v at the compile-time point (float, or
    None where it is not a finite number there)."""

    def __init__(self, system, parameters, discretes=()):
        self.system = system
        subs = {p.symbol: sp.Float(float(p.value)) for p in parameters if _is_number(p.value)}
        for sym in system.symbols:
            info = system.var_info.get(sym)
            start = info.attrs.start if info is not None else None
            subs[sym] = sp.Float(float(start) if start is not None else 0.0)
        subs[time] = sp.Float(0.0)
        for d in discretes:
            subs[d.symbol] = sp.Float(0.0)
        self._subs = subs
        self._cache = {}

    def value(self, e: int, v: int):
        key = (e, v)
        if key not in self._cache:
            self._cache[key] = self._evaluate(e, v)
        return self._cache[key]

    def _evaluate(self, e, v):
        c = partial(self.system.equations[e].residual, self.system.symbols[v])
        if not c.is_number:
            c = c.xreplace(self._subs)
        try:
            x = float(c)
        except (TypeError, ValueError):
            return None
        return x if math.isfinite(x) else None


def _is_number(value) -> bool:
    try:
        float(value)
        return True
    except (TypeError, ValueError):
        return False
