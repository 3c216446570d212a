"""The compile cache: a hit gives the same model (and says so in its report), every change
that alters the model misses, a damaged cache is rebuilt, and a second process loads an
unchanged model without importing sympy.

The reference of the runs is the closed form of an RC discharge, v(t) = v0 exp(-t/tau),
with tau the time constant of the circuit each variant builds.
"""
import importlib
import os
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import acausal as ac
from acausal.compiler.cache import entries as store
from acausal.compiler.pipeline import compile_model
from acausal.runtime import CompiledModel

from .circuits import RC
from .helpers import assert_same_run, run_python

HIT = "came from the compile cache"


@pytest.fixture(autouse=True)
def cache_dir(fresh_cache):
    return fresh_cache


def _compile(model, backend="numpy", cache=True):
    return CompiledModel(compile_model(model, backend, cache=cache))


def _from_cache(compiled) -> bool:
    return any(HIT in n for n in compiled.report.notes)


def _tau(compiled) -> float:
    """The time constant of the discharge, fitted from v(1)/v(0) (closed form exp(-t/tau))."""
    res = ac.simulate(compiled, t_end=1.0, rtol=1e-10, atol=1e-12)
    v = res["C1.v"]
    assert np.max(np.abs(v - v[0] * np.exp(-res.t * np.log(v[0] / v[-1])))) <= 1e-6
    return 1.0 / np.log(v[0] / v[-1])


@pytest.mark.parametrize("backend", ["numpy", "c"])
def test_a_hit_gives_the_same_model_and_says_so(backend):
    if backend == "c":
        from acausal.compiler.backends import cbackend
        if cbackend.compiler_available() is None:
            pytest.skip("no C compiler")
    first = _compile(RC(), backend)
    assert not _from_cache(first)
    # by default the exact key, of the flat model; the instance tree only when asked
    second = _compile(RC(), backend)
    assert _from_cache(second)
    assert "flat model" in [n for n in second.report.notes if HIT in n][0]
    by_tree = _compile(RC(), backend, cache="tree")      # finds it, and indexes it
    assert _from_cache(by_tree)
    second = _compile(RC(), backend, cache="tree")
    assert "instance tree" in [n for n in second.report.notes if HIT in n][0]
    assert second.backend == first.backend == backend
    # the timings are those of the original compile, plus the lookup
    assert set(first.report.timings) - {"cache_store"} <= set(second.report.timings)
    assert "cache_lookup" in second.report.timings
    a = ac.simulate(first, t_end=2.0, rtol=1e-9)
    b = ac.simulate(second, t_end=2.0, rtol=1e-9)
    assert_same_run(a, b)
    exact = np.exp(-b.t)               # tau = R C = 1 s
    assert np.max(np.abs(b["C1.v"] - exact)) <= 1e-6


def test_a_model_without_a_tree_key_is_found_by_its_flat_model():
    class Local(ac.Component):          # defined here: no stable description of its class
        x = ac.Variable(start=2.0, fixed=True)
        k = ac.Parameter(0.5)

        def equations(self):
            return [ac.Eq(ac.der(self.x), -self.k * self.x)]

    assert store.tree_key(Local(), "numpy") is None
    _compile(Local())
    again = _compile(Local())
    assert _from_cache(again)
    assert "flat model" in [n for n in again.report.notes if HIT in n][0]
    res = ac.simulate(again, t_end=1.0, rtol=1e-10, atol=1e-12)
    assert abs(res["x"][-1] - 2.0 * np.exp(-0.5)) <= 1e-7 * 2.0
    # a changed parameter value is another flat model
    changed = _compile(Local(k=0.25))
    assert not _from_cache(changed)


MODULE = '''
import acausal as ac
from acausal.library.electrical import Capacitor, Ground
from acausal.library.electrical.interfaces import OnePort


class Leak(OnePort):
    R = ac.Parameter({R}, unit="Ohm")

    def equations(self):
        return [ac.Eq(self.v, {LAW})]


class Circuit(ac.Component):
    R1 = Leak()
    R2 = Leak()
    C1 = Capacitor(C=1.0, v={{"start": 1.0, "fixed": True}})
    gnd = Ground()

    def equations(self):
        return [{CONNECT}]
'''
SERIES = ("ac.connect(self.C1.p, self.R1.p), ac.connect(self.R1.n, self.R2.p), "
          "ac.connect(self.R2.n, self.C1.n, self.gnd.p)")
