"""An if-expression inside the condition of another, kept as one expression.

sympy folds every ``Piecewise`` that appears inside the condition of another one into
the condition (``Piecewise((a, P > 0), ...)`` with ``P = Piecewise((u, x > 0), (v,
True))`` becomes ``ITE(x > 0, u > 0, v > 0)``): n if-expressions of k branches in one
condition become k^n relations, and the condition of a long inline model (a creep law
normalized where it exceeds a friction bound, both made of profile functions with their
own cases) never finishes building.  Modelica keeps such a relation as one relation
whose sides are evaluated in the modes of the relations inside them, and so does
acausal: inside a condition an if-expression is an :class:`IfExpr`, which sympy does not
fold; the compiler (:func:`acausal.compiler.codegen.extract_relations`) gives every
relation its own mode and turns each ``IfExpr`` back into an if-expression in the
frozen modes.  ``abs``, ``min``, ``max`` and ``sign`` are sympy functions, not
if-expressions, so they never fold.  An if-expression of numbers only (a flag such as
``if_else(v > dv, 0, 1)`` compared with 0) is left to sympy: its fold is logic over its
relations, exact and as small as the flag.
"""
from __future__ import annotations

import sympy as sp

__all__ = ["IfExpr", "unfolded_condition"]


class IfExpr(sp.Function):
    """``IfExpr(e1, c1, e2, c2, ..., en, True)``: e1 where c1 holds, else e2 where c2
    holds, ..., else en -- the if-expression of ``if_else`` where it appears inside a
    condition (module docstring)."""

    @classmethod
    def eval(cls, *args):
        return None

    def _eval_is_real(self):
        return True

    def pairs(self) -> list:
        a = self.args
        return [(a[k], a[k + 1]) for k in range(0, len(a), 2)]

    def _sympystr(self, printer):
        pairs = self.pairs()
        text = printer._print(pairs[-1][0])
        for e, c in reversed(pairs[:-1]):
            text = f"if_else({printer._print(c)}, {printer._print(e)}, {text})"
        return text


def unfolded_condition(cond):
    """``cond`` with every if-expression inside it made an :class:`IfExpr` (walked as
    a DAG, without recursion: :mod:`acausal.compiler.dag`)."""
    from ..compiler.algebra.dag import postorder, transform
    flags = set()      # if-expressions of numbers (and of such if-expressions): flags
    kept = False
    for n in postorder([cond]):
        if isinstance(n, sp.Piecewise):
            if all(e.is_Number or e in flags for e, _ in n.args):
                flags.add(n)
            else:
                kept = True
    if not kept:
        return cond

    def rebuild(node, args, _ctx):
        if isinstance(node, sp.Piecewise) and node not in flags:
            flat = [x for pair in args for x in pair.args]
            return IfExpr(*flat)
        if isinstance(node, sp.functions.elementary.piecewise.ExprCondPair):
            return sp.Tuple(*args)           # read by the Piecewise above it
        if all(a is b for a, b in zip(args, node.args)):
            return node
        return node.func(*args)

    return transform(cond, rebuild)

