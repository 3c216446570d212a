"""The cache key's texts are ExactText's: the recursive walk and the shared assumption
texts change the speed of the key, not the key."""
import sympy as sp

from acausal.compiler.cachekeys import _key_text, _plain
from acausal.compiler.flatten import flatten
from acausal.compiler.symbolic import ExactText
from acausal.library.examples.motor_drive import MotorDrive
from acausal.library.examples.pendulum import Pendulum


def test_key_texts_of_flat_models_are_exacttexts():
    for model in (MotorDrive(), Pendulum()):
        flat = flatten(model)
        key, ref = _key_text(), ExactText(_plain)
        for eq in flat.equations + flat.initial_equations:
            assert key(eq.residual) == ref(eq.residual)
        for p in flat.parameters:
            assert key(p.value) == ref(p.value)


def test_deep_and_unusual_expressions():
    x = sp.Symbol("x", real=True)
    y = sp.Symbol("y", positive=True)
    f = sp.Function("f")
    deep = x
    for i in range(150):                  # deeper than the recursion's limit
        deep = f(deep, i)
    for e in (deep, x + 2 * y ** 2 + sp.Float(0.25), sp.pi * x, sp.oo, sp.Rational(3, 7),
              sp.Piecewise((x, x > 0), (y, True)), 1.5, "text", None):
        assert _key_text()(e) == ExactText(_plain)(e)