PARALLEL = ("ac.connect(self.C1.p, self.R1.p, self.R2.p), "
            "ac.connect(self.R1.n, self.R2.n, self.C1.n, self.gnd.p)")


def _write(tmp_path, **parts):
    text = MODULE.format(**{"R": "1.0", "LAW": "self.R * self.i", "CONNECT": SERIES,
                            **parts})
    (tmp_path / "circuit_variant.py").write_text(textwrap.dedent(text))


def test_changing_a_default_an_equation_or_a_connection_compiles_again(tmp_path,
                                                                       monkeypatch):
    monkeypatch.syspath_prepend(str(tmp_path))
    _write(tmp_path)
    mod = importlib.import_module("circuit_variant")
    try:
        base = _compile(mod.Circuit())
        assert not _from_cache(base) and abs(_tau(base) - 2.0) <= 1e-6     # (R1 + R2) C
        assert _from_cache(_compile(mod.Circuit()))
        variants = [({"R": "1.5"}, 3.0),                     # a parameter default
                    ({"LAW": "2 * self.R * self.i"}, 4.0),   # an equation of the class
                    ({"CONNECT": PARALLEL}, 0.5)]            # the connections
        for parts, tau in variants:
            _write(tmp_path, **parts)
            importlib.reload(mod)
            compiled = _compile(mod.Circuit())
            assert not _from_cache(compiled), parts
            assert abs(_tau(compiled) - tau) <= 1e-6 * tau, parts
        # a modification at instantiation is another model; the same one is found again
        _write(tmp_path)
        importlib.reload(mod)
        assert _from_cache(_compile(mod.Circuit()))
        modified = _compile(mod.Circuit(R2={"R": 3.0}))
        assert not _from_cache(modified) and abs(_tau(modified) - 4.0) <= 1e-6 * 4
    finally:
        sys.modules.pop("circuit_variant", None)


def test_a_changed_class_attribute_compiles_again():
    RC.note = "structural"               # a class attribute an equations() could read
    try:
        before = store.tree_key(RC(), "numpy")
        assert not _from_cache(_compile(RC()))
        RC.note = "changed"
        assert store.tree_key(RC(), "numpy") != before
        # the equations do not read it: the flat model is the same, and decides
        again = _compile(RC())
        assert "flat model" in [n for n in again.report.notes if HIT in n][0]
    finally:
        del RC.note


def _entries(models) -> list:
    """The cache entries (not their side files of Programs, read only by FMU export)."""
    return sorted(p for p in models.glob("*.pkl") if not p.name.endswith(".programs.pkl"))


def test_a_corrupt_or_truncated_entry_is_ignored_and_rebuilt(cache_dir):
    _compile(RC())
    models = cache_dir / "models"
    entries = _entries(models)
    assert len(entries) == 1
    entries[0].write_bytes(b"\x80\x05 not a pickle")
    rebuilt = _compile(RC())
    assert not _from_cache(rebuilt)
    assert abs(ac.simulate(rebuilt, t_end=1.0, rtol=1e-9)["C1.v"][-1] - np.exp(-1)) <= 1e-6
    assert _from_cache(_compile(RC()))            # the entry was written again
    for index in models.glob("tree-*"):
        index.write_text("../../etc/passwd")
    entries = _entries(models)
    entries[0].write_bytes(entries[0].read_bytes()[:100])
    assert not _from_cache(_compile(RC()))
    assert _from_cache(_compile(RC()))


def test_the_size_bound_prunes_and_the_switch_turns_the_cache_off(cache_dir, monkeypatch):
    monkeypatch.setenv("ACAUSAL_CACHE_SIZE", "1")
    _compile(RC())
    assert not list((cache_dir / "models").glob("*.pkl"))      # pruned at once
    assert not _from_cache(_compile(RC()))
    monkeypatch.delenv("ACAUSAL_CACHE_SIZE")
    monkeypatch.setenv("ACAUSAL_COMPILE_CACHE", "0")
    _compile(RC())
    assert not _from_cache(_compile(RC()))
    assert not list((cache_dir / "models").glob("*.pkl"))


