"""Inside ``symbol_arithmetic`` the sums, differences and products of two symbols are
the expressions sympy builds (the same tree, argument order included); outside it
Symbol's own arithmetic is sympy's again."""
import random

import sympy as sp

from acausal.compiler.frontend.fastarith import symbol_arithmetic
from acausal.components.symbols import der

NAMES = ["a", "b", "a.b", "a_b", "A", "R1.p.v", "R10.n.i", "x[1]", "x[10]", "Z", "_x"]


def _operands(rng):
    syms = [sp.Symbol(n, real=True) for n in NAMES]
    syms += [sp.Symbol("q"), sp.Symbol("a"), sp.Dummy("d"),
             sp.Symbol("nc", commutative=False)]
    pool = syms + [der(syms[0]), der(syms[3] - syms[4]), sp.Integer(2), sp.Float(1.5),
                   syms[1] + syms[2], -syms[5]]
    return rng.choice(syms), rng.choice(pool)


def test_two_symbol_arithmetic_is_sympys():
    rng = random.Random(3)
    cases = [_operands(rng) for _ in range(500)]
    reference = [(a + b, a - b, a * b) for a, b in cases]
    with symbol_arithmetic():
        fast = [(a + b, a - b, a * b) for a, b in cases]
        assert type(sp.Symbol("a")).__dict__.get("__add__") is not None
    for (a, b), ref, out in zip(cases, reference, fast):
        for r, o in zip(ref, out):
            assert r == o and sp.srepr(r) == sp.srepr(o), (a, b, r, o)


def test_blocks_nest_and_restore_sympys_methods():
    x, y = sp.symbols("x y", real=True)
    with symbol_arithmetic():
        with symbol_arithmetic():
            assert x - y == sp.Add(x, -y)
        assert "__sub__" in sp.Symbol.__dict__          # still the outer block's
    assert "__sub__" not in sp.Symbol.__dict__
    with sp.evaluate(False), symbol_arithmetic():        # unevaluated: sympy's own
        assert sp.srepr(x + y) == sp.srepr(sp.Add(x, y, evaluate=False))
