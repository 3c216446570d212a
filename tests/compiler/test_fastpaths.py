"""The shortcuts of the back end give what the general paths give.

* solve_linear reads a plain coefficient (x, k*x, p*x) from the term: the result is the
  expression the general path (derivative and r(x=0)) builds, and it solves r = 0;
* coefficient_kind classifies such a coefficient as the derivative would;
* the generated Python is compiled by the first call of one of its functions, once, and
  a traceback still points at the line of the whole source.
"""
import pickle

import numpy as np
import pytest
import sympy as sp

from acausal.compiler.backends.codegen import generate
from acausal.compiler.algebra.derivative import _solve_general, solve_linear
from acausal.compiler.structure.graph import LINEAR_CONST, LINEAR_PARAM, LINEAR_VAR, NONLINEAR
from acausal.compiler.algebra.symbolic import coefficient_kind, sum_partial

x, y, z, p, q = sp.symbols("x y z p q", real=True)

RESIDUALS = [x + y, -x + y, 2 * x - y, x - y + z, -x + y - z, sp.Rational(1, 3) * x + y + z,
             sp.Float(0.5) * x - y, p * x - y, p * x - y + z, x * y - z, x ** 2 - y,
             p * (x - y) + z, sp.sin(y) + p * x, x + y * z + q,
             # one other term, negated and divided directly (derivative._negated,
             # _quotient), and the cases they leave to sympy
             p * x + y, p * x - 2 * y * z, p * x - q * y, p * x - sp.Float(1.5) * y,
             x - y * z, x + 2 * y, p * x - p * y, p * x - sp.sin(y), q * x - p * y * z,
             x - y - z,
             # a coefficient of several factors, classified from them (_factor_kind)
             -p * q * x + y, 2 * p * x * y - z, sp.Float(0.5) * p * x - y, x * y * z,
             # a product with a sum, over which sympy's negation distributes a number
             x - 2 * y * (z + q), p * x + 3 * y * (z - q),
             # several other terms over a symbol coefficient (derivative._negated_sum_over)
             p * x - y + z, p * x + y + z, p * x - y - q * z, p * x + 2 * y - z,
             p * x - y + sp.Float(1.5) * z, p * x + y + 1, p * x - p * y + z,
             p * x + y * (z + q) - z]
LINEAR = [r for r in RESIDUALS if sp.degree(r, x) == 1]


@pytest.mark.parametrize("r", LINEAR, ids=str)
def test_solve_linear_is_the_general_solution(r):
    fast = solve_linear(r, x)
    assert sp.srepr(fast) == sp.srepr(_solve_general(r, x))
    assert sp.simplify(r.subs(x, fast)) == 0


@pytest.mark.parametrize("r", RESIDUALS, ids=str)
def test_coefficient_kind_agrees_with_the_derivative(r):
    c = sum_partial(r, x)
    if c.has(x):
        expected = NONLINEAR
    elif c.is_number:
        expected = LINEAR_CONST
    elif c.free_symbols <= {p, q}:
        expected = LINEAR_PARAM
    else:
        expected = LINEAR_VAR
    assert coefficient_kind(r, x, {}, {p, q}) == expected


def test_generated_functions_compile_on_first_call_and_keep_line_numbers():
    u, v = sp.symbols("u v")
    code = generate([u - 1, sp.sqrt(v)], [u, v], [])
    assert not code.module.compiled
    out = code.residual(0.0, np.array([3.0, 4.0]), np.array([]), [], np.empty(2))
    np.testing.assert_allclose(out, [2.0, 2.0], rtol=1e-15)
    assert code.module.compiled
    namespace = code.module.namespace()
    assert code.module.namespace() is namespace          # compiled once
    with pytest.raises(ValueError) as err:               # sqrt of a negative
        code.residual(0.0, np.array([3.0, -4.0]), np.array([]), [], np.empty(2))
    line = [f.lineno for f in __import__("traceback").extract_tb(err.value.__traceback__)
            if f.filename == "<acausal generated>"][-1]
    assert code.source.splitlines()[line - 1].strip().startswith("out[1] = ")


@pytest.mark.parametrize("e", [-x * y, 2 * x * y * z, -x * (y + z), 3 * x * (y - z),
                               p * x / q, x * sp.sin(y), -sp.Float(1.5) * x * y ** 2],
                         ids=str)
