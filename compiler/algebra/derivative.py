"""Partial derivatives for the compiler, fast on the expressions models are made of.

sympy's ``diff`` is general and slow (about a millisecond a call); the equations of a
physical model are mostly sums of products in which a variable appears once, linearly.
``partial(expr, x)`` handles those directly (d/dx of c*x*y is c*y) and falls back to
sympy otherwise.  Results are cached: the same partials are needed for the incidence
coefficients, the Jacobian and the initialization Jacobian.
"""
from __future__ import annotations

import os
from functools import cmp_to_key, lru_cache

import sympy as sp

from ...components.realsymbol import SYMBOLS
from .dag import DEEP, depth, postorder
from .substitution import Fallback, assemble_sum

__all__ = ["partial", "plain_coefficient", "solve_linear", "simple_partials", "terms_with",
           "symbol_nodes", "flat_symbols", "dag_partial", "forget_partials"]

_CHECK = os.environ.get("ACAUSAL_CHECK_FASTSUBS", "") not in ("", "0")
_CANONICAL = cmp_to_key(sp.Basic.compare)     # the order of a sum's or product's arguments


@lru_cache(maxsize=200_000)
def partial(expr: sp.Expr, x: sp.Symbol) -> sp.Expr:
    """d expr / d x."""
    if x not in _symbols(expr):
        return sp.S.Zero
    if expr is x or (type(expr) in SYMBOLS and expr == x):
        return sp.S.One
    if depth(expr) > DEEP:
        return dag_partial(expr, x)    # the walk below recurses as deep as expr is
    if expr.is_Add:
        return _sum([partial(a, x) for a in expr.args if x in _symbols(a)])
    if expr.is_Mul:
        # product rule over the factors that contain x
        args = expr.args
        terms = []
        for i, a in enumerate(args):
            if x in _symbols(a):
                inner = partial(a, x)
                others = args[:i] + args[i + 1:]
                if inner is sp.S.One and expr.is_commutative and not (
                        others[0].is_Number and any(o.is_Add for o in others)):
                    # d/dx of k*x*y is k*y: the other factors, still in sympy's order
                    # and with nothing to combine, are the product sympy would build
                    # (but a number times a sum is distributed over it)
                    terms.append(_checked(
                        others[0] if len(others) == 1 else sp.Mul(*others, evaluate=False),
                        sp.Mul(*others) if _CHECK else None))
                else:
                    terms.append(sp.Mul(*args[:i], inner, *args[i + 1:]))
        return _sum(terms)
    if expr.is_Pow and x not in _symbols(expr.exp):
        # r u^(r-1) u' directly: sympy writes r u^r/u, which is 0/0 where u = 0
        base, r = expr.args
        return r * base ** (r - 1) * partial(base, x)
    return dag_partial(expr, x)


def dag_partial(expr, x):
    """d expr / d x by forward differentiation over the expression's DAG: every
    distinct subexpression that contains x is differentiated once, children first,
    without recursion (:mod:`acausal.compiler.dag`), so the work and the result grow
    with the DAG, not with the tree.  The discontinuous functions of a model are
    piecewise smooth: sign, floor and ceiling are constant between their events (d = 0,
    not sympy's DiracDelta), abs is sign(u) u', min and max follow the branch that
    holds, an if-expression differentiates its branches under the same conditions, and
    no_event(u) is u."""
    symbols = _symbols(expr)
    if x not in symbols:
        return sp.S.Zero
    boolean = sp.logic.boolalg.Boolean
    nodes = postorder([expr], lambda n: () if isinstance(n, boolean) else n.args)
    d = {}
    for node in nodes:
        if node.is_Atom:
            d[node] = sp.S.One if node == x else sp.S.Zero
        elif isinstance(node, boolean) or x not in _symbols(node):
            d[node] = sp.S.Zero
        else:
            d[node] = _node_derivative(node, d)
    return d[expr]


