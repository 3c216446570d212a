"""The index report: text, data, pictures, and provenance of every equation."""
import json

import acausal as ac
from acausal.library.electromechanical import DCMotor
from acausal.library.electrical import ConstantVoltage, Ground
from acausal.library.examples.motor_drive import MotorDrive
from acausal.library.examples.pendulum import Pendulum


def test_report_text_and_json_agree():
    rep = ac.compile(Pendulum()).report
    data = json.loads(rep.to_json())
    assert data["differential_index"] == 3 == rep.differential_index
    assert data["sigma"]["agrees"] is True
    assert "differential index: 3" in str(rep)
    # every equation of the reduced system says where it came from
    derived = [e for e in data["equations"] if e["order"] == 2]
    assert len(derived) == 1 and "x**2 + y**2" in derived[0]["text"]
    assert derived[0]["text"].startswith("d^2/dt^2(")


def test_report_counts_every_pass():
    rep = ac.compile(MotorDrive()).report
    assert list(rep.counts)[:2] == ["flatten", "alias"]
    assert rep.counts["alias"]["equations"] < rep.counts["flatten"]["equations"]
    assert set(rep.timings) >= {"flatten", "alias", "balance", "index_reduction", "codegen"}


def test_report_dot_and_blt_order():
    rep = ac.compile(MotorDrive()).report
    dot = rep.to_dot()
    assert dot.startswith('digraph "MotorDrive"') and dot.count("->") > 5
    eqs, vars_ = rep.blt_order()
    assert len(eqs) == len(vars_) == sum(b["size"] for b in rep.blocks)


def test_structural_zero_is_reported():
    class Motor(ac.Component):
        src = ConstantVoltage(V=1.0)
        gnd = Ground()
        m = DCMotor(L=0.0)

        def equations(self):
            return [ac.connect(self.src.p, self.m.p), ac.connect(self.src.n, self.m.n, self.gnd.p)]

    compiled = ac.compile(Motor())
    assert any("m.L" in note for note in compiled.report.notes)
    assert "m.La.i" not in compiled.states


def test_equation_texts_printed_on_first_read_are_the_same():
    """The texts are printed when the report is first read: the rows, the printed report
    and the JSON of a report read after pickling (which prints them) equal those of the
    report read directly, and each names its equation as written with its component."""
    import pickle

    from acausal.compiler.pipeline import compile_model
    first = compile_model(Pendulum(), "numpy").report
    second = pickle.loads(pickle.dumps(compile_model(Pendulum(), "numpy").report))
    assert [e["text"] for e in first.equations] == [e["text"] for e in second.equations]
    assert all(isinstance(e["text"], str) and "[" in e["text"] or e["order"] > 0
               for e in first.equations)
    strip = (lambda text: text.rsplit("compile time", 1)[0])
    assert strip(str(first)) == strip(str(second))
    one, two = json.loads(first.to_json()), json.loads(second.to_json())
    for d in (one, two):
        d.pop("timings_s")
        d["units"].pop("seconds", None)
    assert one == two


def test_residual_names_read_as_a_list():
    """The names of the residual rows (messages about failing rows) are a sequence that
    equals, and pickles as, the plain list of the equations' texts."""
    import pickle

    from acausal.compiler.pipeline import compile_model
    mc = compile_model(Pendulum(), "numpy")
    names = mc.meta["equation_names"]
    assert len(names) == mc.n_res > 0 and list(names) == [names[k] for k in range(len(names))]
    texts = {e["text"] for e in mc.report.equations}
    assert set(names) <= texts
    back = pickle.loads(pickle.dumps(names))
    assert type(back) is list and back == list(names) and names == back
