"""Top-level inputs: a model compiled with its undriven input ports, driven by
``simulate(..., inputs=...)`` from a number, a function, a table and a sweep, each
against the closed form of a first-order lag; the same names in linearize, steady_state,
the command line and an FMU; the errors that name a missing, unknown or differentiated
input."""
import math

import numpy as np
import pytest

import acausal as ac
from acausal.library.blocks import CombiTimeTable, Integrator
from acausal.library.translational import Mass, Position
from acausal.ports import BooleanInput, RealInput, RealOutput

T = 0.5


class Lag(ac.Component):
    """T x' = u - x, y = 2 x, x(0) = 0; a Boolean input ``on`` gates u."""

    u = RealInput()
    y = RealOutput()
    T = ac.Parameter(T, unit="s", description="time constant")
    x = ac.Variable(start=0.0, fixed=True)

    def equations(self):
        return [ac.Eq(self.T * ac.der(self.x), self.u - self.x), ac.Eq(self.y, 2 * self.x)]


def _lag_of_sine(t, w=2.0):
    """x for u = sin(w t): the steady sine plus the decaying transient."""
    a = 1.0 / (1.0 + (w * T) ** 2)
    return a * (np.sin(w * t) - w * T * np.cos(w * t)) + a * w * T * np.exp(-t / T)


@pytest.fixture(scope="module")
def lag():
    return ac.compile(Lag())


def test_the_model_compiles_with_its_input_and_names_it(lag):
    assert lag.input_names == ["u"]
    with pytest.raises(ac.MissingInput, match=r"the model's input 'u' is not driven"):
        ac.simulate(lag, t_end=1.0)
    with pytest.raises(ac.NotInModel, match=r"no input 'uu' \(did you mean 'u'\?\)"):
        ac.simulate(lag, t_end=1.0, inputs={"u": 1.0, "uu": 2.0})


def test_a_constant_input(lag):
    t = np.linspace(0.0, 2.0, 21)
    res = ac.simulate(lag, t_end=2.0, t_eval=t, rtol=1e-10, inputs={"u": 1.5})
    assert np.max(np.abs(res["y"] - 3.0 * (1 - np.exp(-t / T)))) < 1e-8
    assert np.allclose(res["u"], 1.5)


def test_an_input_driven_by_a_function(lag):
    t = np.linspace(0.0, 3.0, 61)
    res = ac.simulate(lag, t_end=3.0, t_eval=t, rtol=1e-10,
                      inputs={"u": lambda s: math.sin(2.0 * s)})
    assert np.max(np.abs(res["x"] - _lag_of_sine(t))) < 1e-8
    assert np.max(np.abs(res["u"] - np.sin(2.0 * t))) < 1e-14


def test_an_input_driven_by_a_table_lands_on_its_breakpoints(lag):
    # a ramp 0 -> 1 over [0.5, 1.5], then held: x from the convolution of the ramp
    times, values = np.array([0.0, 0.5, 1.5, 3.0]), np.array([0.0, 0.0, 1.0, 1.0])
    t = np.linspace(0.0, 3.0, 61)
    res = ac.simulate(lag, t_end=3.0, t_eval=t, rtol=1e-10, inputs={"u": (times, values)})

    def ramp_response(s):        # response to the unit ramp (s)_+ starting at 0
        s = np.maximum(s, 0.0)
        return s - T * (1 - np.exp(-s / T))
    exact = ramp_response(t - 0.5) - ramp_response(t - 1.5)
    assert np.max(np.abs(res["x"] - exact)) < 1e-8
    # the same table as a CombiTimeTable
    table = CombiTimeTable(table=np.column_stack([times, values]))
    again = ac.simulate(lag, t_end=3.0, t_eval=t, rtol=1e-10, inputs={"u": table})
    assert np.max(np.abs(again["x"] - exact)) < 1e-8


def test_a_sweep_over_an_input(lag):
    pytest.importorskip("xarray")
    t = np.linspace(0.0, 2.0, 11)
    ds = ac.sweep(lag, {"u": [1.0, 2.0, -0.5]}, t_end=2.0, t_eval=t, rtol=1e-10)
    assert list(ds["u"].values) == [1.0, 2.0, -0.5] and bool(ds["success"].all())
    for k, u in enumerate([1.0, 2.0, -0.5]):
        assert np.max(np.abs(ds["y.signal"].values[k] - 2 * u * (1 - np.exp(-t / T)))) < 1e-8
    # an ensemble drives it by functions, and by a parameter swept with it
    runs = [{"u": lambda s: math.sin(2.0 * s)}, {"u": 1.0, "T": 0.25}]
    ds = ac.ensemble(lag, runs, t_end=2.0, t_eval=t, rtol=1e-10)
    assert np.max(np.abs(ds["x"].values[0] - _lag_of_sine(t))) < 1e-8
    assert np.max(np.abs(ds["x"].values[1] - (1 - np.exp(-t / 0.25)))) < 1e-8