def _node_derivative(node, d):
    """d node from the derivatives ``d`` of its arguments (see :func:`dag_partial`)."""
    from ...components.ifexpr import IfExpr
    from ...components.symbols import no_event
    args = node.args
    da = [d.get(a, sp.S.Zero) for a in args]
    if node.is_Add:
        return sp.Add(*[t for t in da if t != 0])
    if node.is_Mul:
        terms = [sp.Mul(*args[:i], t, *args[i + 1:]) for i, t in enumerate(da) if t != 0]
        return sp.Add(*terms)
    if node.is_Pow:
        base, e = args
        out = sp.S.Zero
        if da[0] != 0:
            out += e * base ** (e - 1) * da[0]
        if da[1] != 0:
            out += node * sp.log(base) * da[1]
        return out
    if isinstance(node, (sp.sign, sp.floor, sp.ceiling)):
        return sp.S.Zero
    if isinstance(node, sp.Abs):
        return sp.sign(args[0]) * da[0]
    if isinstance(node, no_event):
        return da[0]
    if isinstance(node, sp.Piecewise):
        return sp.Piecewise(*[(d.get(e, sp.S.Zero), c) for e, c in args])
    if isinstance(node, sp.functions.elementary.piecewise.ExprCondPair):
        return sp.S.Zero              # read through its Piecewise
    if isinstance(node, IfExpr):
        pairs = node.pairs()
        return IfExpr(*[v for e, c in pairs for v in (d.get(e, sp.S.Zero), c)])
    if isinstance(node, (sp.Min, sp.Max)):
        op = (lambda u, v: u <= v) if isinstance(node, sp.Min) else (lambda u, v: u >= v)
        out, dout = args[0], da[0]
        for a, t in zip(args[1:], da[1:]):
            cond = op(out, a)
            out, dout = sp.Piecewise((out, cond), (a, True)), sp.Piecewise((dout, cond),
                                                                            (t, True))
        return dout
    if isinstance(node, sp.Mod):
        return da[0]                  # d/du Mod(u, T), T constant: frozen floor values
    if isinstance(node, sp.Function):
        return sp.Add(*[node.fdiff(i + 1) * t for i, t in enumerate(da) if t != 0])
    return _sympy_derivative(node, da)


def _sympy_derivative(node, da):
    """A node this module has no rule for: sympy's chain rule over its arguments."""
    out = sp.S.Zero
    for a, t in zip(node.args, da):
        if t != 0:
            dummy = sp.Dummy()
            out += sp.diff(node.xreplace({a: dummy}), dummy).xreplace({dummy: a}) * t
    return out


def simple_partials(expr, wanted) -> dict | None:
    """``{x: partial(expr, x) for x in wanted}`` (symbols of expr, each in it), read off
    the expression for the forms most assigned variables and residuals take once
    causalized -- a symbol (1), a product of a symbol and a factor without it
    (``v/L``, ``R*i``: that factor) and a negated sum of +-symbols (``-(a - b)``: -1 and
    1) -- the same objects :func:`partial` returns for them; None for any other form.
    Why: a ladder of 1000 sections has 10 000 such expressions, and the general path
    hashes each with each of its symbols into the cache of :func:`partial`."""
    out = _simple_partials(expr, wanted)
    if _CHECK and out is not None:
        for x, d in out.items():
            _checked(d, partial(expr, x))
    return out


def _simple_partials(expr, wanted) -> dict | None:
    if type(expr) in SYMBOLS:
        return {x: sp.S.One for x in wanted}          # wanted is [expr]
    if type(expr) is not sp.Mul or len(expr.args) != 2:
        return None
    a, b = expr.args
    if a is sp.S.NegativeOne and type(b) is sp.Add:
        signs = {}
        for t in b.args:
            if type(t) in SYMBOLS:
                signs[t] = sp.S.NegativeOne           # d/dt of -(... + t ...)
            elif (type(t) is sp.Mul and len(t.args) == 2 and t.args[0] is sp.S.NegativeOne
                  and type(t.args[1]) in SYMBOLS):
                signs[t.args[1]] = sp.S.One           # d/dt of -(... - t ...)
            else:
                return None
        return {x: signs[x] for x in wanted} if all(x in signs for x in wanted) else None
    out = {}
    for x in wanted:
        if a is x and x not in _symbols(b):
            out[x] = b
        elif b is x and x not in _symbols(a):
            out[x] = a
        else:
            return None
    return out


def _sum(terms: list) -> sp.Expr:
    """``Add(*terms)``; a single term is its own sum (what Add returns for it)."""
    return terms[0] if len(terms) == 1 else sp.Add(*terms)


