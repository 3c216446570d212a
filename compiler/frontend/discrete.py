"""Integer-valued functions (floor, ceiling, mod, frac) as discrete values frozen between events.

In Modelica, ``floor(u)``, ``ceil(u)``, ``mod(u, P)`` and friends generate events: their
value is held while the integrator steps and changes only at an event where ``u`` crosses
an integer (Modelica Language Specification 3.6, sec. 3.7.3).  The same here: every
``floor(u)`` becomes a discrete symbol ``n`` that the runtime holds at ``floor(u)`` of the
last event, with the crossing functions ``u - n`` and ``n + 1 - u`` watching for the next
one.  The others are written through floor first::

    ceiling(u) = -floor(-u),   Mod(u, P) = u - P floor(u/P),   frac(u) = u - floor(u).

With ``n`` frozen, a periodic signal such as ``Mod(time - t0, P) < w P`` is linear in time
between events, so its edges are known before they happen (exact time events, see
:mod:`acausal.runtime.events`).  A discrete symbol has derivative 0 for index reduction,
as a parameter has.  Inside ``no_event(...)`` the functions are evaluated directly.
"""
from __future__ import annotations

import sympy as sp

from ...components.symbols import no_event


__all__ = ["DiscreteValue", "freeze_integer_functions"]


class DiscreteValue:
    """A frozen ``floor(argument)``: ``symbol`` stands for it in the equations."""

    __slots__ = ("symbol", "argument", "text")

    def __init__(self, symbol, argument, text):
        self.symbol, self.argument, self.text = symbol, argument, text

    def __repr__(self):
        return f"DiscreteValue({self.text})"


def _through_floor(e: sp.Expr) -> sp.Expr:
    """ceiling, Mod and frac written with floor (sympy keeps them symbolic for symbols)."""
    rules = [(sp.ceiling, lambda u: -sp.floor(-u)),
             (sp.frac, lambda u: u - sp.floor(u)),
             (sp.Mod, lambda u, P: u - P * sp.floor(u / P))]
    for f, rewrite in rules:
        if e.has(f):
            e = e.replace(f, rewrite)
    return e


_INTEGER_FUNCTIONS = (sp.floor, sp.ceiling, sp.Mod, sp.frac)


def _has_type(e: sp.Basic, types: tuple) -> bool:
    """``e.has(*types)`` for classes: a node of one of them anywhere in the tree (one
    walk for all of them, where sympy walks once per class)."""
    stack = [e]
    while stack:
        node = stack.pop()
        if isinstance(node, types):
            return True
        stack.extend(node.args)
    return False


def freeze_integer_functions(flat) -> list:
    """Replace floor atoms in every equation and when-clause of ``flat`` by discrete
    symbols (in place); return the :class:`DiscreteValue` list, in a canonical order."""
    found: dict = {}

    def freeze(e):
        if not isinstance(e, sp.Basic) or not _has_type(e, _INTEGER_FUNCTIONS):
            return e
        quiet = {q: sp.Dummy() for q in e.atoms(no_event)}
        e = _through_floor(e.xreplace(quiet) if quiet else e)
        for atom in sorted(e.atoms(sp.floor), key=sp.srepr):
            arg = atom.args[0]
            if arg not in found:
                found[arg] = sp.Symbol(f"floor({sp.sstr(arg)})", real=True)
        e = e.xreplace({sp.floor(a): s for a, s in found.items()})
        return e.xreplace({d: q for q, d in quiet.items()}) if quiet else e

    for eq in flat.equations + flat.initial_equations:
        if not eq.is_plain():      # a sum of +-symbols holds no floor()
            eq.residual = freeze(eq.residual)
    for w in flat.whens:
        w.condition = freeze(w.condition)
        for act in w.actions:
            act.value = freeze(act.value)
    return [DiscreteValue(s, a, s.name) for a, s in found.items()]