def test_linearize_and_steady_state_take_the_input_by_its_name(lag):
    ss = ac.linearize(lag, inputs=["u"], outputs=["y"])
    assert np.allclose(ss.A, [[-1 / T]]) and np.allclose(ss.B, [[1 / T]])
    assert np.allclose(ss.C, [[2.0]]) and np.allclose(ss.D, [[0.0]])
    # the same as the harness of a Component's input gives
    harness = ac.linearize(Lag(), inputs=["u"], outputs=["y"])
    assert np.allclose(harness.A, ss.A) and np.allclose(harness.B, ss.B)
    op = ac.steady_state(lag, inputs={"u": 0.8})
    assert abs(op["x"] - 0.8) < 1e-10 and abs(op["y"] - 1.6) < 1e-10
    assert op.inputs == {"u": pytest.approx(0.8)}


class Gated(ac.Component):
    """der(x) = on ? 1 : 0, with the Boolean input ``on``."""

    on = BooleanInput()
    x = ac.Variable(start=0.0, fixed=True)

    def equations(self):
        return [ac.Eq(ac.der(self.x), ac.if_else(self.on, 1.0, 0.0))]


def test_a_boolean_input_from_a_table_switches_at_its_times():
    t = np.linspace(0.0, 3.0, 31)
    table = (np.array([0.0, 1.0, 1.0, 2.0, 2.0]), np.array([0, 0, 1, 1, 0]))
    res = ac.simulate(Gated(), t_end=3.0, t_eval=t, rtol=1e-10, inputs={"on": table})
    assert np.max(np.abs(res["x"] - np.clip(t - 1.0, 0.0, 1.0))) < 1e-9
    assert res["on"].dtype == bool
    with pytest.raises(ac.InvalidValue, match="not a Boolean"):
        ac.simulate(Gated(), t_end=1.0, inputs={"on": 0.5})


class Pushed(ac.Component):
    """A mass whose position is the input: index reduction needs der(u)."""

    u = RealInput()
    position = Position()
    mass = Mass(m=1.0)

    def equations(self):
        return [ac.connect(self.u, self.position.s_ref),
                ac.connect(self.position.flange, self.mass.flange_a)]


def test_an_input_that_index_reduction_would_differentiate_is_refused():
    with pytest.raises(ac.ModelError, match=r"input 'u' appears in an equation that index "
                                            r"reduction must differentiate"):
        ac.compile(Pushed())


class Driven(ac.Component):
    """Its input is driven inside the model: no top-level input."""

    u = RealInput()
    i = Integrator()

    def equations(self):
        return [ac.Eq(self.u, 2.0), ac.connect(self.u, self.i.u)]


def test_an_input_the_model_drives_itself_is_no_input():
    compiled = ac.compile(Driven())
    assert compiled.input_names == []
    res = ac.simulate(compiled, t_end=1.0, n_points=3)
    assert abs(res["i.y"][-1] - 2.0) < 1e-8


def test_the_command_line_drives_an_input_from_a_csv_file(tmp_path, capsys):
    from acausal.cli import main
    script = tmp_path / "lag.py"
    script.write_text("import acausal as ac\nfrom acausal.tests.models.test_top_level_inputs "
                      "import Lag\nclass Model(Lag):\n    stop_time = 2.0\n")
    data = tmp_path / "u.csv"
    data.write_text("time,u\n0,1.5\n10,1.5\n")
    out = tmp_path / "out.csv"
    assert main(["run", f"{script}:Model", "--input", f"u={data}", "--csv", str(out),
                 "--rtol", "1e-9"]) == 0
    import csv
    rows = list(csv.DictReader(open(out)))
    assert abs(float(rows[-1]["y.signal"]) - 3.0 * (1 - math.exp(-2.0 / T))) < 1e-6
    assert main(["run", f"{script}:Model", "--input", "u=1.5"]) == 0
    assert main(["run", f"{script}:Model"]) == 1          # the input is not driven
    assert "'u' is not driven" in capsys.readouterr().err


def test_a_compiled_model_with_its_input_exports_an_fmu_whose_input_is_set(lag, tmp_path):
    fmpy = pytest.importorskip("fmpy")
    from acausal.compiler.backends.cbackend import compiler_available
    if compiler_available() is None:
        pytest.skip("no C compiler")
    from fmpy.validation import validate_fmu
    path = ac.export_fmu(ac.compile(Lag(), backend="numpy"), tmp_path / "lag.fmu",
                         "CoSimulation", t_end=2.0)
    assert validate_fmu(path) == []
    res = fmpy.simulate_fmu(path, stop_time=2.0, output_interval=0.05, output=["y.signal"],
                            start_values={"u": 1.5}, relative_tolerance=1e-8)
    t = res["time"]
    assert np.max(np.abs(res["y.signal"] - 3.0 * (1 - np.exp(-t / T)))) < 1e-5
