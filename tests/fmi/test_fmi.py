"""FMI 2.0 export checked by a real importer (fmpy): validation, agreement with
acausal's own simulation (Model Exchange to 1e-6 of each signal's size with both at
tight tolerances; Co-Simulation to the accuracy its embedded integrator is asked for),
parameters and inputs set through FMI, the ModelStructure against the linearization,
and an FMU run in a fresh process that never imports acausal."""
import json
import os
import pickle
import shutil
import subprocess
import sys
import zipfile

import numpy as np
import pytest

import acausal as ac
from acausal.compiler.backends.cbackend import compiler_available

fmpy = pytest.importorskip("fmpy", reason="fmpy (the 'fmi' extra) is not installed")
if compiler_available() is None:
    pytest.skip("no C compiler: FMUs cannot be built", allow_module_level=True)

from fmpy import read_model_description, simulate_fmu  # noqa: E402
from fmpy.validation import validate_fmu  # noqa: E402

from .models import Lag, Ship, cases, fmu_errors  # noqa: E402

CASES = {c[0]: c[1:] for c in cases()}
ME_BOUND = 1e-6        # ME: fmpy's CVode and acausal's BDF both at rtol 1e-10
CS_RTOL = 1e-6         # the embedded integrator's tolerance (fmi2SetupExperiment)
CS_BOUND = 100 * CS_RTOL   # its global error: local control, accumulated over the run


@pytest.fixture(scope="module")
def fmus(tmp_path_factory):
    """Exported FMUs by (case, fmi type), built on first use."""
    root = tmp_path_factory.mktemp("fmus")
    built = {}

    def get(case, kind):
        if (case, kind) not in built:
            cls, t_end, _ = CASES[case]
            path = os.fspath(root / f"{case}_{kind}.fmu")
            built[(case, kind)] = ac.export_fmu(cls(), path, kind, t_end=t_end)
        return built[(case, kind)]

    return get


@pytest.mark.parametrize("kind", ["ModelExchange", "CoSimulation"])
def test_exported_fmu_passes_fmpy_validation(fmus, kind):
    path = fmus("motor_drive", kind)
    assert validate_fmu(path) == []
    md = read_model_description(path)
    assert (md.modelExchange if kind == "ModelExchange" else md.coSimulation) is not None
    with zipfile.ZipFile(path) as zf:
        names = set(zf.namelist())
    ident = md.coSimulation.modelIdentifier if kind == "CoSimulation" else \
        md.modelExchange.modelIdentifier
    assert f"binaries/linux64/{ident}.so" in names or sys.platform != "linux"
    assert {"sources/model.c", "sources/fmu.c", "sources/fmi2Functions.h"} <= names


@pytest.mark.parametrize("case", list(CASES))
def test_model_exchange_agrees_with_simulate(fmus, case):
    cls, t_end, names = CASES[case]
    path = fmus(case, "ModelExchange")
    assert validate_fmu(path) == []
    errors, _ = fmu_errors(path, cls, t_end, names, rtol=1e-10)
    assert max(errors.values()) < ME_BOUND, errors


@pytest.mark.parametrize("case", list(CASES))
def test_co_simulation_agrees_with_simulate_to_its_tolerance(fmus, case):
    cls, t_end, names = CASES[case]
    path = fmus(case, "CoSimulation")
    assert validate_fmu(path) == []
    errors, _ = fmu_errors(path, cls, t_end, names, rtol=CS_RTOL)
    assert max(errors.values()) < CS_BOUND, errors


def test_co_simulation_error_falls_with_its_tolerance(fmus):
    """The embedded integrator is error-controlled: 100 times tighter, at least 10 times
    closer to the reference."""
    cls, t_end, names = CASES["motor_drive"]
    path = fmus("motor_drive", "CoSimulation")
    loose = max(fmu_errors(path, cls, t_end, names, rtol=1e-5)[0].values())
    tight = max(fmu_errors(path, cls, t_end, names, rtol=1e-7)[0].values())
    assert tight < loose / 10


@pytest.mark.parametrize("kind", ["ModelExchange", "CoSimulation"])
def test_parameters_set_through_fmi_act_as_in_simulate(fmus, kind):
    cls, t_end, names = CASES["motor_drive"]
    path = fmus("motor_drive", kind)
    rtol, bound = (1e-10, ME_BOUND) if kind == "ModelExchange" else (CS_RTOL, CS_BOUND)
    changed = {"motor.R": 2.0, "load.J": 0.02, "source.V": 12.0}
    errors, res = fmu_errors(path, cls, t_end, names, rtol=rtol, parameters=changed)
    assert max(errors.values()) < bound, errors
    default = ac.simulate(cls(), t_end=t_end, rtol=1e-8, t_eval=res["time"][-1:])
    # the change is large against the agreement: the parameters did reach the FMU
    assert abs(res["load.w"][-1] - default["load.w"][-1]) > 0.2 * abs(default["load.w"][-1])


