"""The index of the equations as written is computed when the report is first read:
a compile whose report is never read does not pay for it, and what is read is what the
compile would have computed (Pantelides and Pryce's Sigma-method on the flat model)."""
import pickle

import pytest

import acausal as ac
from acausal.compiler import pipeline
from acausal.compiler.index import as_written
from acausal.compiler.pipeline import compile_model
from acausal.library.electrical import Capacitor, ConstantVoltage, Ground, Resistor
from acausal.library.examples.pendulum import Pendulum
from tests.models.test_index_reduction import CapacitorOnSource
from tests.models.test_numeric_structure import NodalRC


class RCCircuit(ac.Component):
    """Source, resistor, capacitor: an ODE in the capacitor voltage, index 1 as written
    (Pryce's convention: the resistor's current is algebraic)."""

    src = ConstantVoltage(V=5.0)
    R1 = Resistor(R=10.0)
    C1 = Capacitor(C=1e-3)
    gnd = Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.R1.p), ac.connect(self.R1.n, self.C1.p),
                ac.connect(self.src.n, self.C1.n, self.gnd.p)]


# (model, its differential index as written; NodalRC's is hidden by a singular constant
# coefficient matrix, which the conversion finds: its report gives the converted index)
MODELS = [(RCCircuit, 1), (Pendulum, 3), (CapacitorOnSource, 2), (NodalRC, 1)]


@pytest.fixture
def calls(monkeypatch):
    made = []

    def counted(*args, **kw):
        made.append(1)
        return as_written(*args, **kw)
    monkeypatch.setattr(pipeline, "as_written", counted)
    return made


@pytest.mark.parametrize("model, index", MODELS, ids=[m.__name__ for m, _ in MODELS])
def test_index_as_written_read_equals_computed_eagerly(model, index, calls):
    report = compile_model(model(), backend="numpy").report
    assert not calls                              # the compile did not compute it
    eager = as_written(compile_model(model(), until="balance").flat, checked=True)
    assert report.differential_index == index
    assert len(calls) == 1
    read = dict(report.sigma)
    hidden = read.pop("hidden", False)
    after = read.pop("after_conversion", None)
    assert read == eager
    assert hidden == (model is NodalRC) and (after is not None) == hidden
    if not hidden:
        assert report.differential_index == eager["index_pantelides"]
    assert eager["agrees"]
    report.sigma                                  # noqa: B018
    assert len(calls) == 1                        # computed once


@pytest.mark.parametrize("model", [Pendulum, NodalRC])
def test_a_report_pickled_unread_equals_one_read_first(model):
    unread = compile_model(model(), backend="numpy").report
    read = compile_model(model(), backend="numpy").report
    text = str(read)
    loaded = pickle.loads(pickle.dumps(unread))
    assert "_as_written" not in loaded.__dict__
    loaded.timings = read.timings
    assert str(loaded) == text
    assert loaded.sigma == read.sigma
    assert loaded.differential_index == read.differential_index
