"""``components.symbols.text`` is sympy's ``sstr``, character for character, on the
expressions models are made of and on others: random sums, products, powers, numbers
(integers, fractions, floats, negative ones), derivatives and functions of dotted and
indexed names, and every equation of a few library examples."""
import random

import sympy as sp

import acausal as ac
from acausal.components.symbols import der, text

NAMES = ["x", "R[0].v", "R[10].i", "L[2].L", "a.b.c", "C[3].p.v", "z_1", "Y", "w[1,0]",
         "phi", "tau"]


def _random_expr(rng, symbols, depth=0):
    k = rng.randrange(12 if depth < 3 else 4)
    if k == 0:
        return rng.choice([sp.Integer(rng.randint(-5, 5)), sp.Rational(rng.randint(-7, 7), 3),
                           sp.Float(rng.uniform(-10, 10)), sp.Float(2.5)])
    if k in (1, 2, 3):
        return rng.choice(symbols)
    if k == 4:
        return der(rng.choice(symbols))
    args = [_random_expr(rng, symbols, depth + 1) for _ in range(rng.randint(2, 4))]
    if k in (5, 6):
        return sp.Add(*args)
    if k in (7, 8):
        return sp.Mul(*args)
    if k == 9:
        return sp.Pow(args[0], rng.choice([2, -1, -2, sp.Rational(1, 2), 3]))
    if k == 10:
        return rng.choice([sp.sin, sp.exp, sp.Function("f"), sp.Abs])(args[0])
    return -args[0]


def test_random_expressions_print_as_sympy_prints_them():
    rng = random.Random(11)
    symbols = [sp.Symbol(n, real=True) for n in NAMES]
    seen = 0
    for _ in range(3000):
        e = _random_expr(rng, symbols)
        assert text(e) == sp.sstr(e), sp.srepr(e)
        seen += e.is_Mul or e.is_Add
    assert seen > 1000


def test_the_equations_of_library_examples_print_as_sympy_prints_them():
    from acausal.compiler.frontend.flatten import flatten
    from acausal.library.examples.motor_drive import MotorDrive
    from acausal.library.examples.pendulum import Pendulum
    from acausal.library.rotational.examples.coupled_clutches import CoupledClutches
    n = 0
    for model in (MotorDrive(), Pendulum(), CoupledClutches()):
        for eq in flatten(model).equations:
            assert text(eq.residual) == sp.sstr(eq.residual)
            n += 1
    assert n > 50
    assert ac.Eq(sp.Symbol("x") * 2, 1).text == sp.sstr(sp.Symbol("x") * 2) + " = 1"
