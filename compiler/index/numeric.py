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

from ...components.symbols import no_event, time
from ..algebra.derivative import partial
from ..algebra.symbolic import symbols_of

__all__ = ["CoefficientValues"]


class CoefficientValues:
    """``value(e, v)``: d residual_e / d symbol_v at the compile-time point (float, or
    None where it is not a finite number there)."""

    def __init__(self, system, parameters, discretes=()):
        # Why the point is not built here: a large model has tens of thousands of
        # symbols and the checks ask for a few coefficients; each coefficient takes the
        # values of its own symbols (discrete values and time 0, variables their start
        # value, parameters their value, in that order of precedence)
        self.system = system
        self._parameters = {p.symbol: p for p in parameters}    # a value when asked
        self._discretes = {d.symbol for d in discretes}
        self._subs = {}
        self._cache = {}

    def value(self, e: int, v: int):
        key = (e, v)
        if key not in self._cache:
            self._cache[key] = self._evaluate(e, v)
        return self._cache[key]

    def _evaluate(self, e, v):
        c = partial(self.system.equations[e].residual, self.system.symbols[v])
        if c.has(no_event):
            # a coefficient under no_event switches during the run without an event
            # (a flow regularised in a band around 0): its value at the compile-time
            # point says nothing about the block elsewhere, so it is not sampled
            return None
        try:
            if not c.is_number:
                # a relation whose operand is not a number there (0/0 at start values of
                # 0) is refused by sympy with a TypeError: no value at this point
                c = c.xreplace({q: x for q in symbols_of(c)
                                if (x := self._point(q)) is not None})
            x = float(c)
        except (TypeError, ValueError):
            return None
        return x if math.isfinite(x) else None

    def _point(self, q):
        """The value of symbol q at the compile-time point (a Float), or None."""
        if q in self._subs:
            return self._subs[q]
        if q in self._discretes or q == time:
            x = 0.0
        elif q in self.system.index:
            info = self.system.var_info.get(q)
            start = info.attrs.start if info is not None else None
            x = float(start) if start is not None else 0.0
        elif q in self._parameters and is_number(self._parameters[q].value):
            x = float(self._parameters[q].value)
        else:
            x = None
        out = self._subs[q] = sp.Float(x) if x is not None else None
        return out


def is_number(value) -> bool:
    """Whether float(value) works (a parameter's value is a number, not an expression)."""
    if isinstance(value, sp.Expr) and not value.is_number:
        return False           # free symbols: what float() would find out the slow way
    try:
        float(value)
        return True
    except (TypeError, ValueError):
        return False
