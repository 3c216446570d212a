"""``expr.xreplace(mapping)`` for the substitutions of the front passes, without sympy's
general re-evaluation where the result is known to be canonical already.

Alias elimination replaces variables by +-their representative (or 0), and derivative
expansion replaces ``der(x)`` by the symbol ``der(x)``; the expressions are mostly sums
and products of symbols.  sympy's ``xreplace`` rebuilds every node it changes through
``Add``/``Mul`` (flatten, sort, the cache), most of these passes' time.  Here a sum or
product whose new arguments are symbols, +-symbols and the numbers it had is assembled
directly in sympy's canonical form -- terms with equal non-numeric parts combined,
factors and terms in sympy's own order (:meth:`sympy.Basic.compare`), the numeric
coefficient first -- which is the expression sympy would build, and builds with
``evaluate=False`` from arguments already in that form.  Anything else (a mapped symbol
inside a power or a function, a product that would combine powers, float coefficients
that change, a sum nested in a sum) falls back to ``xreplace`` for the whole
expression, so the result is always ``expr.xreplace(mapping)``.

Setting ``ACAUSAL_CHECK_FASTSUBS=1`` compares every result with ``xreplace`` (a test aid).
"""
from __future__ import annotations

import os
from functools import cmp_to_key

import sympy as sp
from sympy.calculus.accumulationbounds import AccumBounds
from sympy.tensor.tensor import TensExpr

from ...components.realsymbol import SYMBOLS, Symbol
from ...components.symbols import has_atom_in
from .dag import DEEP, xreplace

__all__ = ["fast_xreplace", "fast_difference", "has_undefined", "sort_args", "negated",
           "forget_negated",
           "assemble_sum", "Fallback"]

_ONE, _ZERO, _MINUS = sp.S.One, sp.S.Zero, sp.S.NegativeOne
_Add, _Mul = sp.Add, sp.Mul
_Rational = sp.Rational
_CANONICAL = cmp_to_key(sp.Basic.compare)     # the order of a sum's or product's arguments
_CHECK = os.environ.get("ACAUSAL_CHECK_FASTSUBS", "") not in ("", "0")


class Fallback(Exception):
    """The fast path does not know sympy's canonical form of this result."""


def fast_xreplace(expr, mapping: dict):
    """``expr.xreplace(mapping)`` (the same expression), faster on sums and products."""
    if not mapping:
        return expr
    try:
        # the fast path recurses as deep as expr is: below DEEP levels, or it falls back
        out = _sub(expr, mapping, 0)
    except Fallback:
        return xreplace(expr, mapping)
    if _CHECK:
        ref = expr.xreplace(mapping)
        if out != ref or type(out) is not type(ref):
            raise AssertionError(f"fast_xreplace({expr}) gave {out}, xreplace {ref}")
    return out


_UNDEFINED = frozenset((sp.zoo, sp.nan))


def has_undefined(expr) -> bool:
    """``expr.has(sp.zoo, sp.nan)``, by one walk over the arguments."""
    return has_atom_in(expr, _UNDEFINED)


def _contains_key(e, mapping) -> bool:
    stack, seen = [e], set()
    while stack:
        node = stack.pop()
        if node in mapping:
            return True
        if node not in seen:
            seen.add(node)
            stack.extend(node.args)
    return False


def _sub(e, mapping, level=0):
    v = mapping.get(e)
    if v is not None:
        return v
    if e.is_Atom:
        return e
    if level > DEEP:
        raise Fallback          # xreplace walks deep expressions without recursion
    t = type(e)
    if t is _Add:
        return _sum(e, mapping, level + 1)
    if t is _Mul:
        return _product(e, mapping, level + 1)
    if _contains_key(e, mapping):
        raise Fallback
    return e


def negated(q) -> sp.Expr:
    """``-q`` of a symbol or der(symbol), as sympy builds it (``Mul(-1, q)``), made once
    per compile: the same node serves every sum it is a term of (a port's voltage is
    negated in its element's equation, in the connection's, and where an alias stands
    for it), so that look-ups of it find it by identity, not by comparing two copies."""
    if type(q) is Symbol:
        return q.negative()              # kept with the symbol
    out = _NEGATED.get(q)
    if out is None:
        out = _NEGATED[q] = _Mul(_MINUS, q, evaluate=False)
    return out


_NEGATED: dict = {}       # emptied at a compile's end (symbolic.forget_expressions)


def forget_negated() -> None:
    """Let go of the negated symbols and the symbols' facts kept so far (a compile's
    end)."""
    _NEGATED.clear()
    _FACTS.clear()


_FACTS: dict = {}      # symbol -> its assumptions, one object per distinct set
_FACT_SETS: dict = {}


