"""The command line (acausal.cli): run, report, fmu, list, and its errors.

The numbers a command prints are checked against the library call it stands for
(``ac.simulate`` / ``Result.to_csv`` / ``compiled.report`` of the same model), and a
script's RC circuit against its closed form v_C = V (1 - exp(-t / (R C))).
"""
from __future__ import annotations

import importlib
import importlib.util
import json
import os
import re
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import acausal as ac
from acausal.cli import load_model, main
from acausal.library.examples.motor_drive import MotorDrive

SHOWCASE = "acausal.library.examples.motor_drive"
T_END = 0.4            # past the 0.1 s voltage step and several shaft oscillations
RTOL = 1e-8

RC_SCRIPT = textwrap.dedent('''
    """A 2 V step on R = 1 kOhm and C = 100 uF in series (tau = 0.1 s)."""
    import acausal as ac
    from acausal.library.electrical import Capacitor, ConstantVoltage, Ground, Resistor

    LOADED_AS = __name__


    class RCCharge(ac.Component):
        src = ConstantVoltage(V=2.0)
        R1 = Resistor(R=1e3)
        C1 = Capacitor(C=1e-4)
        gnd = Ground()

        def equations(self):
            return [ac.connect(self.src.p, self.R1.p), ac.connect(self.R1.n, self.C1.p),
                    ac.connect(self.C1.n, self.src.n, self.gnd.p)]


    if __name__ == "__main__":
        raise SystemExit("a script loaded by the command line must not run as __main__")
''')


def final_values(out: str) -> dict:
    """{name: value} from the 'final values at t = ...' block of ``acausal run``."""
    lines = out.splitlines()
    start = next(k for k, line in enumerate(lines) if line.startswith("final values at t ="))
    values = {}
    for line in lines[start + 1:]:
        if not line.startswith("  "):
            break
        name, value = line.split()
        values[name] = float(value)
    return values