SECOND_PROCESS = """
import sys
import acausal as ac
from acausal.compiler.pipeline import compile_model
from acausal.runtime import CompiledModel
from acausal.tests.persist.circuits import RC
compiled = CompiledModel(compile_model(RC(), "numpy", cache="tree"))
res = ac.simulate(compiled, t_end=1.0, rtol=1e-9)
print(any("came from the compile cache" in n for n in compiled.report.notes),
      "sympy" in sys.modules, repr(float(res["C1.v"][-1])))
"""


def test_two_processes_at_once_then_a_third_loads_without_sympy(cache_dir):
    env = dict(os.environ, ACAUSAL_CACHE=str(cache_dir))
    procs = [subprocess.Popen([sys.executable, "-c", SECOND_PROCESS], env=env,
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
             for _ in range(2)]
    for proc in procs:
        out, err = proc.communicate(timeout=300)
        assert proc.returncode == 0, err[-3000:]
        assert abs(float(out.split()[2]) - np.exp(-1.0)) <= 1e-6
    assert not list((cache_dir / "models").glob(".tmp-*"))    # no half-written entry
    hit, sympy_loaded, v = run_python(SECOND_PROCESS, cache_dir).split()
    assert hit == "True" and sympy_loaded == "False"
    assert abs(float(v) - np.exp(-1.0)) <= 1e-6


def test_models_with_events_and_dynamic_states_come_back_equal():
    from acausal.library.examples.pendulum import Pendulum
    from acausal.tests.models.test_events import BouncingBall
    for model_class, t_end in ((Pendulum, 3.0), (BouncingBall, 2.0)):
        first = _compile(model_class())
        second = _compile(model_class())
        assert _from_cache(second) and not _from_cache(first)
        assert second.report.differential_index == first.report.differential_index
        assert_same_run(ac.simulate(first, t_end=t_end, rtol=1e-8),
                        ac.simulate(second, t_end=t_end, rtol=1e-8))


def test_exact_texts_tell_apart_what_the_compiler_would():
    import sympy as sp
    from acausal.compiler.algebra.symbolic import ExactText
    x, y = sp.symbols("x y", real=True)
    ex = ExactText()
    texts = [ex(e) for e in (2 * x, 2.0 * x, sp.Float("2.0000000000000001", 30) * x,
                             sp.Rational(1, 3) * x, x / 3.0, sp.Dummy("x") * 2, x + y,
                             x - y, sp.Piecewise((x, x > 0), (y, True)),
                             sp.Piecewise((x, x >= 0), (y, True)), sp.Symbol("x") * 2)]
    assert len(set(texts)) == len(texts)
    assert ex(x + 2 * y) == ExactText()(y * 2 + x)       # the same expression, the same text
    # a long chain is printed without recursion
    long = sp.Add(*[sp.Symbol(f"q{k}", real=True) ** 2 for k in range(3000)])
    assert len(ex(long)) > 3000 * 20


def test_a_component_given_as_an_argument_is_part_of_the_tree_key():
    from acausal.library.electrical import Resistor

    base = RC()
    object.__setattr__(base, "spare", Resistor(R=1.0))     # a plain attribute, not a child
    other = RC()
    object.__setattr__(other, "spare", Resistor(R=5.0))
    assert store.tree_key(base, "numpy") != store.tree_key(other, "numpy")


GLOBAL_RATE = {"k": 1.0}        # read by an equation at call time: no source changes


class ReadsAGlobal(ac.Component):
    x = ac.Variable(start=1.0)

    def equations(self):
        return [ac.Eq(ac.der(self.x), -GLOBAL_RATE["k"] * self.x)]


def test_the_default_key_sees_what_equations_read_at_call_time():
    """The flat key is exact: an equation whose constant comes from a mutable global gets
    a new compile when the global changes, and the decay rate follows it."""
    first = _compile(ReadsAGlobal())
    GLOBAL_RATE["k"] = 3.0
    try:
        second = _compile(ReadsAGlobal())
    finally:
        GLOBAL_RATE["k"] = 1.0
    assert not _from_cache(second)
    for compiled, k in ((first, 1.0), (second, 3.0)):
        res = ac.simulate(compiled, t_end=1.0, rtol=1e-9)
        assert abs(res["x"][-1] - np.exp(-k)) <= 1e-6 * np.exp(-k)
