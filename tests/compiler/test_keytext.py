"""The cache key's texts are ExactText's: the recursive walk, the shared assumption
texts and the references to repeated texts change the speed of the key, not what it
says (a text with its references replaced by what they stand for is ExactText's)."""
import re

import sympy as sp

from acausal.compiler.cache.keys import _key_text, _plain
from acausal.compiler.frontend.flatten import flatten
from acausal.compiler.algebra.symbolic import ExactText
from acausal.library.examples.motor_drive import MotorDrive
from acausal.library.examples.pendulum import Pendulum


def _expanded(key, text):
    """The key text with each reference replaced by the text it stands for."""
    return re.sub("\x1d([0-9]+)", lambda m: key.defs[int(m.group(1))], text)


def test_key_texts_of_flat_models_are_exacttexts():
    for model in (MotorDrive(), Pendulum()):
        flat = flatten(model)
        key, ref = _key_text(), ExactText(_plain)
        for eq in flat.equations + flat.initial_equations:
            text = key(eq.residual)
            assert len(text) < len(ref(eq.residual))
            assert _expanded(key, text) == ref(eq.residual)
        for p in flat.parameters:
            assert _expanded(key, key(p.value)) == ref(p.value)
        # one reference, one text
        assert len(set(key.defs)) == len(key.defs)


def test_deep_and_unusual_expressions():
    x = sp.Symbol("x", real=True)
    y = sp.Symbol("y", positive=True)
    f = sp.Function("f")
    deep = x
    for i in range(150):                  # deeper than the recursion's limit
        deep = f(deep, i)
    for e in (deep, x + 2 * y ** 2 + sp.Float(0.25), sp.pi * x, sp.oo, sp.Rational(3, 7),
              sp.Piecewise((x, x > 0), (y, True)), 1.5, "text", None):
        key = _key_text()
        assert _expanded(key, key(e)) == ExactText(_plain)(e)


def test_a_declared_attribute_written_once_still_changes_the_key():
    """The key's references stand for their texts: two flat models that differ only in
    one variable's start value, or one's description, have different keys; the same
    model flattened twice has one."""
    from dataclasses import replace

    from acausal.compiler.cache.keys import flat_key
    first, again = flatten(MotorDrive()), flatten(MotorDrive())
    assert flat_key(first, "numpy") == flat_key(again, "numpy")
    for change in ({"start": 0.125}, {"description": "another text"}):
        changed = flatten(MotorDrive())
        k = next(i for i, v in enumerate(changed.variables) if v.attrs.start is None)
        v = changed.variables[k]
        changed.variables[k] = replace(v, attrs=replace(v.attrs, **change))
        assert flat_key(changed, "numpy") != flat_key(first, "numpy"), change


def _key_text_length(model, monkeypatch) -> int:
    from acausal.compiler.cache import keys as cachekeys
    seen = []
    digest = cachekeys._Hasher.hexdigest

    def spy(self):
        seen.append(sum(map(len, self.parts)))
        return digest(self)

    monkeypatch.setattr(cachekeys._Hasher, "hexdigest", spy)
    cachekeys.flat_key(flatten(model), "numpy")
    return seen[-1]


def test_the_key_of_a_large_node_grows_with_its_ports(monkeypatch):
    """A ladder's capacitors share one ground: n + 2 ports, n + 1 equations each
    located by all of them.  The key text is linear in n (the location written once),
    not quadratic."""
    import sys
    sys.path.insert(0, str(__import__("pathlib").Path(__file__).parents[2] / "benchmarks"))
    from families import RLCLadder
    small, large = (_key_text_length(RLCLadder(n), monkeypatch) for n in (100, 400))
    assert large < 4.6 * small


def test_the_key_says_which_variable_an_equation_reads():
    """Symbols in the equations are written as their numbers in the variable records:
    two models that differ only in which variable one equation reads have different
    keys, and swapping the order of two variables' records changes the key."""
    from acausal.compiler.cache.keys import flat_key
    first = flatten(MotorDrive())
    base = flat_key(first, "numpy")
    changed = flatten(MotorDrive())
    k = next(i for i, eq in enumerate(changed.equations)
             if eq.residual.is_Add and len(eq.residual.free_symbols) >= 2)
    a, b = sorted(changed.equations[k].residual.free_symbols, key=str)[:2]
    eq = changed.equations[k]
    eq.residual = eq.residual.xreplace({a: b, b: a})
    eq.source = "swapped"
    assert flat_key(changed, "numpy") != base
    swapped = flatten(MotorDrive())
    swapped.variables[0], swapped.variables[1] = swapped.variables[1], swapped.variables[0]
    assert flat_key(swapped, "numpy") != base