def solve_linear(residual, x):
    """x from residual(x) = 0 when x enters linearly:  x = -r(x=0) / (dr/dx).

    A sum is split into the terms with and without x (the canonical terms of a sum stay
    canonical, so no rebuilding of the whole sum is needed: a node balance of n terms
    costs n).  When the term with x is x, k*x or p*x (a number k, a symbol p), its
    coefficient is read from the term itself: neither the derivative nor r(x=0) is
    built, and the result is the same expression."""
    if residual.is_Add:
        inner = terms_with(residual).get(x, ())
        if len(inner) == 1:
            c = plain_coefficient(inner[0], x)
            if c is not None:
                # the cached index may hold an equal term of an equal sum: compare by
                # value (a sum has no two equal terms), the hash first
                t, h = inner[0], hash(inner[0])
                rest = [a for a in residual.args if hash(a) != h or a != t]
                return _solved(rest, c)
    return _solve_general(residual, x)


@lru_cache(maxsize=200_000)
def _symbols(e) -> frozenset:
    """Every Symbol node of e, bound ones included: ``x in _symbols(e)`` is
    ``e.has(x)`` for a symbol x (sympy walks the tree twice for each such question;
    the partials of a model ask it of the same subexpressions many times)."""
    if e.is_Symbol:
        return frozenset((e,))
    out = flat_symbols(e)
    if out is not None:
        return frozenset(out)
    out, stack, seen = set(), list(e.args), set()
    while stack:            # iterative: a deeply nested expression must not recurse
        node = stack.pop()
        if node.is_Symbol:
            out.add(node)
        elif node not in seen:       # and over the DAG: a shared part once
            seen.add(node)
            stack.extend(node.args)
    return frozenset(out)


def plain_coefficient(term, x):
    """k (a number or a symbol) when term is x or k*x, else None."""
    if term == x:
        return sp.S.One
    if term.is_Mul and len(term.args) == 2:
        a, b = term.args
        k = a if b == x else b if a == x else None
        if k is not None and (k.is_Number or k.is_Symbol) and k != x:
            return k
    return None


def _solved(rest, c):
    """-(sum of rest) / c, built as :func:`_solve_general` builds it."""
    if len(rest) > 1:
        r0 = sp.Add(*rest, evaluate=False)
        if c.is_Number:
            # x = (-1/c) * r0, kept as a product: distributing the number over the
            # sum would rebuild every term
            if c is sp.S.One:     # what Mul(-1, r0, evaluate=False) makes
                return sp.Mul(sp.S.NegativeOne, r0, evaluate=False)
            return sp.Mul(-1 / c, r0, evaluate=False) if c != -1 else r0
        return _checked(_negated_sum_over(rest, c), -r0 / c if _CHECK else None)
    # one other term: r(x=0) is that term
    if c is sp.S.One:
        return _negated(rest[0])
    if c is sp.S.NegativeOne:
        return rest[0]
    return _checked(_quotient(_negated(rest[0]), c), -rest[0] / c if _CHECK else None)


def _negated(t):
    """-t, as sympy builds it; a product of a number and other factors (``-L.v``,
    ``-R*i``) directly: its coefficient negated, the other factors as they were (but
    sympy distributes a number over a sum, so a product with a sum is left to it)."""
    if type(t) is sp.Mul and t.args[0].is_Number and t.is_commutative \
            and not any(f.is_Add for f in t.args):
        k, others = -t.args[0], t.args[1:]
        if k is sp.S.One:
            out = others[0] if len(others) == 1 else sp.Mul(*others, evaluate=False)
        else:
            out = sp.Mul(k, *others, evaluate=False)
        return _checked(out, -t if _CHECK else None)
    if type(t) in SYMBOLS:
        return _checked(sp.Mul(sp.S.NegativeOne, t, evaluate=False),
                        -t if _CHECK else None)
    return -t


def _negated_sum_over(rest, c):
    """-(sum of rest) / c for a symbol c, as sympy builds it: the sum with every term
    negated (sympy distributes -1 over it), times c**-1, the two factors in sympy's
    order; sympy's own arithmetic where a term is not a plain product."""
    if type(c) not in SYMBOLS or not c.is_commutative:
        return -sp.Add(*rest, evaluate=False) / c
    negated = [_negated(t) for t in rest]
    if any(t.is_Add or t.is_Number for t in negated):
        return -sp.Add(*rest, evaluate=False) / c
    try:
        total = assemble_sum(negated)
    except Fallback:
        return -sp.Add(*rest, evaluate=False) / c
    if not total.is_Add or c in total.free_symbols:
        return -sp.Add(*rest, evaluate=False) / c
    factors = [total, sp.Pow(c, sp.S.NegativeOne)]
    factors.sort(key=_CANONICAL)
    return sp.Mul(*factors, evaluate=False)