def _facts(q):
    """The assumptions of the symbol ``q`` as one shared object per distinct set, so
    that two symbols' are compared by identity (``assumptions0`` makes a new dict each
    time it is read).  A model's symbols are all real (:class:`Symbol`)."""
    if type(q) is Symbol:
        return _REAL
    out = _FACTS.get(q)
    if out is None:
        items = frozenset(q.assumptions0.items())
        out = _FACTS[q] = _FACT_SETS.setdefault(items, items)
    return out


_REAL = frozenset(Symbol("x").assumptions0.items())
_FACT_SETS[_REAL] = _REAL


def _signed_symbol(v):
    """(sign, symbol) of a value that is a commutative symbol or its negative; else None."""
    if type(v) in SYMBOLS:
        return (1, v) if v.is_commutative else None
    if type(v) is _Mul and len(v.args) == 2 and v.args[0] is _MINUS \
            and type(v.args[1]) in SYMBOLS and v.args[1].is_commutative:
        return -1, v.args[1]
    return None


def _product(e, mapping, level):
    """A product whose changed factors are +-symbols, 0 or rational numbers: the sign and
    the numbers into the coefficient, the factors re-sorted, 0 if a factor became 0; a new factor whose base another
    factor shares (x*x) falls back, as does a coefficient with a sum left to distribute
    over."""
    args = e.args
    sign, coeff, factors, new, changed, zero = 1, None, [], [], False, False
    for f in args:
        if f.is_Number:
            coeff = f
            continue
        v = mapping.get(f)
        if v is _ZERO:
            zero = changed = True
            continue
        if v is not None:
            s = _signed_symbol(v)
            if s is None:
                raise Fallback
            sign *= s[0]
            factors.append(s[1])
            new.append(s[1])
            changed = True
            continue
        if f.is_Atom:
            factors.append(f)
            continue
        g = _sub(f, mapping, level)
        if g is _ZERO:
            zero = changed = True
            continue
        if g is not f:
            if isinstance(g, _Rational):
                # a factor that became a rational number joins the coefficient (a
                # factor 1 + alpha*(T - T_ref) with alpha = 0 is 1)
                coeff = g if coeff is None else coeff * g
                if not isinstance(coeff, _Rational):
                    raise Fallback
                if coeff is _ONE:
                    coeff = None
                changed = True
                continue
            if g.is_Number or type(g) is _Mul or not g.is_commutative:
                raise Fallback
            changed = True
            new.append(g)
        factors.append(g)
    if not changed:
        return e
    if zero:
        # 0 times finite factors is 0 (Mul.flatten); an infinite factor makes nan
        if (coeff is not None and not isinstance(coeff, _Rational)) \
                or any(f.is_finite is False for f in factors):
            raise Fallback
        return _ZERO
    if new:
        bases = [f.base if f.is_Pow else f for f in factors]
        if len(set(bases)) < len(bases):
            raise Fallback
    if sign == -1:
        if coeff is None:
            coeff = _MINUS
        elif isinstance(coeff, _Rational):
            coeff = -coeff
            if coeff is _ONE:
                coeff = None
        else:
            raise Fallback
    if coeff is not None and any(f.is_Add for f in factors):
        raise Fallback
    if coeff is _MINUS and len(factors) == 1 and type(factors[0]) in SYMBOLS:
        return negated(factors[0])
    sort_args(factors)
    if coeff is not None:
        factors.insert(0, coeff)
    if len(factors) == 1:
        return factors[0]
    return _Mul(*factors, evaluate=False)


def _sum(e, mapping, level):
    """A sum: each term substituted, terms with equal non-numeric parts combined (rational
    coefficients only), zeros dropped, sympy's order, the number first."""
    args = e.args
    new_args, changed = [], False
    for a in args:
        b = _sub(a, mapping, level)
        if b is not a:
            changed = True
        new_args.append(b)
    if not changed:
        return e
    return assemble_sum(new_args)


def fast_difference(lhs, rhs):
    """``lhs - rhs`` (sympy's ``Add(lhs, -rhs)``, the residual of an equation), with the
    terms assembled directly where the result's canonical form is known."""
    if rhs is _ZERO or lhs is _ZERO:
        return lhs - rhs
    terms = list(lhs.args) if type(lhs) is _Add else [lhs]
    # -(a + b) distributes as -a - b (Mul's two-argument rule), each by sympy's __neg__
    terms += [-t for t in rhs.args] if type(rhs) is _Add else [-rhs]
    try:
        out = assemble_sum(terms)
    except Fallback:
        return lhs - rhs
    if _CHECK:
        ref = lhs - rhs
        if out != ref or type(out) is not type(ref):
            raise AssertionError(f"fast_difference({lhs}, {rhs}) gave {out}, sympy {ref}")
    return out


