"""fast_xreplace builds exactly the expression sympy's xreplace builds (the same tree,
argument order included), on random sums and products and on the cases it leaves to
sympy."""
import random

import sympy as sp

from acausal.compiler.algebra.substitution import fast_xreplace
from acausal.components.symbols import der

X = sp.symbols("a b c d e f g h", real=True)
P = sp.symbols("R L", positive=True)


def _same(expr, mapping):
    out, ref = fast_xreplace(expr, mapping), expr.xreplace(mapping)
    assert out == ref and type(out) is type(ref), (expr, mapping, out, ref)
    assert sp.srepr(out) == sp.srepr(ref)


def _random_expr(rng, depth=0):
    kind = rng.random()
    if depth > 2 or kind < 0.3:
        return rng.choice(X + P)
    if kind < 0.6:
        return sp.Add(*[rng.choice([1, -1, 2, sp.Rational(1, 2)]) * _random_expr(rng, depth + 1)
                        for _ in range(rng.randint(2, 4))], rng.choice([0, 0, 1, 0.5]))
    if kind < 0.85:
        return sp.Mul(*[_random_expr(rng, depth + 1) for _ in range(rng.randint(2, 3))],
                      rng.choice([1, -1, 3, 1.5]))
    return rng.choice([sp.sin, sp.exp, der])(_random_expr(rng, depth + 1))


def _random_mapping(rng):
    out = {}
    for s in rng.sample(X, rng.randint(1, 4)):
        out[s] = rng.choice([rng.choice(X), -rng.choice(X), sp.S.Zero, sp.Integer(2),
                             sp.Rational(-1, 3), P[0] * P[1], rng.choice(X) + 1])
    return out


def test_random_sums_and_products_match_xreplace():
    rng = random.Random(7)
    for _ in range(800):
        _same(_random_expr(rng), _random_mapping(rng))


def test_connection_sums_collapse_as_sympy_does():
    a, b, c, d = X[:4]
    _same(a + b + c, {b: -a})              # a - a cancels
    _same(a - b + 2 * c, {c: b})           # -b + 2b = b
    _same(a + b, {a: sp.S.Zero, b: sp.S.Zero})
    _same(-a - b, {a: -c, b: -d})
    _same(P[0] * a - b, {a: -b})           # -R*b - b
    _same(P[0] * a * b, {a: b})            # b**2: left to sympy
    _same(a * (b + c), {c: -b})            # a*0
    _same(sp.Float(2.5) * a + b, {a: -b})  # float coefficient changes sign


def test_derivatives_replaced_by_symbols():
    x, y = X[:2]
    dx = sp.Symbol("der(a)", real=True)
    _same(P[1] * der(x) - y, {der(x): dx})
    _same(der(x) ** 2 + y, {der(x): dx})
    _same(sp.sin(der(x)) * y, {der(x): dx})


def test_differences_match_sympy_subtraction():
    from acausal.compiler.algebra.substitution import fast_difference
    rng = random.Random(11)
    a, b = X[:2]
    cases = [(a, sp.Float(0.0)), (sp.Float(0.0), a), (a + 1.5, sp.Float(1.5)),
             (a + b, a), (2 * a, a + b), (P[0] * der(a), b), (sp.S.Zero, a + b)]
    cases += [(_random_expr(rng), _random_expr(rng)) for _ in range(400)]
    for lhs, rhs in cases:
        out, ref = fast_difference(lhs, rhs), lhs - rhs
        assert out == ref and sp.srepr(out) == sp.srepr(ref), (lhs, rhs, out, ref)


def test_a_factor_that_becomes_zero():
    a, b, c = X[:3]
    _same(P[0] * (a - b) + c, {b: sp.S.Zero})        # c*(s_rel - s_rel0), s_rel0 = 0
    _same(P[0] * (a - b) + c, {b: a})                # the sum itself becomes 0
    _same(-P[0] * a * b + c, {a: sp.S.Zero})
    _same(sp.oo * a + b, {a: sp.S.Zero})             # oo*0: nan, left to sympy
    _same(sp.Float(2.5) * a * b + c, {a: sp.S.Zero})


def test_sort_args_is_sympys_order():
    """Sums of +-symbols are ordered by their names where that is sympy's order
    (symbols before products, names as strings, equal assumptions); mixed assumptions,
    other coefficients and other terms are left to sympy's key: always sympy's order."""
    from functools import cmp_to_key

    from acausal.compiler.algebra.substitution import sort_args
    rng = random.Random(5)
    names = ["a", "b", "a.b", "a_b", "A", "R1.p.v", "R10.n.i", "der(x)", "x[1]", "x[10]",
             "x[2]", "Z", "_x", "é"]
    for trial in range(600):
        syms = [sp.Symbol(n, real=True) for n in rng.sample(names, rng.randint(1, 8))]
        if trial % 5 == 0:
            syms.append(sp.Symbol("q"))                   # other assumptions
        terms = [s if rng.random() < 0.5 else -s for s in syms]
        if trial % 7 == 0:
            terms.append(2 * sp.Symbol("k", real=True))   # another coefficient
        rng.shuffle(terms)
        out = list(terms)
        sort_args(out)
        ref = sorted(terms, key=cmp_to_key(sp.Basic.compare))
        assert all(x is y for x, y in zip(out, ref)), (out, ref)


def test_factor_that_becomes_a_number_joins_the_coefficient():
    """R (1 + alpha (T - T_ref)) i with alpha = 0 or T = T_ref: the factor becomes a
    rational number, folded into the product's coefficient on the fast path (no
    rebuild of the whole residual by sympy), the same expression as xreplace's."""
    from acausal.compiler.algebra import substitution
    v, i, a, T, T_ref = X[:5]
    R = P[0]
    for expr, mapping in [
            (v - R * (1 + a * (T - T_ref)) * i, {a: sp.S.Zero, T: T_ref}),
            (v - R * (1 + a * (T - T_ref)) * i, {T: T_ref}),
            (v - 2 * R * (3 + a * (T - T_ref)) * i, {T: T_ref}),
            (v - sp.Rational(1, 3) * R * (2 + a * (T - T_ref)) * i, {a: sp.S.Zero}),
            (v + (-1 + a * (T - T_ref)) * i * R, {T: T_ref}),
            (i / (1 + a * (T - T_ref)) - v, {T: T_ref})]:
        _same(expr, mapping)
        if not expr.has(sp.Pow):
            substitution._sub(expr, mapping)     # no Fallback: the fast path made it
    # a float coefficient, or a number left to distribute over a sum, stays sympy's
    _same(v - sp.Float(0.5) * R * (2 + a * (T - T_ref)) * i, {T: T_ref})
    _same(v - (3 + a * (T - T_ref)) * (i + R), {T: T_ref})