def test_a_variable_fixed_to_a_parameter_follows_it(fmus):
    """supply.port.p is the supply's parameter p (alias elimination keeps it as a
    function of the parameters): set through FMI, both change, and the motor follows."""
    cls, t_end, names = CASES["valve_motor"]
    errors, res = fmu_errors(fmus("valve_motor", "ModelExchange"), cls, t_end,
                             names + ["supply.port.p"], rtol=1e-10,
                             parameters={"supply.p": 1.2e7})
    assert max(errors.values()) < ME_BOUND, errors
    assert np.max(np.abs(res["supply.port.p"] / 1.2e7 - 1.0)) < 1e-12


@pytest.mark.parametrize("kind", ["ModelExchange", "CoSimulation"])
def test_input_signal_applied_through_fmi_drives_the_model(tmp_path, kind):
    """A top-level RealInput is an FMI input: a unit step at t = 0.5 s into
    T x' = u - x, y = 2 x gives y = 2 (1 - exp(-(t - 0.5)/T)) after the step."""
    path = ac.export_fmu(Lag(T=0.25), os.fspath(tmp_path / "lag.fmu"), kind, t_end=2.0)
    assert validate_fmu(path) == []
    md = read_model_description(path)
    causality = {v.name: v.causality for v in md.modelVariables}
    assert causality["u"] == "input" and causality["y"] == "output"
    signal = np.array([(0.0, 0.0), (0.5, 0.0), (0.5, 1.0), (2.0, 1.0)],
                      dtype=[("time", float), ("u", float)])
    rtol, bound = (1e-10, ME_BOUND) if kind == "ModelExchange" else (CS_RTOL, CS_BOUND)
    res = simulate_fmu(path, stop_time=2.0, input=signal, relative_tolerance=rtol,
                       output_interval=0.01, output=["y", "x"])
    t = res["time"]
    exact = 2.0 * np.where(t > 0.5, 1.0 - np.exp(-(t - 0.5) / 0.25), 0.0)
    after = t > 0.5 + 1e-9
    assert np.max(np.abs(res["y"][after] - exact[after])) < bound * 2.0
    assert np.max(np.abs(res["y"][~after])) < bound
    assert res["y"][-1] > 1.99


@pytest.mark.parametrize("kind", ["ModelExchange", "CoSimulation"])
def test_start_values_of_states_set_through_fmi(fmus, kind):
    """A state's start value is an FMI start value (initial = exact): h(0) = 2 m,
    v(0) = 1 m/s gives h = 2 + t - g t^2/2 up to the first bounce at 0.757 s."""
    path = fmus("bouncing_ball", kind)
    initial = {v.name: v.initial for v in read_model_description(path).modelVariables}
    assert initial["h"] == initial["v"] == "exact"
    rtol, bound = (1e-10, ME_BOUND) if kind == "ModelExchange" else (CS_RTOL, CS_BOUND)
    res = simulate_fmu(path, stop_time=0.7, start_values={"h": 2.0, "v": 1.0},
                       relative_tolerance=rtol, output_interval=0.01, output=["h", "v"])
    t = res["time"]
    assert np.max(np.abs(res["h"] - (2.0 + t - 9.81 * t**2 / 2))) < bound * 2.0
    assert np.max(np.abs(res["v"] - (1.0 - 9.81 * t))) < bound * 9.81 * 0.7


def test_a_compiled_model_exports_with_its_parameter_values(tmp_path):
    cls, t_end, names = CASES["motor_drive"]
    compiled = ac.compile(cls())
    compiled.set_parameters({"motor.R": 2.0})
    path = ac.export_fmu(compiled, os.fspath(tmp_path / "compiled.fmu"), "ModelExchange")
    start = {v.name: v.start for v in read_model_description(path).modelVariables}
    assert float(start["motor.R"]) == 2.0
    errors, _ = fmu_errors(path, cls, t_end, names, rtol=1e-10, parameters={"motor.R": 2.0})
    assert max(errors.values()) < ME_BOUND, errors


