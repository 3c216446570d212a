"""Results that scale: ``simulate(..., store="run.h5")`` writes the run as it goes and
gives the same numbers as a run held in memory; ``outputs=[...]`` keeps only what was
asked for; a stored variable is read alone.  The reference values are the in-memory
run's, which itself follows the RC step's closed form (test_ensemble.py)."""
import numpy as np
import pytest

import acausal as ac
from acausal.solvers import integrate

from .models import BouncingBall, StepRC, rc_voltage

pytest.importorskip("h5py")

KW = {"rtol": 1e-9, "atol": 1e-12}


def test_a_stored_run_equals_the_run_held_in_memory(tmp_path):
    compiled = ac.compile(StepRC())
    memory = ac.simulate(compiled, 2.0, n_points=20001, **KW)
    stored = ac.simulate(compiled, 2.0, n_points=20001, store=tmp_path / "run.h5", **KW)
    assert stored.compiled is None and stored.success == memory.success
    assert np.array_equal(stored.t, memory.t)
    assert stored.names == memory.names
    for name in memory.names:
        assert np.array_equal(stored[name], memory[name]), name
    assert [float(e) for e in stored.events] == [float(e) for e in memory.events]
    assert stored.parameter_values == memory.parameter_values
    assert stored.units["C1.v"] == "V" and stored.states == memory.states
    exact = rc_voltage(stored.t)
    assert np.max(np.abs(stored["C1.v"] - exact)) <= 1e-7 * 2.0


def test_a_stored_variable_is_read_alone(tmp_path):
    res = ac.simulate(StepRC(), 1.0, n_points=1001, store=tmp_path / "run.h5", **KW)
    table = res._table
    assert not table.read
    res["C1.v"]
    assert list(table.read) == ["C1.v"]
    loaded = ac.load_result(tmp_path / "run.h5")
    assert np.array_equal(loaded["R1.i"], res["R1.i"])


def test_the_run_streams_its_points_to_the_sink():
    compiled = ac.compile(StepRC())

    class Counting:
        def __init__(self):
            self.t = []

        def add(self, t, y, index, values, snapshots):
            assert len(y) == len(t) == len(index)
            self.t += list(t)

    sink = Counting()
    y0, yp0 = compiled.initialize(0.0)
    out = integrate(compiled, (0.0, 1.0), y0, yp0, rtol=1e-8, t_eval=np.linspace(0, 1, 10001),
                    initialize=False, sink=sink)
    assert len(out.t) == 0 and out.points == 10001    # the output held none of them
    assert np.array_equal(np.array(sink.t), np.linspace(0, 1, 10001))


def test_outputs_keeps_what_was_asked_for(tmp_path):
    compiled = ac.compile(StepRC())
    full = ac.simulate(compiled, 1.0, n_points=101, **KW)
    kept = ac.simulate(compiled, 1.0, n_points=101, outputs=["C1.v", "R1.i"], **KW)
    assert kept.names == ["C1.v", "R1.i"]
    assert np.array_equal(kept["C1.v"], full["C1.v"])
    with pytest.raises(KeyError, match="outputs="):
        kept["R1.v"]
    stored = ac.simulate(compiled, 1.0, n_points=101, outputs=["R1.i"],
                         store=tmp_path / "r.h5", **KW)
    assert stored.names == ["R1.i"] and np.array_equal(stored["R1.i"], full["R1.i"])
    with pytest.raises(ac.InvalidArgument, match=r"no variable 'C1.vv' \(did you mean "
                                                 r"'C1.v'\?\)"):
        ac.simulate(compiled, 1.0, outputs=["C1.vv"])
    with pytest.raises(ac.InvalidArgument, match="does not exist"):
        ac.simulate(compiled, 1.0, store=tmp_path / "no" / "such" / "run.h5")


def test_a_failed_run_stores_what_it_computed(tmp_path):
    # e = 0.5: the bounces accumulate before 2 s (chattering), the run stops there
    with pytest.warns(RuntimeWarning, match="stopped early"):
        res = ac.simulate(BouncingBall(e=0.5), 2.0, store=tmp_path / "ball.h5", rtol=1e-8,
                          atol=1e-10)
    assert not res.success and "chattering" in res.message
    loaded = ac.load_result(tmp_path / "ball.h5")
    assert not loaded.success and len(loaded.t) == len(res.t) > 10
    assert np.all(np.isfinite(loaded["h"]))
