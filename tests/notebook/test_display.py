"""acausal.display: the HTML, SVG and PNG that notebooks show.

Each picture or table is checked against the object it shows: the schematic against the
model's connect() statements, the report tables against the IndexReport's data, the
result summary against the Result's arrays, the poles table against the closed-form poles
of a second-order system (s^2 + 2 zeta wn s + wn^2: wn and zeta recovered).
"""
import base64
import html as htmllib
import re
import shutil
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import acausal as ac
from acausal import display
from acausal.library.electrical import (Capacitor, ConstantVoltage, Ground, Inductor,
                                        Resistor, StepVoltage)
from acausal.display.schematic import DOMAIN_COLOURS
from acausal.library.electromechanical import DCMotor

SVG = "{http://www.w3.org/2000/svg}"


class SeriesRLC(ac.Component):
    """A 1 V step on a resistor, an inductor and a capacitor in series."""

    src = StepVoltage(V=1.0)
    R1 = Resistor(R=10.0)
    L1 = Inductor(L=1e-2)
    C1 = Capacitor(C=1e-4)
    gnd = Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.R1.p),
                ac.connect(self.R1.n, self.L1.p),
                ac.connect(self.L1.n, self.C1.p),
                ac.connect(self.C1.n, self.src.n, self.gnd.p)]


class Bridge(ac.Component):
    """A resistor bridge feeding a capacitor: one algebraic loop, torn."""

    src = ConstantVoltage(V=10.0)
    R1, R2, R3 = Resistor(R=1.0), Resistor(R=2.0), Resistor(R=3.0)
    R4, R5 = Resistor(R=4.0), Resistor(R=5.0)
    C1 = Capacitor(C=1e-3)
    gnd = Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.R1.p, self.R2.p),
                ac.connect(self.R1.n, self.R3.p, self.R5.p),
                ac.connect(self.R2.n, self.R4.p, self.R5.n),
                ac.connect(self.R3.n, self.R4.n, self.C1.p),
                ac.connect(self.C1.n, self.src.n, self.gnd.p)]


@pytest.fixture(scope="module")
def bridge():
    return ac.compile(Bridge())


def _svg(text):
    start = text.index("<svg")
    return ET.fromstring(text[start:text.index("</svg>", start) + 6])


def _rows(html, heading):
    """The cells of the table after ``<h4>heading``, one list per row."""
    part = html[html.index(f"<h4>{heading}"):]
    part = part[:part.index("</table>")]
    return [[htmllib.unescape(c) for c in re.findall(r"<td[^>]*>(.*?)</td>", row)]
            for row in re.findall(r"<tr>(.*?)</tr>", part, re.S)[1:]]


def test_schematic_follows_the_connections():
    sch = display.diagram(SeriesRLC())
    assert list(sch.boxes) == ["src", "R1", "L1", "C1", "gnd"]
    assert {d for _, d in sch.boxes.values()} == {"electrical"}
    pairs = [tuple(sorted(e[:2])) for e in sch.edges if not e[0].startswith("node")]
    assert pairs == [("R1", "src"), ("L1", "R1"), ("C1", "L1")]
    (node,) = sch.junctions
    assert sorted(b for a, b, *_ in sch.edges if a == node) == ["C1", "gnd", "src"]


def test_schematic_svg_is_valid_and_draws_each_part():
    root = _svg(display.component_svg(SeriesRLC(), engine="networkx"))
    groups = root.findall(f"{SVG}g")
    names = [g.findall(f"{SVG}text")[0].text for g in groups if g.get("class") == "component"]
    assert names == ["src", "R1", "L1", "C1", "gnd"]
    assert len([e for e in root.iter(f"{SVG}line") if e.get("class") == "edge"]) == 6
    colour = DOMAIN_COLOURS["electrical"]
    assert all(e.get("stroke") == colour for e in root.iter(f"{SVG}line"))


def test_schematic_of_a_component_with_own_ports():
    sch = display.diagram(DCMotor())
    assert set(sch.ports) == {"p", "n", "flange"}
    assert sch.ports["flange"] == "rotational" and sch.ports["p"] == "electrical"
    assert ("Ra", "Resistor") == ("Ra", sch.boxes["Ra"][0])
    ends = {frozenset(e[:2]) for e in sch.edges}
    assert frozenset(("p", "Ra")) in ends        # connect(p, Ra.p): the border port
    dot = display.component_dot(DCMotor())
    assert dot.startswith('graph "DCMotor"') and '"p" -- "Ra"' in dot


def test_showing_a_model_does_not_name_it():
    model = SeriesRLC()
    display.component_html(model)
    assert model._path is None and model.R1._path is None
    res = ac.simulate(ac.compile(model), t_end=1e-3)     # still compiles as usual
    assert res.success


def test_schematic_of_a_model_whose_equations_fail_says_so():
    class Broken(SeriesRLC):
        def equations(self):
            raise RuntimeError("typo in the model")

    sch = display.diagram(Broken())
    assert list(sch.boxes) == ["src", "R1", "L1", "C1", "gnd"] and not sch.edges
    assert "typo in the model" in sch.note
    assert "typo in the model" in display.component_svg(sch, engine="networkx")


@pytest.mark.skipif(shutil.which("dot") is not None, reason="Graphviz is installed")
def test_dot_engine_without_graphviz_says_so():
    with pytest.raises(RuntimeError, match="dot"):
        display.component_svg(SeriesRLC(), engine="dot")
    with pytest.raises(ValueError):
        display.component_svg(SeriesRLC(), engine="neato")