def _unusual(t) -> bool:
    """Terms Add.flatten treats specially: orders, intervals, tensors, zoo, matrices,
    unevaluated powers of numbers."""
    return (not isinstance(t, sp.Expr) or t.is_Order or t is sp.S.ComplexInfinity
            or isinstance(t, (AccumBounds, TensExpr))
            or (t.is_Pow and t.base.is_Number))


_USUAL = SYMBOLS | {sp.Mul}     # term classes known not to be _unusual (Mul: its factors
                                 # are checked where they are combined)


def assemble_sum(new_args):
    """Add(*new_args) for terms that are not sums themselves, in sympy's canonical form:
    numbers summed, terms with equal non-numeric
    parts combined (rational coefficients), zeros dropped, sympy's order of terms, the
    number first; Fallback where sympy's flatten would do something else."""
    coeff = _ZERO
    for a in new_args:       # in flatten's order, by sympy's arithmetic (0.0 -> 0)
        if a.is_Number:
            if not isinstance(a, (_Rational, sp.Float)):
                raise Fallback
            coeff = coeff + a
    terms = {}           # non-numeric factors -> [coefficient, term as it stands]
    for a in new_args:
        if a.is_Number:
            continue
        if type(a) is _Add or not a.is_commutative \
                or (type(a) not in _USUAL and _unusual(a)):
            raise Fallback
        if type(a) is _Mul and a.args[0].is_Number:
            c, key = a.args[0], a.args[1:]
        else:
            c, key = _ONE, (a.args if type(a) is _Mul else (a,))
        known = terms.get(key)
        if known is None:
            terms[key] = [c, a]
            continue
        if not (isinstance(c, _Rational) and isinstance(known[0], _Rational)):
            raise Fallback
        known[0] = known[0] + c
        known[1] = None              # rebuilt below from the combined coefficient
    seq = []
    for key, (c, term) in terms.items():
        if term is not None:
            seq.append(term)
            continue
        if c is _ZERO:
            continue
        if any(f.is_Add or f.is_Number or _unusual(f) for f in key):
            raise Fallback
        if c is _ONE:
            seq.append(key[0] if len(key) == 1 else _Mul(*key, evaluate=False))
        else:
            seq.append(_Mul(c, *key, evaluate=False))
    sort_args(seq)
    if coeff is not _ZERO:
        seq.insert(0, coeff)
    if not seq:
        return _ZERO
    if len(seq) == 1:
        return seq[0]
    return _Add(*seq, evaluate=False)


def sort_args(seq: list) -> None:
    """``seq.sort(key=cmp_to_key(Basic.compare))``: sympy's canonical order of the
    arguments of a sum or product, in place.

    ``Basic.compare`` orders by class first (a Symbol before a Mul), then by the
    hashable contents: a symbol's is its name followed by its assumptions, a product's
    its arguments.  Where every argument is a symbol or ``-1`` times a symbol, and all
    these symbols have the same assumptions (as a model's variables do), that order is
    the order of the keys (0, name) and (1, name); the comparisons, each a few calls
    into sympy, were most of the time of building a model's sums.  Anything else is
    sorted by sympy's key."""
    keys = _plain_keys(seq)
    if keys is None:
        seq.sort(key=_CANONICAL)
        return
    if len(seq) == 2:               # most sums: no sort needed to order two
        ordered = seq[::-1] if keys[1] < keys[0] else list(seq)
    else:
        ordered = [seq[k] for k in sorted(range(len(seq)), key=keys.__getitem__)]
    if _CHECK:
        ref = sorted(seq, key=_CANONICAL)
        if any(a is not b for a, b in zip(ordered, ref)):
            raise AssertionError(f"sort_args({seq}) gave {ordered}, sympy {ref}")
    seq[:] = ordered


def _plain_keys(seq):
    """The keys of :func:`sort_args`, or None where they do not give sympy's order."""
    keys, facts = [], None
    for t in seq:
        kind = type(t)
        if kind in SYMBOLS:
            key, q = (0, t.name), t
        elif kind is _Mul:
            args = t.args
            if len(args) != 2 or args[0] is not _MINUS or type(args[1]) not in SYMBOLS:
                return None
            q = args[1]
            key = (1, q.name)
        else:
            return None
        # a symbol's hashable content is its name and its assumptions: the same
        # assumptions for all (a model's variables are real), the names decide
        if facts is None:
            facts = _facts(q)
        elif _facts(q) is not facts:
            return None
        keys.append(key)
    return keys