def run_cli(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def assert_close(printed: dict, res, names):
    """Printed with 12 significant digits: equal to the library's result to ~1e-11 of each
    signal's own size over the run."""
    for n in names:
        scale = np.max(np.abs(res[n]))
        assert abs(printed[n] - res[n][-1]) <= 1e-10 * scale, (n, printed[n], res[n][-1])


@pytest.fixture(scope="module")
def reference():
    compiled = ac.compile(MotorDrive(), backend="numpy")
    return compiled, ac.simulate(compiled, t_end=T_END, rtol=RTOL)


@pytest.fixture
def rc_script(tmp_path):
    path = tmp_path / "rc_charge.py"
    path.write_text(RC_SCRIPT)
    return path


# -- run ---------------------------------------------------------------------------------
def test_run_prints_the_final_values_of_the_states(capsys, reference):
    compiled, res = reference
    code, out, err = run_cli(capsys, "run", SHOWCASE, "--t-end", str(T_END), "--rtol",
                             str(RTOL), "--backend", "numpy")
    assert code == 0, err
    printed = final_values(out)
    assert list(printed) == compiled.states
    assert_close(printed, res, compiled.states)
    assert "success" in out and re.search(r"\bsteps [1-9]\d*,", out)
    assert "events 1 (at 0.1)" in out          # the voltage step, a time event


def test_run_print_csv_and_plot(capsys, reference, tmp_path):
    _, res_default = reference
    csv_cli, png = tmp_path / "cli.csv", tmp_path / "speeds.png"
    code, out, err = run_cli(capsys, "run", SHOWCASE, "--t-end", str(T_END), "--rtol",
                             str(RTOL), "--backend", "numpy", "--n-points", "41",
                             "--csv", str(csv_cli), "--plot", str(png), "load.w",
                             "motor.rotor.w", "--print", "load.w", "shaft.tau")
    assert code == 0, err
    printed = final_values(out)
    assert list(printed) == ["load.w", "shaft.tau"]
    res = ac.simulate(ac.compile(MotorDrive(), backend="numpy"), t_end=T_END, rtol=RTOL,
                      n_points=41)
    assert_close(printed, res, ["load.w", "shaft.tau"])
    csv_api = tmp_path / "api.csv"
    res.to_csv(csv_api)
    with open(csv_cli) as a, open(csv_api) as b:
        assert a.readline() == b.readline()        # the same columns, in the same order
    x, y = np.loadtxt(csv_cli, delimiter=",", skiprows=1), \
        np.loadtxt(csv_api, delimiter=",", skiprows=1)
    assert x.shape == y.shape == (41, len(res.names) + 1)
    scale = np.max(np.abs(y), axis=0) + 1e-300
    assert np.all(np.abs(x - y) <= 1e-9 * scale)
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_set_changes_the_result_as_parameters_does(capsys, reference):
    compiled, res_default = reference
    code, out, err = run_cli(capsys, "run", SHOWCASE, "--t-end", str(T_END), "--rtol",
                             str(RTOL), "--backend", "numpy", "--set", "motor.R=2.5",
                             "load.J=0.02", "--print", "load.w", "motor.La.i")
    assert code == 0, err
    assert "set motor.R = 2.5 (default 1)" in out
    printed = final_values(out)
    res = ac.simulate(ac.compile(MotorDrive(), backend="numpy"), t_end=T_END, rtol=RTOL,
                      parameters={"motor.R": 2.5, "load.J": 0.02})
    assert_close(printed, res, ["load.w", "motor.La.i"])
    # and the change is one the result can see: far beyond the printed precision
    assert abs(printed["load.w"] - res_default["load.w"][-1]) > 1e-3 * abs(res["load.w"][-1])


def test_script_file_rc_charge_against_its_closed_form(capsys, rc_script):
    # tau = R C = 0.1 s; v_C(0.3) = 2 (1 - exp(-3))
    for spec in (str(rc_script), f"{rc_script}:RCCharge"):
        code, out, err = run_cli(capsys, "run", spec, "--t-end", "0.3", "--rtol", "1e-9",
                                 "--backend", "numpy", "--print", "C1.v")
        assert code == 0, err
        exact = 2.0 * (1.0 - np.exp(-3.0))
        assert abs(final_values(out)["C1.v"] - exact) <= 1e-6 * exact
    # loaded as a module, not as __main__ (whose block would have raised SystemExit)
    model, module = load_model(str(rc_script))
    assert type(model).__name__ == "RCCharge"
    assert module.LOADED_AS == module.__name__ != "__main__"


TANK_SCRIPT = textwrap.dedent('''
    import acausal as ac


    class Tank(ac.Component):
        """Torricelli draining with a leak: der(h) = -sqrt(h) - 0.1, h(0) = 1."""
        h = ac.Variable(start=1.0, fixed=True)

        def equations(self):
            return [ac.Eq(ac.der(self.h), -ac.sqrt(self.h) - 0.1)]
''')


def test_a_failed_run_prints_what_it_computed_and_exits_1(capsys, tmp_path):
    # the tank is empty at t* = int_0^1 dh / (sqrt(h) + 0.1) = 2 (1 - 0.1 ln 11), and
    # der(h) = -sqrt(h) - 0.1 has no real solution after it
    script, csv = tmp_path / "tank.py", tmp_path / "tank.csv"
    script.write_text(TANK_SCRIPT)
    code, out, err = run_cli(capsys, "run", str(script), "--t-end", "5", "--backend",
                             "numpy", "--csv", str(csv))
    assert code == 1 and "Traceback" not in err
    assert "FAILED" in out and "last values at t = " in out
    assert err.startswith("acausal run: error: the simulation stopped at t = ")
    t_empty = 2.0 * (1.0 - 0.1 * np.log(11.0))
    data = np.loadtxt(csv, delimiter=",", skiprows=1)       # the partial result is kept
    column = dict(zip(csv.read_text().splitlines()[0].split(","), data.T))
    assert abs(column["time"][-1] - t_empty) <= 1e-3 * t_empty
    assert np.all(column["h"] >= -1e-6) and column["h"][-1] <= 1e-3


def test_subprocess_python_m_acausal_run(reference):
    compiled, res = reference
    proc = subprocess.run(
        [sys.executable, "-m", "acausal", "run", SHOWCASE, "--t-end", str(T_END), "--rtol",
         str(RTOL), "--backend", "numpy", "--print", "load.w", "shaft.phi_rel"],
        capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert_close(final_values(proc.stdout), res, ["load.w", "shaft.phi_rel"])


# -- report --------------------------------------------------------------------------------
def test_report_json_names_the_states_the_report_names(capsys, reference, tmp_path):
    compiled, _ = reference
    dot = tmp_path / "blt.dot"
    code, out, err = run_cli(capsys, "report", SHOWCASE, "--json", "--dot", str(dot),
                             "--backend", "numpy")
    assert code == 0, err
    data = json.loads(out)
    report = compiled.report
    assert data["model"] == "MotorDrive"
    assert data["states"] == report.states
    assert data["dummy_derivatives"] == report.dummy_derivatives == ["der(motor.emf.flange.phi)"]
    assert data["differential_index"] == report.differential_index == 2
    # the blocks in names: every state-free unknown is solved by exactly one block
    texts = {e["text"] for e in report.equations}
    assert len(data["blocks"]) == len(report.blocks)
    for block in data["blocks"]:
        assert all(isinstance(v, str) for v in block["variables"])
        assert set(block["equations"]) <= texts
    solved = [v for b in data["blocks"] for v in b["variables"]]
    assert len(solved) == len(set(solved)) and "motor.Ra.v" in solved
    text = dot.read_text()
    assert text.startswith('digraph "MotorDrive"')
    assert text.count("[label=") == len(report.blocks)


BRIDGE_SCRIPT = textwrap.dedent('''
    import acausal as ac
    from acausal.library.electrical import Ground, Inductor, Resistor, StepVoltage


    class Bridge(ac.Component):
        """A 1 V step through L1 into the Wheatstone bridge R1..R5: one algebraic loop."""
        src = StepVoltage(V=1.0)
        L1 = Inductor(L=1e-3)
        R1, R2, R3, R4, R5 = (Resistor(R=1.0), Resistor(R=2.0), Resistor(R=3.0),
                              Resistor(R=4.0), Resistor(R=5.0))
        gnd = Ground()

        def equations(self):
            return [ac.connect(self.src.p, self.L1.p),
                    ac.connect(self.L1.n, self.R1.p, self.R2.p),
                    ac.connect(self.R1.n, self.R3.p, self.R5.p),
                    ac.connect(self.R2.n, self.R4.p, self.R5.n),
                    ac.connect(self.R3.n, self.R4.n, self.src.n, self.gnd.p)]
''')


def test_bridge_torn_block_in_json_and_its_steady_current(capsys, tmp_path):
    script = tmp_path / "bridge.py"
    script.write_text(BRIDGE_SCRIPT)
    code, out, err = run_cli(capsys, "report", str(script), "--json", "--backend", "numpy")
    assert code == 0, err
    torn = [b for b in json.loads(out)["blocks"] if b["torn"]]
    assert len(torn) == 1
    loop = torn[0]
    assert {f"R{k}.i" for k in range(1, 6)} <= set(loop["variables"])   # one loop, by name
    assert set(loop["iteration_variables"]) < set(loop["variables"])
    # 50 time constants L / R_eq after the step, i_L = V / R_eq, R_eq by nodal analysis
    # of nodes a (R1, R2), b (R1, R3, R5), c (R2, R4, R5) with a held at 1 V
    g = {k: 1.0 / r for k, r in zip((1, 2, 3, 4, 5), (1.0, 2.0, 3.0, 4.0, 5.0))}
    A = np.array([[g[1] + g[3] + g[5], -g[5]], [-g[5], g[2] + g[4] + g[5]]])
    vb, vc = np.linalg.solve(A, [g[1], g[2]])
    i_exact = g[1] * (1.0 - vb) + g[2] * (1.0 - vc)
    code, out, err = run_cli(capsys, "run", str(script), "--t-end", "0.05", "--backend",
                             "numpy", "--rtol", "1e-9", "--print", "L1.i")
    assert code == 0, err
    assert abs(final_values(out)["L1.i"] - i_exact) <= 1e-6 * i_exact


def test_report_text_is_the_index_report(capsys, reference):
    compiled, _ = reference
    code, out, err = run_cli(capsys, "report", SHOWCASE, "--backend", "numpy")
    assert code == 0, err
    assert out.startswith("Index report for MotorDrive")
    assert "states: " + ", ".join(compiled.report.states) in out


# -- fmu ----------------------------------------------------------------------------------
def test_fmu_export_from_the_command_line(capsys, tmp_path):
    if importlib.util.find_spec("fmpy") is None:
        pytest.skip("fmpy (the fmi extra) is not installed")
    try:
        importlib.import_module("acausal.fmi").export_fmu
    except (ImportError, AttributeError):
        pytest.skip("acausal.fmi.export_fmu is not available yet")
    import fmpy
    from fmpy.validation import validate_fmu
    for kind, fmi_type in (("me", "ModelExchange"), ("cs", "CoSimulation")):
        path = tmp_path / f"motor_{kind}.fmu"
        code, out, err = run_cli(capsys, "fmu", SHOWCASE, "-o", str(path), "--type", kind)
        assert code == 0, err
        assert fmi_type in out and path.is_file()
        assert validate_fmu(str(path)) == []
        desc = fmpy.read_model_description(str(path))
        names = {v.name for v in desc.modelVariables}
        assert {"load.w", "motor.R"} <= names
        assert (desc.modelExchange if kind == "me" else desc.coSimulation) is not None
    # the exported Model Exchange FMU, run by fmpy in a process that never imports acausal
    probe = textwrap.dedent(f'''
        import sys, fmpy
        r = fmpy.simulate_fmu({str(tmp_path / "motor_me.fmu")!r}, stop_time={T_END},
                              relative_tolerance=1e-10, output=["load.w"])
        assert "acausal" not in sys.modules
        print(repr(float(r["time"][-1])), repr(float(r["load.w"][-1])))
    ''')
    proc = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True,
                          timeout=120, cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    t_last, w_last = map(float, proc.stdout.split())
    res = ac.simulate(MotorDrive(), t_end=T_END, rtol=RTOL, backend="numpy")
    assert abs(t_last - T_END) <= 1e-9 * T_END
    assert abs(w_last - res["load.w"][-1]) <= 1e-5 * np.max(np.abs(res["load.w"]))


# -- list ---------------------------------------------------------------------------------
def test_list_names_every_domain_and_its_components(capsys):
    code, out, err = run_cli(capsys, "list")
    assert code == 0, err
    for domain in ("electrical", "rotational", "translational", "hydraulics", "thermal",
                   "blocks", "multibody", "friction", "electromechanical"):
        assert f"\n{domain}: " in "\n" + out
    assert "  Resistor " in out and "examples:" not in out


def test_list_domain_json_ports_and_parameters(capsys):
    from acausal.library.electrical import HeatingResistor, Resistor
    code, out, err = run_cli(capsys, "list", "electrical", "--json")
    assert code == 0, err
    comps = json.loads(out)["electrical"]["components"]
    r = comps["Resistor"]
    assert [(p["name"], p["type"], p["domain"]) for p in r["ports"]] == \
        [("p", type(Resistor.p).__name__, "electrical"),
         ("n", type(Resistor.n).__name__, "electrical")]
    by_name = {p["name"]: p for p in r["parameters"]}
    assert by_name["R"] == {"name": "R", "default": Resistor.R.value, "unit": Resistor.R.unit,
                            "description": Resistor.R.description}
    # its own parameters and those of the heat port it may have (useHeatPort, T)
    assert set(by_name) == {"useHeatPort", "T", "R", "T_ref", "alpha"}
    assert ("heatPort", "thermal") in {(p["name"], p["domain"])
                                       for p in comps["HeatingResistor"]["ports"]}
    assert [p["name"] for p in comps["HeatingResistor"]["parameters"]] == \
        [n for n, v in vars(HeatingResistor).items() if isinstance(v, ac.Parameter)]
    assert "Pin" not in comps                  # ports are not components
    code, out, err = run_cli(capsys, "list", "electrical")
    assert "R = 1 [Ohm]  resistance" in out


# -- errors ----------------------------------------------------------------------------------
@pytest.mark.parametrize("argv, status, words", [
    (["run", SHOWCASE, "--t-end", "0.1", "--backend", "numpy", "--set", "motor.Rx=2"], 1,
     ["NotInModel", "motor.Rx"]),
    (["run", SHOWCASE, "--t-end", "0.1", "--set", "motor.R=two"], 2, ["'two' is not a number"]),
    (["run", SHOWCASE, "--t-end", "0.1", "--set", "motor.R"], 2, ["NAME=VALUE"]),
    (["run", SHOWCASE, "--t-end", "0.1", "--backend", "numpy", "--print", "load.x"], 1,
     ["no variable 'load.x'"]),
    (["run", "no/such/model.py", "--t-end", "1"], 2, ["does not exist"]),
    (["run", "acausal.library.no_such_module", "--t-end", "1"], 2, ["no module named"]),
    (["run", "acausal.library.examples.pendulum", "--t-end", "1"], 2,
     ["Pendulum", "DoublePendulum", "MODEL"]),
    (["run", f"{SHOWCASE}:Nope", "--t-end", "1"], 2, ["no 'Nope'", "MotorDrive"]),
    (["run", f"{SHOWCASE}:main", "--t-end", "1"], 2, ["not a model"]),
    (["run", SHOWCASE], 2, ["--t-end", "stop_time"]),
    (["run", SHOWCASE, "--t-end", "-1"], 2, ["InvalidArgument", "t_end = -1.0 must be after"]),
    (["run", SHOWCASE, "--t-end", "1", "--rtol", "-1e-6"], 2,
     ["InvalidArgument", "rtol", "(0, 1)", "-1e-06"]),
    (["run", SHOWCASE, "--t-end", "1", "--rtol", "5"], 2, ["InvalidArgument", "rtol"]),
    (["run", SHOWCASE, "--t-end", "1", "--atol", "0"], 2, ["InvalidArgument", "atol", "> 0"]),
    (["run", SHOWCASE, "--t-end", "1", "--atol", "-1E-3"], 2, ["InvalidArgument", "atol"]),
    (["run", SHOWCASE, "--t-end", "1", "--n-points", "-3"], 2, ["InvalidArgument", "n_points"]),
    (["run", SHOWCASE, "--t-end", "1", "--n-points", "2.5"], 2, ["not a whole number"]),
    (["run", "--print", "load.w", SHOWCASE, "--t-end", "1"], 2, ["SCRIPT[:MODEL] is missing"]),
    (["run", SHOWCASE, "--t-end", "1", "--csv", "/no/such/dir/out.csv"], 2,
     ["does not exist"]),
    (["list", "plumbing"], 2, ["no library domain", "electrical"]),
    (["simulate", SHOWCASE], 2, ["invalid choice"]),
])
def test_bad_input_one_line_no_traceback(capsys, argv, status, words):
    code, out, err = run_cli(capsys, *argv)
    assert code == status, err
    assert "Traceback" not in err
    assert all(w in err for w in words), err


def test_model_error_of_a_script_and_debug(capsys, tmp_path):
    bad = tmp_path / "open_circuit.py"
    bad.write_text(RC_SCRIPT.replace("ac.connect(self.C1.n, self.src.n, self.gnd.p)",
                                     "ac.connect(self.C1.n, self.src.n)"))
    code, out, err = run_cli(capsys, "run", str(bad), "--t-end", "1", "--backend", "numpy")
    assert code == 1 and "Traceback" not in err
    first = err.splitlines()[0]
    assert first.startswith("acausal run: error: ") and "Model" in first
    code, out, err = run_cli(capsys, "run", str(bad), "--t-end", "1", "--backend", "numpy",
                             "--debug")
    assert code == 1 and "Traceback" in err
    raising = tmp_path / "raising.py"
    raising.write_text("raise RuntimeError('the script itself fails')\n")
    code, out, err = run_cli(capsys, "report", str(raising))
    assert code == 1 and "the script itself fails" in err and "Traceback" not in err


@pytest.mark.parametrize("command", [[], ["run"], ["report"], ["fmu"], ["list"]])
def test_help_everywhere(capsys, command):
    code, out, _ = run_cli(capsys, *command, "--help")
    assert code == 0 and out.startswith("usage: acausal")


def test_version(capsys):
    code, out, _ = run_cli(capsys, "--version")
    assert code == 0 and out.startswith("acausal ")
    script = os.path.join(os.path.dirname(sys.executable), "acausal")
    if os.path.exists(script):                 # the console script of pyproject.toml
        proc = subprocess.run([script, "--version"], capture_output=True, text=True,
                              timeout=60)
        assert proc.returncode == 0 and proc.stdout == out


WRONG_UNITS_SCRIPT = '''
import acausal as ac
from acausal.library import rotational as rot


class WrongSpring(rot.PartialCompliant):
    c = ac.Parameter(10.0, unit="N.m/rad", min=0)

    def equations(self):
        return [ac.Eq(self.tau, self.c * ac.der(self.phi_rel))]


class Oscillator(ac.Component):
    stop_time = 0.1
    housing = rot.Fixed()
    spring = WrongSpring()
    mass = rot.Inertia(J=0.1, phi={"start": 0.1, "fixed": True})

    def equations(self):
        return [ac.connect(self.housing.flange, self.spring.flange_a),
                ac.connect(self.spring.flange_b, self.mass.flange_a)]
'''


def test_check_units_error_refuses_a_model_whose_units_differ(capsys, tmp_path):
    path = tmp_path / "wrong_units.py"
    path.write_text(WRONG_UNITS_SCRIPT)
    code, out, err = run_cli(capsys, "run", f"{path}:Oscillator", "--check-units", "error",
                             "--backend", "numpy")
    assert code == 1 and "UnitError" in err and "spring.tau" in err
    code, out, err = run_cli(capsys, "report", f"{path}:Oscillator", "--check-units", "off",
                             "--backend", "numpy")
    assert code == 0, err


UNDERDETERMINED = """
import acausal as ac


class Loose(ac.Component):
    x = ac.Variable(start=1.0)
    y = ac.Variable()

    def equations(self):
        return [ac.Eq(ac.der(self.x), -self.x + self.y)]
"""


def test_a_structural_error_reaches_the_command_line_as_itself(capsys, tmp_path):
    script = tmp_path / "loose.py"
    script.write_text(UNDERDETERMINED)
    code, out, err = run_cli(capsys, "run", str(script), "--t-end", "1")
    assert code == 1
    assert "UnderdeterminedModel: under-determined" in err
    assert "unexpected" not in err and "Traceback" not in err