def test_component_html_has_schematic_and_parameters():
    html = display.component_html(SeriesRLC(R1={"R": 5.0}))
    assert "<svg" in html
    rows = _rows(html, "Sub-component parameters")
    assert ["R1", "Resistor", "R", "5", "Ohm", "resistance at temperature T_ref"] in rows
    assert ["C1", "Capacitor", "C", "0.0001", "F", "capacitance"] in rows


_IN_A_SHELL = """
import sys, json
from IPython.core.interactiveshell import InteractiveShell
shell = InteractiveShell.instance()
import acausal as ac
from acausal.library.electrical import Ground, Resistor, StepVoltage

class Loop(ac.Component):
    src = StepVoltage(V=1.0)
    R1 = Resistor(R=5.0)
    gnd = Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.R1.p), ac.connect(self.R1.n, self.src.n, self.gnd.p)]

model = Loop()
before = "acausal.display" in sys.modules
data, _ = shell.display_formatter.format(model)
print(json.dumps([before, hasattr(ac.Component, "_repr_html_"), data.get("text/html", "")]))
"""


def test_a_notebook_finds_the_renderer_from_outside_the_language():
    # the language imports no renderer: IPython's HTML formatter has it by class name,
    # registered by `import acausal`, and imports acausal.display when a model is shown
    import json
    import subprocess
    import sys
    pytest.importorskip("IPython")
    out = subprocess.run([sys.executable, "-c", _IN_A_SHELL], capture_output=True,
                         text=True, check=True).stdout
    before, has_repr, html = json.loads(out.strip().splitlines()[-1])
    assert before is False and has_repr is False
    assert "<svg" in html
    assert ["R1", "Resistor", "R", "5", "Ohm", "resistance at temperature T_ref"] in \
        _rows(html, "Sub-component parameters")


def test_report_tables_match_the_report(bridge):
    r = bridge.report
    html = display.report_html(r)
    assert [row[0] for row in _rows(html, "States")] == r.states
    blocks = _rows(html, "BLT blocks")
    assert len(blocks) == len(r.blocks)
    (torn,) = [(row, b) for row, b in zip(blocks, r.blocks) if b.get("torn")]
    row, block = torn
    assert int(row[1]) == block["size"] == 12
    assert row[5] == ", ".join(r._names[v] for v in block["iteration_variables"])
    assert "(torn)" in row[4]
    counts = _rows(html, "Equations and variables")
    assert [c[0] for c in counts] == list(r.counts)


def test_blt_picture_has_one_square_per_incidence_entry(bridge):
    r = bridge.report
    root = _svg(display.blt_svg(r))
    rects = list(root.iter(f"{SVG}rect"))
    eqs, vars_ = r.blt_order()
    expected = sum(1 for e in eqs for v in r._graph[e] if v in set(vars_))
    assert sum(1 for e in rects if e.get("class") == "nz") == expected
    blocks = [e for e in rects if e.get("class") == "block"]
    assert len(blocks) == len(r.blocks)
    assert [e.get("stroke") for e in blocks].count("#d62728") == 1     # the torn block


def test_result_summary_matches_the_arrays(bridge):
    res = ac.simulate(bridge, t_end=0.02, rtol=1e-8)
    html = display.result_html(res)
    rows = _rows(html, "Summary")
    assert [row[0] for row in rows] == list(bridge.states)
    for name, _unit, first, last, lo, hi in rows:
        x = res[name]
        got = np.array([first, last, lo, hi], dtype=float)
        want = np.array([x[0], x[-1], x.min(), x.max()])
        assert np.allclose(got, want, rtol=1e-5, atol=1e-6 * np.max(np.abs(x)))
    png = re.search(r'base64,([^"]+)"', html).group(1)
    assert base64.b64decode(png)[:8] == b"\x89PNG\r\n\x1a\n"
    assert display.result_png(res)[:4] == b"\x89PNG"


def test_poles_table_of_a_second_order_system():
    wn, zeta = 30.0, 0.2
    ss = ac.StateSpace.from_tf([wn**2], [1.0, 2 * zeta * wn, wn**2])
    html = display.statespace_html(ss)
    rows = np.array(_rows(html, "Poles"), dtype=float)
    assert rows.shape == (2, 4)
    assert np.allclose(rows[:, 0], -zeta * wn, rtol=1e-5)
    assert np.allclose(sorted(rows[:, 1]), [-wn * np.sqrt(1 - zeta**2),
                                            wn * np.sqrt(1 - zeta**2)], rtol=1e-5)
    assert np.allclose(rows[:, 2], wn, rtol=1e-5) and np.allclose(rows[:, 3], zeta, rtol=1e-5)
    assert "stable" in html and "data:image/png" in html
    assert display.bode_png(ss)[:4] == b"\x89PNG"


def test_show_dispatches_and_rejects_other_objects(bridge):
    assert "Index report" in display.show(bridge.report)._repr_html_()
    assert "Compiled model" in display.show(bridge)._repr_html_()
    assert "<svg" in display.show(SeriesRLC())._repr_html_()
    with pytest.raises(TypeError, match="show"):
        display.show(42)


def test_model_html_lists_states_with_units_and_parameters(bridge):
    html = display.model_html(bridge)
    states = _rows(html, "States")
    assert [row[0] for row in states] == list(bridge.states)
    units = display.units_of(bridge)
    assert [row[1] for row in states] == [units.get(s, "") for s in bridge.states]
    params = dict((row[0], float(row[1])) for row in _rows(html, "Parameters"))
    assert params == pytest.approx(dict(zip(bridge.param_names, bridge.p.tolist())),
                                   rel=1e-5)
