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