def _quotient(t, c):
    """t / c, as sympy builds it; for a symbol c and a product of a number and symbols
    other than c (``L.v / L.L``) directly: the factors and c**-1 in sympy's order,
    the number first (there is nothing to combine)."""
    if type(c) not in SYMBOLS or not c.is_commutative:
        return t / c
    if type(t) in SYMBOLS:
        k, factors = None, [t]
    elif type(t) is sp.Mul and all(type(f) in SYMBOLS for f in t.args[1:]) \
            and (type(t.args[0]) in SYMBOLS or t.args[0].is_Number):
        k = t.args[0] if t.args[0].is_Number else None
        factors = list(t.args[1:] if k is not None else t.args)
    else:
        return t / c
    if c in factors or not all(f.is_commutative for f in factors):
        return t / c
    factors.append(sp.Pow(c, sp.S.NegativeOne))
    factors.sort(key=_CANONICAL)
    return sp.Mul(*([k] if k is not None else []), *factors, evaluate=False)


def _checked(out, ref):
    """``out``; with ``ACAUSAL_CHECK_FASTSUBS=1``, first compared with sympy's ``ref``."""
    if _CHECK and (out != ref or sp.srepr(out) != sp.srepr(ref)):
        raise AssertionError(f"built {out}, sympy builds {ref}")
    return out


def _solve_general(residual, x):
    c = partial(residual, x)
    if residual.is_Add:
        rest = [a for a in residual.args if not a.has(x)]
        inner = [a for a in residual.args if a.has(x)]
        # the term with x must be x times its coefficient: a term such as k (x - a)
        # also contributes -k a to r(x=0)
        if len(inner) == 1 and inner[0] == c * x and len(residual.args) > 2:
            r0 = sp.Add(*rest, evaluate=False) if len(rest) > 1 else rest[0]
            if c.is_Number and r0.is_Add:
                return sp.Mul(-1 / c, r0, evaluate=False) if c != -1 else r0
            return -r0 / c
    return -_at_zero(residual, x) / c


def _at_zero(expr, x):
    """``expr`` at x = 0 outside its relations: a relation is frozen between events
    (its value is the discrete state's, as :func:`partial` differentiates it), so
    ``z = if z + s > 0 then -1 else 1`` solves to itself, with the relation reading z,
    not to a relation ``s > 0`` of another model."""
    frozen = {r: sp.Dummy() for r in expr.atoms(sp.core.relational.Relational)
              if x in _symbols(r)}
    if not frozen:
        return expr.xreplace({x: 0})
    back = {d: r for r, d in frozen.items()}
    return expr.xreplace(frozen).xreplace({x: 0}).xreplace(back)


@lru_cache(maxsize=200_000)
def terms_with(r: sp.Expr) -> dict:
    """symbol -> the terms of the sum r that contain it, in the order of r's arguments
    (every symbol a term has, as ``has`` sees them)."""
    out = {}
    for t in r.args:
        for q in symbol_nodes(t):
            out.setdefault(q, []).append(t)
    return out


def flat_symbols(e) -> set | None:
    """The symbols among e's arguments when all of them are atoms (most terms of a
    model: ``-R*i``, ``k*x``), found without the walk; None otherwise."""
    out = set()
    for a in e.args:
        if a.is_Symbol:
            out.add(a)
        elif not a.is_Atom:
            return None
    return out


def symbol_nodes(e: sp.Basic) -> set:
    """``e.atoms(Symbol)``: every Symbol node of the tree, bound ones included (what
    ``has`` finds)."""
    if e.is_Symbol:
        return {e}
    out = flat_symbols(e)
    if out is not None:
        return out
    out, stack, seen = set(), [e], set()
    while stack:
        node = stack.pop()
        if node.is_Symbol:
            out.add(node)
        elif node not in seen:        # a shared subexpression is walked once
            seen.add(node)
            stack.extend(node.args)
    return out


def forget_partials() -> None:
    """Empty the caches of :func:`partial` and of the symbols of subexpressions (a
    compile's end, :func:`acausal.compiler.algebra.symbolic.forget_expressions`)."""
    partial.cache_clear()
    _symbols.cache_clear()
