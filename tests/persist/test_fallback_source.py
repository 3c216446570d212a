"""The Python functions behind a C library are printed only when first needed: a call
whose C output is not finite is repeated in Python, and the error it raises names the
failing equation (here der(x) = -sqrt(x) at x = -1, a math domain error) with the same
words as the numpy backend -- for a model just compiled, pickled, or loaded from the
compile cache in another process (whose entry keeps the Program to print it from, in
its side file, and is compiled again without it)."""
import pickle

import pytest

import acausal as ac
from acausal.compiler.backends import cbackend
from acausal.compiler.pipeline import compile_model
from acausal.runtime import CompiledModel

# the package name, as the other process imports it: the tree key names the class by
# its module, and pytest may import this directory under another name
from acausal.tests.persist.circuits import SqrtOfStart
from .helpers import run_python

pytestmark = pytest.mark.skipif(cbackend.compiler_available() is None,
                                reason="no C compiler on this machine")

HIT = "came from the compile cache"


@pytest.fixture(autouse=True)
def cache_dir(fresh_cache):
    return fresh_cache


def _failure(compiled) -> str:
    with pytest.raises(ac.InitializationFailed) as err:
        ac.simulate(compiled, t_end=1.0)
    return str(err.value)


def _numpy_message() -> str:
    return _failure(CompiledModel(compile_model(SqrtOfStart(), "numpy", cache=False)))


def test_a_fresh_c_model_prints_its_python_at_the_failure():
    compiled = CompiledModel(compile_model(SqrtOfStart(), "c", cache=False))
    code = compiled.model_code.initial.code
    assert not code.module.printed                      # not printed by the compile
    message = _failure(compiled)
    assert "der(x)" in message and "math domain error" in message
    assert message == _numpy_message()
    again = pickle.loads(pickle.dumps(compiled))        # a pickle keeps the source
    assert _failure(again) == message


LOAD = """
import sys
import acausal as ac
from acausal.compiler.pipeline import compile_model
from acausal.runtime import CompiledModel
from acausal.tests.persist.circuits import SqrtOfStart
compiled = CompiledModel(compile_model(SqrtOfStart(), "c", cache="tree"))
loaded = any("came from the compile cache" in n for n in compiled.report.notes)
without_sympy = "sympy" not in sys.modules
try:
    ac.simulate(compiled, t_end=1.0)
    print("no failure")
except ac.InitializationFailed as exc:
    print(repr((loaded, without_sympy, str(exc))))
"""


def test_a_model_from_the_cache_prints_its_python_from_the_side_file(cache_dir):
    first = CompiledModel(compile_model(SqrtOfStart(), "c", cache="tree"))
    assert not first.model_code.initial.code.module.printed
    expected = _numpy_message()
    loaded, without_sympy, message = eval(run_python(LOAD, cache_dir).strip())  # noqa: S307
    assert loaded and without_sympy          # loading needed neither sympy nor the source
    assert message == expected
    sides = list((cache_dir / "models").glob("*.programs.pkl"))
    assert len(sides) == 1
    sides[0].unlink()                        # the entry cannot print its source any more:
    loaded, _, message = eval(run_python(LOAD, cache_dir).strip())  # noqa: S307
    assert not loaded and message == expected           # so it was compiled again


def test_pruning_removes_an_entry_with_its_side_file(cache_dir, monkeypatch):
    CompiledModel(compile_model(SqrtOfStart(), "c", cache=True))
    models = cache_dir / "models"
    assert len(list(models.glob("*.programs.pkl"))) == 1
    monkeypatch.setenv("ACAUSAL_CACHE_SIZE", "1")
    from acausal.compiler.cache import entries as cache
    cache._prune(str(cache_dir))
    assert not list(models.glob("*.pkl"))


def test_a_model_from_the_cache_pickles_with_its_source_printed():
    """A user's pickle of a model loaded from the cache carries the source (printed
    from the entry's side file), so it needs neither the cache nor the Program."""
    CompiledModel(compile_model(SqrtOfStart(), "c", cache=True))
    loaded = CompiledModel(compile_model(SqrtOfStart(), "c", cache=True))
    assert any(HIT in n for n in loaded.report.notes)
    assert not loaded.model_code.initial.code.module.printed
    again = pickle.loads(pickle.dumps(loaded))
    assert again.model_code.initial.code.module.printed
    assert _failure(again) == _numpy_message()
