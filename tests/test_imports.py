"""What importing acausal loads: only what a call needs.

``import acausal`` binds its public names lazily (PEP 562): sympy comes with the first
symbol or equation, scipy with compile, simulate and the analyses.  Each check runs in a
fresh interpreter, since this test process has imported everything already.  No timing
is asserted (see benchmarks/first_result.py for the times).
"""
from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

from acausal.tests.rc_script import RC_CLASS

HEAVY = ("sympy", "networkx", "matplotlib", "scipy.sparse")


def _loaded(code: str, modules=HEAVY) -> list:
    """The ``modules`` present in sys.modules after running ``code`` in a new process."""
    probe = (f"{code}\nimport sys, json\n"
             f"print(json.dumps(sorted(m for m in {tuple(modules)!r} if m in sys.modules)))")
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True,
                         check=True).stdout
    return json.loads(out.strip().splitlines()[-1])


def test_import_acausal_loads_no_heavy_package():
    out = subprocess.run(
        [sys.executable, "-c", "import acausal, sys; print(sorted(m for m in ('sympy','networkx',"
         "'matplotlib','scipy.sparse') if m in sys.modules))"],
        capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"


def test_import_acausal_loads_no_scipy_or_pandas_at_all():
    assert _loaded("import acausal", ("scipy", "pandas", "scipy.signal", "scipy.optimize",
                                      "scipy.linalg")) == []


def test_electrical_library_and_component_classes_load_no_sympy():
    # declaring a component class checks its declarations without building a symbol
    code = """
import acausal as ac
import acausal.library.electrical
from acausal.library.electrical import Capacitor, Ground, Resistor

class RC(ac.Component):
    R1 = Resistor(R=2.0)
    C1 = Capacitor(C=1e-3, v={"start": 1.0, "fixed": True})
    gnd = Ground()
    k = ac.Parameter(2.0, unit="1", min=0)
    x = ac.Variable(start=0.5)
"""
    assert _loaded(code) == []


def test_the_first_equation_loads_sympy_and_nothing_else():
    code = """
import acausal as ac
from acausal import compile, simulate, Component, Parameter
from acausal.library.electrical import Resistor
"""
    assert _loaded(code) == []       # names cost nothing until they are called
    assert _loaded(code + "ac.Eq\n") == ["sympy"]
    assert _loaded(code + "ac.Eq(ac.time, 1.0)\n") == ["sympy"]


@pytest.mark.parametrize("package", ["acausal", "acausal.components", "acausal.solvers",
                                     "acausal.runtime", "acausal.library.electrical",
                                     "acausal.library.rotational", "acausal.library.friction",
                                     "acausal.library.hydraulics"])
def test_every_public_name_resolves(package):
    """Each name in __all__ is an attribute, comes with ``import *`` and is in dir()."""
    code = f"""
import importlib, json
pkg = importlib.import_module({package!r})
bad = [n for n in pkg.__all__ if getattr(pkg, n, None) is None]
star = {{}}
exec("from {package} import *", star)
print(json.dumps({{"bad": bad, "missing": sorted(set(pkg.__all__) - set(star)),
                  "dir": sorted(set(pkg.__all__) - set(dir(pkg)))}}))
"""
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout
    assert json.loads(out.strip().splitlines()[-1]) == {"bad": [], "missing": [], "dir": []}


def test_lazy_names_are_the_defining_modules_objects():
    import acausal as ac
    from acausal.components import symbols
    from acausal.library import electrical
    from acausal.analysis.linearize import linearize
    from acausal.library.electrical import sources
    from acausal.runtime.model import CompiledModel
    from acausal.simulation import compile, simulate

    assert ac.der is symbols.der and ac.Eq is symbols.Eq and ac.time is symbols.time
    assert ac.compile is compile and ac.simulate is simulate
    assert ac.CompiledModel is CompiledModel
    assert electrical.StepVoltage is sources.StepVoltage
    assert electrical.sources is sources          # submodules stay attributes
    assert ac.linearize is linearize and ac.analysis.linearize is linearize


def test_unknown_names_raise_attribute_error():
    import acausal as ac
    from acausal.library import electrical
    with pytest.raises(AttributeError, match="no attribute 'Resistr'"):
        electrical.Resistr    # noqa: B018
    with pytest.raises(AttributeError):
        ac.not_a_name         # noqa: B018
    assert not hasattr(ac, "benchmarks")   # a directory of the tree is not an attribute


RC_MODEL = '''
import json, math, sys
''' + RC_CLASS + '''

compiled = ac.compile(RC(), cache={"tree": "tree", "flat": True}[sys.argv[1]],
                      backend=sys.argv[2])
res = ac.simulate(compiled, t_end=5.0e-3, rtol=1e-6)
print(json.dumps({"error": abs(float(res["C1.v"][-1]) - (1.0 - math.exp(-5.0))),
                  "backend": compiled.backend,
                  "cached": any("compile cache" in n for n in compiled.report.notes),
                  "loaded": sorted(m for m in HEAVY if m in sys.modules)}))
'''


@pytest.mark.parametrize("backend", ["numpy", "auto"])
def test_a_cached_model_loads_neither_sympy_nor_what_its_run_does_not_use(tmp_path, backend):
    """The RC circuit (v_C = 1 - exp(-t/RC)) compiled in one process and found in the
    compile cache by the next ones: by its instance tree without sympy at all, by its
    flat model with sympy (flattening) but not sympy's units (the unit check's findings
    are in the entry); neither needs scipy.optimize, nor a run of a small system, by the
    compiled step loop or the Python one, scipy.sparse: its Jacobians are built dense."""
    heavy = ("sympy", "sympy.physics.units", "scipy.sparse", "scipy.optimize", "networkx")
    script = tmp_path / "rc_model.py"        # the tree key needs the class's source file
    script.write_text(f"HEAVY = {heavy!r}\n" + RC_MODEL)
    env = dict(os.environ, ACAUSAL_CACHE=str(tmp_path / "cache"))

    def run(mode):
        out = subprocess.run([sys.executable, str(script), mode, backend],
                             capture_output=True, text=True, check=True, env=env).stdout
        found = json.loads(out.strip().splitlines()[-1])
        assert found["error"] < 1e-4, found            # the run is still right
        return found

    assert not run("tree")["cached"]
    flat, tree = run("flat"), run("tree")
    assert flat["cached"] and tree["cached"]
    assert "sympy" in flat["loaded"] and "sympy.physics.units" not in flat["loaded"]
    assert "scipy.optimize" not in flat["loaded"]
    assert tree["loaded"] == []
