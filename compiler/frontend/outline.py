"""The ``outline`` pass: a long inline expression split into named intermediate quantities.

A user may write a whole force law inline -- a wheelset's creep forces, built from the
wheel and rail profiles, the contact angles and the normal forces, every intermediate
quantity a Python variable holding an expression.  The residual is then a DAG of a few
thousand distinct subexpressions whose *tree* (each shared part counted where it is
used) has hundreds of thousands of nodes, and every pass that walks it as sympy does --
incidence, partial derivatives, time derivatives, printing, substitution -- pays the
tree, and recurses as deep as it is.  A Modelica user would have written the
intermediate quantities as variables, and with them the same model compiles in a
second.  This pass does it for them, on the DAG (:mod:`acausal.compiler.dag`: each
distinct node once, no recursion):

* a residual whose tree has at least ``OUTLINE_FROM`` nodes is walked children first;
  a subexpression that depends on a variable (or time) becomes an intermediate variable
  ``<component>._x<k>`` with its own equation ``_x<k> = <subexpression>`` when what it
  holds, counting the intermediates already made as one node each, reaches ``LOCAL``
  nodes, or ``SHARED`` nodes where it is used more than once;
* so every equation after the pass has at most about ``LOCAL`` nodes of its own beside
  the intermediates it reads, and a depth bounded by that: the later passes, whatever
  they do on an expression, do it on small ones, and the work is linear in the size of
  the DAG;
* an intermediate is never a state (``state_select = "never"``: index reduction may
  differentiate its equation, the dummy derivative is then its own) and starts at its
  value at the start values; a result can read it by its name, as any variable.

Not split: the inside of ``no_event``, ``delay`` and ``pre`` (whose argument must stay
what it is), conditions themselves (relations are kept whole, their sides are split),
and the initial equations.
"""
from __future__ import annotations

import math

import sympy as sp

from ...components.symbols import Equation
from ..algebra.dag import postorder, tree_reaches, tree_size

__all__ = ["outline_expressions", "definition_of", "OUTLINE_FROM", "LOCAL", "SHARED",
           "INTERMEDIATE"]

OUTLINE_FROM = 4000    # residuals with a tree of at least this many nodes are split
LOCAL = 64             # an intermediate holds about this many nodes of its own ...
SHARED = 8             # ... or this many where it is used more than once
INTERMEDIATE = "intermediate"      # FlatVariable.kind of the variables this pass makes


def outline_expressions(flat) -> int:
    """Split the long residuals of ``flat`` in place (module docstring); returns the
    number of intermediate variables made."""
    from ...components.symbols import time
    from .flatten import FlatEquation, FlatVariable
    big = [k for k, eq in enumerate(flat.equations)
           if eq.terms is None and not eq.residual.is_Atom
           and tree_reaches(eq.residual, OUTLINE_FROM)]
    if not big:
        return 0
    # der(x) is a node over x: a subexpression varies when a variable or time is in it
    unknowns = {v.symbol for v in flat.variables} | set(flat.derivatives.values()) | {time}
    values = _start_values(flat, time)
    made = 0
    for k in big:
        eq = flat.equations[k]
        prefix = f"{eq.component}._x" if eq.component else "_x"
        residual, parts = _split(eq.residual, unknowns, prefix, made)
        flat.equations[k] = _with_residual(eq, residual)
        for sym, expr in parts:
            start = _value(expr, values)
            if start is not None:
                values[sym] = start
            attrs = _attributes(start)
            flat.variables.append(FlatVariable(sym.name, sym, attrs, eq.component,
                                               eq.component_class, INTERMEDIATE))
            flat.equations.append(FlatEquation(sym - expr, _definition(sym, expr),
                                               eq.component, eq.component_class, "equation",
                                               eq.label))
            unknowns.add(sym)
        made += len(parts)
    return made


def _split(root, unknowns, prefix, first):
    """``(new root, [(symbol, expression), ...])`` in the order they are computed."""
    from ...components.symbols import Pre as pre
    from ...components.symbols import delay, no_event
    opaque = (no_event, delay, pre)
    order = postorder([root], lambda n: () if isinstance(n, opaque) else n.args)
    uses = {}
    for node in order:
        if not isinstance(node, opaque):
            for a in node.args:
                uses[a] = uses.get(a, 0) + 1
    new, local, varies, parts = {}, {}, {}, []
    for node in order:
        if node.is_Atom or isinstance(node, opaque):
            new[node] = node
            local[node] = 1 if node.is_Atom else tree_size(node)
            varies[node] = node in unknowns or (not node.is_Atom and any(
                q in unknowns for q in node.free_symbols))
            continue
        args = [new[a] for a in node.args]
        new[node] = node if all(a is b for a, b in zip(args, node.args)) else node.func(*args)
        local[node] = 1 + sum(local[a] for a in node.args)
        varies[node] = any(varies[a] for a in node.args)
        if node is root or not varies[node] or not _outlinable(node):
            continue
        size = local[node]
        if size >= LOCAL or (uses.get(node, 0) > 1 and size >= SHARED):
            from ...components.realsymbol import real_symbol
            sym = real_symbol(f"{prefix}{first + len(parts) + 1}")
            parts.append((sym, new[node]))
            new[node], local[node] = sym, 1
    return new[root], parts


def _outlinable(node) -> bool:
    """An expression with a value of its own (not a condition, a relation, a pair of
    a Piecewise or a tuple)."""
    return (isinstance(node, sp.Expr) and not isinstance(node, sp.Tuple)
            and not isinstance(node, sp.logic.boolalg.Boolean))


def definition_of(eq):
    """The intermediate a (flat or symbolic) equation defines, or None."""
    src = getattr(eq, "source", None)
    while src is not None and not isinstance(src, _Definition):
        src = getattr(src, "source", None)    # a SymbolicEquation holds the FlatEquation
    return src.lhs if src is not None else None


def _definition(sym, expr):
    """``sym = expr`` as an equation written by this pass."""
    return _Definition(sym, expr)


class _Definition(Equation):
    """An equation of the outline pass, ``intermediate = expression`` (its text printed
    when read, its symbol what :func:`definition_of` finds)."""


def _with_residual(eq, residual):
    from dataclasses import replace
    return replace(eq, residual=residual, plain=None)


def _attributes(start):
    from ...components.declarations import VariableAttributes
    return VariableAttributes(start=start, state_select="never",
                              description="an intermediate quantity of a long expression")


def _start_values(flat, time) -> dict:
    """Numbers for the symbols an intermediate's start value is computed from."""
    values = {time: 0.0}
    for p in flat.parameters:
        try:
            values[p.symbol] = float(p.value)
        except (TypeError, ValueError):
            pass
    for v in flat.variables:
        values[v.symbol] = float(v.attrs.start) if v.attrs.start is not None else 0.0
    for d in flat.derivatives.values():
        values.setdefault(d, 0.0)
    return values


def _value(expr, values):
    """expr at the start values (small: the intermediates it reads are numbers by then),
    or None where it has none."""
    try:
        out = complex(expr.xreplace({q: values.get(q, 0.0) for q in expr.free_symbols}))
    except (TypeError, ValueError, ZeroDivisionError, OverflowError):
        return None
    if out.imag != 0.0 or not math.isfinite(out.real):
        return None
    return out.real
