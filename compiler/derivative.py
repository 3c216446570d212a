"""Partial derivatives for the compiler, fast on the expressions models are made of.

sympy's ``diff`` is general and slow (about a millisecond a call); the equations of a
physical model are mostly sums of products in which a variable appears once, linearly.
``partial(expr, x)`` handles those directly (d/dx of c*x*y is c*y) and falls back to
sympy otherwise.  Results are cached: the same partials are needed for the incidence
coefficients, the Jacobian and the initialization Jacobian.
"""
from __future__ import annotations

from functools import lru_cache

import sympy as sp

__all__ = ["partial"]


@lru_cache(maxsize=200_000)
def partial(expr: sp.Expr, x: sp.Symbol) -> sp.Expr:
    """d expr / d x."""
    if not expr.has(x):
        return sp.Integer(0)
    if expr == x:
        return sp.Integer(1)
    if expr.is_Add:
        return sp.Add(*[partial(a, x) for a in expr.args if a.has(x)])
    if expr.is_Mul:
        # product rule over the factors that contain x
        args = expr.args
        terms = []
        for i, a in enumerate(args):
            if a.has(x):
                terms.append(sp.Mul(*args[:i], partial(a, x), *args[i + 1:]))
        return sp.Add(*terms)
    if expr.is_Pow and not expr.exp.has(x):
        # r u^(r-1) u' directly: sympy writes r u^r/u, which is 0/0 where u = 0
        base, r = expr.args
        return r * base ** (r - 1) * partial(base, x)
    return sp.diff(expr, x)
