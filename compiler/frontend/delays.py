"""Time delays ``delay(expr, T)`` as values the runtime supplies from its history.

Modelica's ``delay(expr, T)`` (Modelica Language Specification 3.7.2.2) is expr at time
``time - T``.  Its value is no function of the current unknowns: once the integrator's
step is limited to T (the runtime does that), ``time - T`` lies in the part of the
solution already accepted, so for the generated code a delay is an *input*, read from a
buffer the runtime keeps (:mod:`acausal.runtime.delays`).  This pass replaces every
``delay(expr, T)`` by a symbol ``delay(expr, T)`` that the generated code reads from
the parameter vector, after the tunable parameters (``p[n_params + j]``), and records
the delayed expression (compiled into its own function of the unknowns, so the runtime
can sample it) and the delay time (an expression of parameters, evaluated at run time).

Nothing downstream differentiates a delay symbol: an equation with a delay that index
reduction would have to differentiate is refused (:meth:`SymbolicSystem.time_derivative`
raises), since d/dt delay(u, T) = delay(der(u), T) needs a history of der(u).
"""
from __future__ import annotations

import sympy as sp

from ...components.component import ModelError
from ...components.symbols import delay
from ..gcpause import gc_paused

__all__ = ["DelayValue", "extract_delays"]


class DelayValue:
    """One ``delay(argument, T)``: ``symbol`` stands for its value in the equations."""

    __slots__ = ("symbol", "argument", "T", "text", "where")

    def __init__(self, symbol, argument, T, text, where):
        self.symbol, self.argument, self.T = symbol, argument, T
        self.text, self.where = text, where

    def __repr__(self):
        return f"DelayValue({self.text})"


def _innermost(e: sp.Basic) -> list:
    """The delay() nodes of e whose argument holds no other delay, in a canonical order."""
    return sorted((d for d in e.atoms(delay) if not d.args[0].has(delay)
                   and not d.args[1].has(delay)), key=sp.srepr)


@gc_paused
def extract_delays(flat) -> list:
    """Replace every delay() in the equations, initial equations and when-clauses of
    ``flat`` by a symbol (in place); return the :class:`DelayValue` list.  A delay time
    that is not a positive expression of parameters is a ModelError naming the delay
    and its component."""
    found: dict = {}
    params = {p.symbol: p for p in flat.parameters}

    def replace(e, where):
        if not isinstance(e, sp.Basic) or not e.has(delay):
            return e
        while e.has(delay):
            for node in _innermost(e):
                if node not in found:
                    found[node] = _new(node, len(found), where, params, flat)
                e = e.xreplace({node: found[node].symbol})
        return e

    for eq in flat.equations + flat.initial_equations:
        if eq.plain is not eq.residual and _has_delay(eq.residual):   # (FlatEquation.plain)
            eq.residual = replace(eq.residual, _where(eq))
    for w in flat.whens:
        where = f"{w.origin or '(model)'} ({w.origin_class})"
        w.condition = replace(w.condition, where)
        for act in w.actions:
            act.value = replace(act.value, where)
    return list(found.values())


def _has_delay(e) -> bool:
    """``e.has(delay)`` by one walk over the arguments (sympy's ``has`` builds an
    iterator and a type test per node; most equations hold no delay)."""
    stack = [e]
    while stack:
        node = stack.pop()
        if isinstance(node, delay):
            return True
        if not node.is_Atom:
            stack.extend(node.args)
    return False


def _where(eq) -> str:
    return f"{eq.component or '(model)'} ({eq.component_class})"


def _new(node, k, where, params, flat) -> DelayValue:
    argument, T = node.args
    text = f"delay({sp.sstr(argument)}, {sp.sstr(T)})"
    bad = [q for q in T.free_symbols if q not in params]
    if bad:
        raise ModelError(f"{text} in {where}: the delay time must be an expression of "
                         f"parameters, but it reads {', '.join(sorted(q.name for q in bad))}")
    value = _value(T, params)
    if not (value > 0 and value < float("inf")):
        raise ModelError(f"{text} in {where}: the delay time must be positive and "
                         f"finite, it is {value!r} with the parameter values given")
    symbol = sp.Symbol(text, real=True)
    return DelayValue(symbol, argument, T, text, where)


def _value(T, params) -> float:
    """T at the parameter values (a parameter may be bound to others)."""
    for _ in range(100):
        free = [q for q in T.free_symbols if q in params]
        if not free:
            break
        T = T.xreplace({q: sp.sympify(params[q].value) for q in free})
    try:
        return float(T)
    except (TypeError, ValueError):
        return float("nan")


def feeds_back(system, delays) -> bool:
    """Whether a delayed value can reach a delayed expression (a loop through a delay),
    judged on the connectivity of the equations: symbols of one equation, and x with
    der(x), are connected.  Connectivity over-approximates dependence, so the answer
    errs towards True.  Without such a loop a discontinuity comes back through a delay
    once and stops (the runtime then follows one generation instead of six)."""
    parent = {}

    def find(q):
        parent.setdefault(q, q)
        while parent[q] is not q:
            parent[q] = parent[parent[q]]
            q = parent[q]
        return q

    def union(a, b):
        ra, rb = find(a), find(b)
        if ra is not rb:
            parent[ra] = rb

    for eq in system.equations:
        syms = list(eq.residual.free_symbols)
        for q in syms[1:]:
            union(syms[0], q)
    for x, dx in system.derivatives.items():
        union(x, dx)
    roots = {find(d.symbol) for d in delays}
    return any(find(q) in roots for d in delays for q in d.argument.free_symbols
               if q in parent)


def delay_code(delays, rows, code, parameters, psyms, known, feedback=True):
    """The :class:`~acausal.compiler.modelcode.DelayCode` of the model: ``code`` computes
    the delayed expressions (``rows``) from the unknowns; each delay time becomes a
    float or a function of the tunable parameters ``psyms``."""
    from ...components.symbols import time
    from ..modelcode import DelayCode
    from ..assemble import _parameter_functions
    for d, row in zip(delays, rows):
        unknown = sorted(q.name for q in row.free_symbols if q not in known and q != time)
        if unknown:
            raise ModelError(f"{d.text} in {d.where}: the delayed expression reads "
                             f"{', '.join(unknown)}, which the compiled model does not "
                             "compute")
    values = {p.symbol: p for p in parameters}
    tunable = set(psyms)
    times, exprs = [], {}
    for d in delays:
        T = d.T
        for _ in range(100):                 # parameters bound to others, down to tunables
            bound = {q: sp.sympify(values[q].value) for q in T.free_symbols
                     if q in values and q not in tunable}
            if not bound:
                break
            T = T.xreplace(bound)
        if T.free_symbols:
            exprs[d.text] = T
            times.append(None)
        else:
            times.append(float(T))
    funcs = dict(_parameter_functions(exprs, psyms)) if exprs else {}
    times = [funcs[d.text] if t is None else t for d, t in zip(delays, times)]
    return DelayCode(code, [d.text for d in delays], times, [d.where for d in delays],
                     feedback)