def test_model_structure_matches_the_linearization(fmus):
    """Derivatives' dependencies (structural) against the nonzero pattern of A from
    ac.linearize (numeric, an independent path through the model)."""
    cls = CASES["motor_drive"][0]
    md = read_model_description(fmus("motor_drive", "ModelExchange"))
    ss = ac.linearize(cls())
    index = {v: k for k, v in enumerate(md.modelVariables)}
    states = [d.variable.derivative for d in md.derivatives]
    assert [v.name for v in states] == list(ss.states)
    A = np.asarray(ss.A)
    for i, der in enumerate(md.derivatives):
        listed = {index[v] for v in der.dependencies}
        numeric = {index[states[j]] for j in np.flatnonzero(np.abs(A[i]) > 1e-12 * np.abs(A).max())}
        assert listed == numeric, (der.variable.name, listed, numeric)
    assert md.numberOfEventIndicators == 1          # the step's relation
    units = {v.name: v.unit for v in md.modelVariables}
    assert units["motor.R"] == "Ohm" and units["load.w"] == "rad/s"


def test_fmu_runs_in_a_fresh_process_without_acausal(fmus, tmp_path):
    path = fmus("motor_drive", "ModelExchange")
    script = (
        "import json, sys\n"
        "from fmpy import simulate_fmu\n"
        f"r = simulate_fmu({path!r}, stop_time=1.0, relative_tolerance=1e-10, "
        "output_interval=0.01, output=['load.w'])\n"
        "assert not any(m == 'acausal' or m.startswith('acausal.') for m in sys.modules)\n"
        "print(json.dumps([float(r['time'][-1]), float(r['load.w'][-1])]))\n")
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    proc = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                          cwd=tmp_path, env=env, timeout=120)
    assert proc.returncode == 0, proc.stderr
    t_last, w_last = json.loads(proc.stdout.strip().splitlines()[-1])
    ref = ac.simulate(CASES["motor_drive"][0](), t_end=1.0, rtol=1e-10, t_eval=[t_last])
    assert abs(w_last - ref["load.w"][-1]) < ME_BOUND * abs(ref["load.w"][-1])


def test_fmu_rebuilds_from_its_sources(fmus, tmp_path):
    """sources/ and the SourceFiles of the modelDescription are everything the binary is
    built from: rebuilt by fmpy's own builder (cmake; the C compiler alone without it),
    the FMU runs as acausal does."""
    path = fmus("bouncing_ball", "ModelExchange")
    root = tmp_path / "unzipped"
    with zipfile.ZipFile(path) as zf:
        zf.extractall(root)
    shutil.rmtree(root / "binaries")
    if shutil.which("cmake"):
        from fmpy.build import build_platform_binary
        build_platform_binary(os.fspath(root))
    else:
        md = read_model_description(os.fspath(root))
        out = root / "binaries" / "linux64" / f"{md.modelExchange.modelIdentifier}.so"
        out.parent.mkdir(parents=True)
        src = root / "sources"
        proc = subprocess.run([compiler_available(), "-O2", "-fPIC", "-ffp-contract=off",
                               "-shared", "-I", str(src), "-o", str(out),
                               *sorted(str(p) for p in src.glob("*.c")), "-lm"],
                              capture_output=True, text=True)
        assert proc.returncode == 0, proc.stderr
    assert list((root / "binaries").rglob("*.so"))
    rebuilt = tmp_path / "rebuilt.fmu"
    shutil.make_archive(str(rebuilt.with_suffix("")), "zip", root)
    os.replace(str(rebuilt.with_suffix(".zip")), rebuilt)
    cls, t_end, names = CASES["bouncing_ball"]
    errors, _ = fmu_errors(os.fspath(rebuilt), cls, t_end, names, rtol=1e-10)
    assert max(errors.values()) < ME_BOUND, errors


def test_bad_arguments_are_typed_errors(tmp_path, monkeypatch):
    from acausal.library.examples.pendulum import Pendulum
    cls = CASES["bouncing_ball"][0]
    with pytest.raises(ValueError, match="ModelExchange.*CoSimulation"):
        ac.export_fmu(cls(), os.fspath(tmp_path / "a.fmu"), "Hybrid")
    with pytest.raises(ac.ModelError, match=r"dynamically.*\{der\(x\), der\(y\)\}"):
        ac.export_fmu(Pendulum(), os.fspath(tmp_path / "b.fmu"))
    with pytest.raises(ac.ModelError, match=r"differentiates its input 'delta'"):
        ac.export_fmu(Ship(), os.fspath(tmp_path / "e.fmu"))
    # a pickled model keeps its functions, not the Program its C is printed from
    stripped = pickle.loads(pickle.dumps(ac.compile(cls(), backend="numpy")))
    with pytest.raises(ac.ModelError, match="export the Component"):
        ac.export_fmu(stripped, os.fspath(tmp_path / "d.fmu"))
    monkeypatch.setenv("CC", os.fspath(tmp_path / "no-such-compiler"))
    with pytest.raises(ac.BackendError, match="C compiler"):
        ac.export_fmu(cls(), os.fspath(tmp_path / "c.fmu"))
    assert not (tmp_path / "c.fmu").exists()
