"""Exact rational arithmetic for the numeric checks of structural decisions.

Coefficients of numbers and parameters are evaluated with the parameter values as
rationals (``Fraction`` of the float values; an irrational constant such as pi or
sqrt(beta/rho) is one atom with the Fraction of its float value) and eliminated without round-off, so a rank
is a fact, not a tolerance: sparse fraction-free Gaussian elimination with the cheap form
of Markowitz's pivoting (Markowitz, Management Sci. 3, 1957).  Used by
:mod:`acausal.compiler.index.conversion` (Pryce's success test, the LC conversion) and, through
:func:`coefficient_oracle`, by state selection.
"""
from __future__ import annotations

import heapq
from fractions import Fraction
from math import gcd, isfinite, lcm, prod

import sympy as sp

from .derivative import partial

__all__ = ["parameter_values", "exact_value", "exact_rank", "left_null_vectors",
           "integer_vector", "coefficient_oracle"]


# -- exact values ----------------------------------------------------------------------
def parameter_values(parameters) -> dict:
    """symbol -> Fraction of the float value, for every finite numeric parameter (not
    one found by initialization: its value is a guess, no structural fact)."""
    out = {}
    for p in parameters:
        if not getattr(p, "fixed", True):
            continue
        try:
            x = float(p.value)
        except (TypeError, ValueError):
            continue
        if isfinite(x):
            out[p.symbol] = Fraction(x)
    return out


def exact_value(expr: sp.Expr, values: dict):
    """`expr` as a Fraction with the parameters at `values`; None if it contains anything
    else (a variable, time, a parameter without a value) or is not rational."""
    if expr.is_Rational:
        return Fraction(int(expr.p), int(expr.q))
    if expr.is_Float:
        x = float(expr)
        return Fraction(x) if isfinite(x) else None
    if expr.is_Symbol:
        return values.get(expr)
    if expr.is_Add or expr.is_Mul:
        parts = [exact_value(a, values) for a in expr.args]
        if any(q is None for q in parts):
            return None
        return sum(parts, Fraction(0)) if expr.is_Add else prod(parts, start=Fraction(1))
    if expr.is_Pow and expr.exp.is_Integer:
        base = exact_value(expr.base, values)
        if base is None or (base == 0 and expr.exp < 0):
            return None
        return base ** int(expr.exp)
    return _atom_value(expr, values)


def _atom_value(expr: sp.Expr, values: dict):
    """An irrational constant of numbers and parameters (pi, sqrt(beta/rho), sin(k pi/5))
    as the Fraction of its float value.  The same atom always gets the same value, so
    cancellations between equal terms (B w - B w, two rows both B) stay exact; only
    identities sympy does not see as such would be missed."""
    if not (expr.is_number or expr.free_symbols <= values.keys()):
        return None
    try:
        x = complex(expr.xreplace({s: sp.Float(float(values[s]), 30)
                                   for s in expr.free_symbols}).evalf(30))
    except (TypeError, ValueError, ZeroDivisionError):
        return None
    if x.imag != 0 or not isfinite(x.real):
        return None
    return Fraction(x.real)


# -- sparse exact elimination ----------------------------------------------------------
def _eliminate(rows: dict) -> list:
    """Gaussian elimination on sparse rational rows ``{row: {col: Fraction}}``.

    Rows are scaled to integers and updated fraction-free (q <- a q - b p, divided by the
    gcd of its entries): integer arithmetic, no Fraction normalised at every operation.
    Pivot: a column with the fewest non-zeros, then its shortest row (the cheap form of
    Markowitz's rule, minimize (r - 1)(c - 1)), which keeps the fill-in of chains and
    meshes small.  Returns the pivots in order, ``(column, pivot row when chosen)``:
    the integer rows of U, each holding its column and columns pivoted later or never.
    """
    a = {}
    for r, vals in rows.items():
        den = lcm(*(v.denominator for v in vals.values() if v))
        a[r] = {c: int(v * den) for c, v in vals.items() if v}
    col_rows = {}
    for r, vals in a.items():
        for c in vals:
            col_rows.setdefault(c, set()).add(r)
    heap = [(len(rs), c) for c, rs in col_rows.items()]
    heapq.heapify(heap)
    done, pivots = set(), []
    while heap:
        count, c = heapq.heappop(heap)
        if c in done or count != len(col_rows[c]):
            continue                    # stale entry: the count changed since
        done.add(c)
        if count == 0:
            continue
        p = min(col_rows[c], key=lambda r: (len(a[r]), r))
        prow = a.pop(p)
        for q in sorted(col_rows[c] - {p}):
            qrow = a[q]
            g = gcd(prow[c], qrow[c])
            mp, mq = qrow[c] // g, prow[c] // g        # mq row_q - mp row_p: zero at c
            for k in qrow:
                qrow[k] *= mq
            for k, v in prow.items():
                x = qrow.get(k, 0) - mp * v
                if x:
                    qrow[k] = x
                    col_rows[k].add(q)
                else:
                    qrow.pop(k, None)
                    col_rows[k].discard(q)
            g = gcd(*qrow.values())
            if g > 1:
                for k in qrow:
                    qrow[k] //= g
        for k in prow:
            col_rows[k].discard(p)
            if k not in done:
                heapq.heappush(heap, (len(col_rows[k]), k))
        pivots.append((c, prow))
    return pivots


def exact_rank(rows: dict) -> int:
    """Rank of a sparse rational matrix ``{row: {col: Fraction}}``."""
    return len(_eliminate(rows))


def left_null_vectors(rows: dict) -> list:
    """A basis of ``{u : u^T A = 0}`` as dicts ``{row: Fraction}`` (empty if full row rank).

    The left null space of A is the right null space of A^T: eliminate A^T, then for
    each free column (a row of A that no pivot took) back-substitute through U with
    that unknown set to 1 — linear in the size of U, where tracking row combinations
    during the elimination would be quadratic on a chain.
    """
    cols = {}
    for r, vals in rows.items():
        for c, v in vals.items():
            if v:
                cols.setdefault(c, {})[r] = v
    pivots = _eliminate(cols)
    pivoted = {c for c, _ in pivots}
    out = []
    for f in sorted(r for r in rows if r not in pivoted):
        u = {f: Fraction(1)}
        for c, prow in reversed(pivots):
            acc = sum((v * u[k] for k, v in prow.items() if k != c and k in u), Fraction(0))
            if acc:
                u[c] = -acc / prow[c]
        out.append(u)
    return out


# -- the oracle for state selection ------------------------------------------------------
def coefficient_oracle(system, values: dict):
    """``coefficient(eq, var) -> Fraction | None``: the exact coefficient of variable
    `var` in equation `eq` of `system` (looked up when called, so it sees equations that
    index reduction appends), or None if it is not a constant of numbers and parameters."""
    cache = {}

    def coefficient(eq: int, var: int):
        key = (eq, var)
        if key not in cache:
            expr = partial(system.equations[eq].residual, system.symbols[var])
            cache[key] = exact_value(expr, values)
        return cache[key]

    return coefficient


def integer_vector(u: dict, target: int) -> dict:
    """u scaled to coprime integers with a positive entry at `target`."""
    den = lcm(*(q.denominator for q in u.values()))
    ints = {i: int(q * den) for i, q in u.items()}
    g = gcd(*ints.values()) * (1 if ints[target] > 0 else -1)
    return {i: v // g for i, v in ints.items()}
