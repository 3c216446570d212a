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

from ...components.symbols import delay
from ...errors import ModelError

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
        if not eq.is_plain() and _has_delay(eq.residual):   # (FlatEquation.plain)
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
