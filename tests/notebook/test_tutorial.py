"""The tutorial notebook (docs/tutorial.ipynb) runs from top to bottom and shows what it
says it shows: the schematic, the index report's states, a result and a linearization.

The kernel is this interpreter: a kernelspec for it is written into a temporary
JUPYTER_PATH, so the test needs no user-level kernel installation (a fresh venv in CI).
"""
import json
import pathlib
import re
import sys

import pytest

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")
pytest.importorskip("ipykernel")

NOTEBOOK = pathlib.Path(__file__).resolve().parents[2] / "docs" / "tutorial.ipynb"
KERNEL = "acausal-tutorial-test"


@pytest.fixture(scope="module")
def executed(tmp_path_factory):
    where = tmp_path_factory.mktemp("jupyter")
    spec = where / "kernels" / KERNEL
    spec.mkdir(parents=True)
    (spec / "kernel.json").write_text(json.dumps({
        "argv": [sys.executable, "-m", "ipykernel_launcher", "-f", "{connection_file}"],
        "display_name": "acausal test kernel", "language": "python"}))
    mp = pytest.MonkeyPatch()
    mp.setenv("JUPYTER_PATH", str(where))
    mp.delenv("MPLBACKEND", raising=False)     # the kernel's inline backend draws the plots
    try:
        nb = nbformat.read(NOTEBOOK, as_version=4)
        client = nbclient.NotebookClient(nb, kernel_name=KERNEL, timeout=120,
                                         resources={"metadata": {"path": str(where)}})
        client.execute()        # raises CellExecutionError on the first failing cell
    finally:
        mp.undo()
    return nb


def _outputs(cell, mime):
    return [o.get("data", {}).get(mime, "") for o in cell.get("outputs", [])
            if o.get("output_type") in ("execute_result", "display_data")]


def _cell(nb, text):
    """The code cell whose source contains ``text`` (one, or the test is wrong)."""
    found = [c for c in nb.cells if c.cell_type == "code" and text in c.source]
    assert len(found) == 1, text
    return found[0]


def _html(nb, text) -> str:
    html = "".join(_outputs(_cell(nb, text), "text/html"))
    assert html, f"no HTML output from the cell with {text!r}"
    return html


def test_no_cell_raised(executed):
    for cell in executed.cells:
        for out in cell.get("outputs", []):
            assert out.get("output_type") != "error", cell.source


def test_signature_cell_shows_units(executed):
    stream = "".join(o.get("text", "") for o in _cell(executed, "inspect.signature").outputs
                     if o.get("output_type") == "stream")
    assert "R: float [Ohm] = 1.0" in stream
    assert "R=2.0 Ohm" in "".join(_outputs(_cell(executed, "inspect.signature"), "text/plain"))


def test_schematic_shows_every_component(executed):
    html = _html(executed, "drive     #")
    svg = html[html.index("<svg"):html.index("</svg>")]
    boxes = re.findall(r'<g class="component">.*?font-weight="bold">([^<]+)</text>', svg)
    assert boxes == ["source", "ground", "motor", "shaft", "load", "bearing", "housing"]
    # six connects: five of two ports (edges) and one node of three (a junction, 3 edges)
    assert svg.count('class="edge"') == 8 and svg.count('class="junction"') == 1


def test_report_names_the_states_and_the_differentiated_constraint(executed):
    html = _html(executed, "compiled.report")
    states = ["motor.La.i", "motor.rotor.w", "shaft.phi_rel", "load.phi", "load.w"]
    table = html[html.index("<h4>States</h4>"):html.index("<h4>Dummy derivatives")]
    assert re.findall(r"<td>([^<]+)</td>", table) == states
    assert "Differentiated equations (Pantelides)" in html and "shaft.phi_rel =" in html
    assert "der(motor.emf.flange.phi)" in html and 'class="acausal-blt"' in html
    assert "Differential index: <b>2</b>" in html


def test_result_and_plot_are_shown(executed):
    html = _html(executed, "n_points=801)\nres")
    assert "Summary" in html and "<td>load.w</td>" in html and "data:image/png" in html
    assert any(_outputs(_cell(executed, "res.plot("), "image/png"))


def test_simulated_steady_state_matches_the_closed_form(executed):
    stream = "".join(o.get("text", "") for o in _cell(executed, "w_ss =").outputs)
    got, expected = map(float, re.findall(r"(-?\d+\.\d+) rad/s", stream))
    # the slowest pole is near -1.24/s: after 7.9 s the transient is below 1e-4
    assert abs(got - expected) < 1e-3 * expected


def test_linearization_shows_poles_and_bode(executed):
    html = _html(executed, "ac.linearize(")
    assert "Poles" in html and "5 states" in html and "data:image/png" in html