def test_partial_of_a_product_is_sympys(e):
    """d/dx of a product in which x is a factor: the other factors (derivative.partial
    builds them directly unless a number would be distributed over a sum)."""
    from acausal.compiler.algebra.derivative import partial
    d = partial(e, x)
    assert sp.srepr(d) == sp.srepr(sp.diff(e, x))


def test_a_variable_symbol_is_real_and_equal_to_sympys_symbol():
    """real_symbol(name) is of acausal's own class, named Symbol: real, and equal to
    sympy's Symbol(name, real=True) both ways, with one hash, text and order, so that a
    user's own symbol finds it (==, dict keys, subs, xreplace, diff, solve); it pickles
    as itself.  Its sums, differences and products with another of its class, and with
    der() of one, are the expressions sympy's own arithmetic builds."""
    from acausal.components.realsymbol import Symbol, real_symbol
    from acausal.components.symbols import der
    a, b, c = real_symbol("R1.v"), real_symbol("C1.i"), real_symbol("C1.C")
    plain, other = sp.Symbol("R1.v", real=True), sp.Symbol("C1.i", real=True)
    assert type(a) is Symbol and isinstance(a, sp.Symbol) and type(a).__name__ == "Symbol"
    assert a == plain and plain == a and not a != plain and not plain != a
    assert hash(a) == hash(plain) and {plain: 1}[a] == 1 and {a: 1}[plain] == 1
    assert a != sp.Symbol("R1.v") and sp.Symbol("R1.v") != a       # not real: another
    assert sp.srepr(a) == sp.srepr(plain) and str(a) == "R1.v"
    assert sp.default_sort_key(a) == sp.default_sort_key(plain) and a.compare(plain) == 0
    assert a.is_real and (a**2).is_nonnegative and a.is_positive is None
    assert Symbol("x") is Symbol("x", real=True)          # always real: one per name
    r = pickle.loads(pickle.dumps(a))
    assert type(r) is Symbol and r == a
    e = 3 * a + a * b + sp.sin(a)
    assert e.subs(plain, 2) == 2 * b + sp.sin(2) + 6
    assert e.subs({plain: 2, other: 3}) == sp.sin(2) + 12
    assert e.xreplace({plain: 2}) == 2 * b + sp.sin(2) + 6
    assert sp.diff(e, plain) == b + sp.cos(a) + 3 and plain in e.free_symbols
    assert sp.solve(2 * a - 4, plain) == [2]
    for x, y in ((a, b), (b, a), (c, b), (a, a)):
        for op in ("__add__", "__sub__", "__mul__"):
            built, ref = getattr(x, op)(y), getattr(sp.Expr, op)(x, y)
            assert built == ref and sp.srepr(built) == sp.srepr(ref), (op, x, y)
    d = der(b)
    assert c * d == sp.Expr.__mul__(c, d) and sp.srepr(c * d) == sp.srepr(sp.Expr.__mul__(c, d))
    # mixed with sympy's own symbols (time), sympy's order and arithmetic
    t = sp.Symbol("time", real=True)
    assert a - t == sp.Expr.__sub__(a, t) and sp.srepr(b + t) == sp.srepr(sp.Add(b, t))
    assert a + plain == 2 * a and a - plain == 0


def test_simple_partials_are_the_general_partials():
    """The partials read off a symbol, a product of two factors and a negated sum of
    +-symbols are partial()'s, the same objects; any other form is left to it."""
    from acausal.compiler.algebra.derivative import partial, simple_partials
    L, R = sp.symbols("L R", positive=True)
    def minus(s):        # -(s), kept a product, as solve_linear builds it
        return sp.Mul(sp.S.NegativeOne, s, evaluate=False)

    read_off = [x, -x, 2 * x, sp.Float(0.5) * x, x / L, R * y, x * y, p * x, x / (L + R),
                minus(x - y), minus(x + y - z), minus(y - x + z), minus(x + y)]
    left = [x ** 2, 2 * x * y, minus(x - 2 * y), minus(x - y * z), x * sp.sin(x), sp.sin(x),
            x + y, minus(x + 1), p * x * y, -(x - y)]
    for e in read_off:
        wanted = sorted(e.free_symbols - {L, R, p}, key=str)
        got = simple_partials(e, wanted)
        assert got is not None, e
        for v in wanted:
            ref = partial(e, v)
            assert got[v] == ref and sp.srepr(got[v]) == sp.srepr(ref), (e, v)
        assert list(got) == wanted
    for e in left:
        wanted = sorted(e.free_symbols - {p}, key=str)
        assert simple_partials(e, wanted) is None, e
