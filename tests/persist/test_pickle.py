"""pickle of compiled models and results: the same runs before and after, in this process
and in a fresh one that cannot import sympy, for both backends.

Models: a pendulum in Cartesian coordinates (index 3, dynamic state selection), a
bouncing ball (a when-clause re-initializing a state) and a heater behind a limiter
(relations that switch at events).  The reference of every comparison is the run of the
original object, to 1e-12 of each signal's own size.
"""
import os
import pickle

import numpy as np
import pytest

import acausal as ac
from acausal.compiler.backends import cbackend
from acausal.library.examples.pendulum import Pendulum
from acausal.tests.heater import LimitedHeater
from acausal.tests.models.test_events import BouncingBall

from .helpers import assert_same_run, run_python

BACKENDS = ["numpy", pytest.param("c", marks=pytest.mark.skipif(
    cbackend.compiler_available() is None, reason="no C compiler on this machine"))]
MODELS = [(Pendulum, 3.0), (BouncingBall, 3.0), (LimitedHeater, 600.0)]


@pytest.fixture(autouse=True)
def _own_cache(tmp_path, monkeypatch):
    monkeypatch.setenv("ACAUSAL_CACHE", str(tmp_path / "cache"))


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("model_class, t_end", MODELS, ids=lambda m: getattr(m, "__name__", ""))
def test_a_compiled_model_and_its_result_round_trip(model_class, t_end, backend):
    compiled = ac.compile(model_class(), backend=backend)
    data = pickle.dumps(compiled)
    assert b"sympy" not in data          # the loaded model needs no sympy
    loaded = pickle.loads(data)
    assert loaded.backend == compiled.backend == backend
    assert loaded.names == compiled.names and loaded.param_names == compiled.param_names
    a = ac.simulate(compiled, t_end=t_end, rtol=1e-8)
    b = ac.simulate(loaded, t_end=t_end, rtol=1e-8)
    assert_same_run(a, b)
    assert [e.time if hasattr(e, "time") else e for e in a.events] == \
        [e.time if hasattr(e, "time") else e for e in b.events]
    # a result holds its compiled model: it round-trips with it and runs again
    res = pickle.loads(pickle.dumps(a))
    assert_same_run(a, res, rel=0.0)
    assert_same_run(a, ac.simulate(res.compiled, t_end=t_end, rtol=1e-8))
    assert str(loaded.report) == str(compiled.report)
    assert loaded.report.as_dict()["states"] == compiled.report.as_dict()["states"]


def test_parameters_discrete_state_and_state_choice_are_kept():
    # released near the horizontal: the states are re-chosen during the swing
    compiled = ac.compile(Pendulum(x={"start": 0.99}, y={"start": -0.1}), backend="numpy")
    compiled.set_parameters({"g": 5.0})
    res = ac.simulate(compiled, t_end=3.0, rtol=1e-8)
    assert res.success and len(compiled.dynamic.switches) > 1
    loaded = pickle.loads(pickle.dumps(compiled))
    assert np.array_equal(loaded.p, compiled.p)
    assert loaded.dummies == compiled.dummies
    assert loaded.dynamic.switches == compiled.dynamic.switches
    assert loaded.states == compiled.states
    # the loaded model runs with g = 5: the energy m g y + m v^2 / 2 is conserved
    again = ac.simulate(loaded, t_end=1.0, rtol=1e-9)
    energy = 5.0 * again["y"] + 0.5 * (again["vx"] ** 2 + again["vy"] ** 2)
    assert np.max(np.abs(energy - energy[0])) <= 1e-5 * 5.0
    heater = ac.compile(LimitedHeater(), backend="numpy")
    ac.simulate(heater, t_end=10.0, rtol=1e-8)
    assert heater.m.any()                 # still heating at full power: the limit holds
    assert np.array_equal(pickle.loads(pickle.dumps(heater)).m, heater.m)


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_fresh_process_without_sympy_unpickles_and_simulates(tmp_path, backend):
    compiled = ac.compile(BouncingBall(), backend=backend)
    compiled.set_parameters({"e": 0.7})
    path = tmp_path / "ball.pkl"
    path.write_bytes(pickle.dumps(compiled))
    ref = ac.simulate(compiled, t_end=2.0, rtol=1e-8)
    out = run_python(f"""
import sys
sys.modules["sympy"] = None          # any import of sympy fails
import pickle
import numpy as np
import acausal as ac
compiled = pickle.loads(open({str(path)!r}, "rb").read())
res = ac.simulate(compiled, t_end=2.0, rtol=1e-8)
np.save({str(tmp_path / "h.npy")!r}, np.vstack([res.t, res["h"], res["v"]]))
print(compiled.backend, compiled.p.tolist())
""", tmp_path / "cache")
    assert out.split()[0] == backend
    assert "0.7" in out
    t, h, v = np.load(tmp_path / "h.npy")
    assert np.array_equal(t, ref.t)
    for x, y in ((h, ref["h"]), (v, ref["v"])):
        assert np.max(np.abs(x - y)) <= 1e-12 * np.max(np.abs(y))


@pytest.mark.skipif(cbackend.compiler_available() is None, reason="no C compiler")
def test_a_missing_c_library_is_rebuilt_from_its_source(tmp_path):
    compiled = ac.compile(LimitedHeater(), backend="c")
    data = pickle.dumps(compiled)
    library = compiled.code.library
    assert os.path.dirname(library) == str(tmp_path / "cache")
    os.remove(library)
    loaded = pickle.loads(data)
    assert loaded.backend == "c" and os.path.exists(loaded.code.library)
    assert_same_run(ac.simulate(compiled, t_end=600.0, rtol=1e-8),
                    ac.simulate(loaded, t_end=600.0, rtol=1e-8))


def test_without_a_library_or_a_compiler_the_loaded_model_runs_in_python(tmp_path,
                                                                        monkeypatch):
    if cbackend.compiler_available() is None:
        pytest.skip("no C compiler")
    compiled = ac.compile(BouncingBall(), backend="c")
    data = pickle.dumps(compiled)
    os.remove(compiled.code.library)
    monkeypatch.setenv("CC", "no-such-compiler-acausal")
    loaded = pickle.loads(data)
    assert loaded.backend == "numpy"
    assert any("could not be loaded or built" in n for n in loaded.report.notes)
    assert_same_run(ac.simulate(compiled, t_end=2.0, rtol=1e-8),
                    ac.simulate(loaded, t_end=2.0, rtol=1e-8))


def test_a_variable_fixed_to_a_parameter_expression_survives_pickling():
    import sympy as sp

    class Fixed(ac.Component):
        a = ac.Parameter(2.0)
        x = ac.Variable(start=1.0, fixed=True)
        c = ac.Variable()

        def equations(self):
            return [ac.Eq(self.c, sp.sqrt(self.a)), ac.Eq(ac.der(self.x), -self.x)]

    compiled = ac.compile(Fixed(), backend="numpy")
    loaded = pickle.loads(pickle.dumps(compiled))
    loaded.set_parameters({"a": 9.0})
    res = ac.simulate(loaded, t_end=1.0, rtol=1e-8)
    assert np.allclose(res["c"], 3.0, rtol=1e-14, atol=0)
    assert abs(res["x"][-1] - np.exp(-1.0)) <= 1e-6
