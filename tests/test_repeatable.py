"""The same model, inputs and options give bitwise the same result whatever ran before.

Each variant is a fresh interpreter that runs one script and prints a digest of the
results' bytes (the times and every variable) with the step loop and the LU
that ran: scipy.linalg imported first or not, the compile cache empty or warm, no C
compiler on the path (the numpy backend), inside an IPython shell as a notebook runs
it, and a second run in the same process.  The model has a relation (a diode) and an
algebraic loop, so modes, events and Newton iterations on a dense LU all take part;
it is run by the compiled step loop and by the Python one, on both backends."""
import json
import os
import subprocess
import sys

import pytest

from acausal import native

SCRIPT = '''
import hashlib, json, sys
if "scipy" in sys.argv[1:]:
    import scipy.linalg  # noqa: F401
import acausal as ac
from acausal.library.electrical import (Capacitor, Ground, IdealDiode, Resistor,
                                        SineVoltage)


class Rectifier(ac.Component):
    """A half-wave rectifier with a smoothing capacitor and a load."""
    src = SineVoltage(V=10.0, f=50.0)
    D1 = IdealDiode()
    R1 = Resistor(R=10.0)
    C1 = Capacitor(C=1e-3)
    RL = Resistor(R=100.0)
    gnd = Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.R1.p), ac.connect(self.R1.n, self.D1.p),
                ac.connect(self.D1.n, self.C1.p, self.RL.p),
                ac.connect(self.C1.n, self.RL.n, self.src.n, self.gnd.p)]


def digest(res):
    h = hashlib.sha256(res.t.tobytes())
    for name in res.names:             # every variable, in the order the result has them
        h.update(name.encode() + res[name].tobytes())
    return h.hexdigest()[:20]


out = {}
for backend in BACKENDS:
    compiled = ac.compile(Rectifier(), backend=backend)
    for loop in ("auto", "python"):
        res = ac.simulate(compiled, t_end=0.05, rtol=1e-6, step_loop=loop)
        again = ac.simulate(compiled, t_end=0.05, rtol=1e-6, step_loop=loop)
        out[f"{backend} {loop}"] = [digest(res), digest(again), res.stats["step_loop"],
                                    res.stats["lu"], len(res.events)]
print(json.dumps(out))
'''

IN_IPYTHON = '''
import sys
from IPython.core.interactiveshell import InteractiveShell
shell = InteractiveShell.instance()
source = open(sys.argv[1]).read()
sys.argv = sys.argv[1:]
shell.run_cell(source, store_history=False).raise_error()
'''


def _run(tmp_path, cache: str, *flags, path=None, ipython=False, backends=("numpy", "c")):
    script = tmp_path / "rectifier.py"
    script.write_text(f"BACKENDS = {list(backends)!r}\n" + SCRIPT)
    env = dict(os.environ, ACAUSAL_CACHE=str(tmp_path / cache))
    if path is not None:
        env["PATH"] = path
        env.pop("CC", None)
    args = [sys.executable, "-c", IN_IPYTHON, str(script)] if ipython else \
        [sys.executable, str(script)]
    out = subprocess.run(args + list(flags), capture_output=True, text=True, check=True,
                         env=env, timeout=600).stdout
    return json.loads(out.strip().splitlines()[-1])


def test_a_result_is_the_same_bitwise_whatever_ran_before(tmp_path):
    backends = ("numpy", "c") if native.find_compiler() is not None else ("numpy",)
    cold = _run(tmp_path, "cache", "scipy", backends=backends)      # empty cache
    warm = _run(tmp_path, "cache", backends=backends)               # its entries found
    warm_scipy = _run(tmp_path, "cache", "scipy", backends=backends)
    other = _run(tmp_path, "other", backends=backends)              # empty, no scipy
    for case in (warm, warm_scipy, other):
        assert case == cold
    for key, (first, second, loop, lu, n_events) in cold.items():
        assert first == second, key                   # a later run equals the first
        assert n_events > 0                           # the diode switched
        assert loop == ("python" if key.endswith("python") else loop)
    assert cold["numpy python"][3] in ("compiled", "numpy", "lapack")


def test_the_numpy_backend_does_not_depend_on_a_c_compiler_on_the_path(tmp_path):
    bare = tmp_path / "bin"               # a PATH with no C compiler on it
    bare.mkdir()
    with_cc = _run(tmp_path, "one", backends=("numpy",))
    without = _run(tmp_path, "two", path=str(bare), backends=("numpy",))
    assert without == with_cc


def test_a_notebook_gets_the_numbers_a_script_gets(tmp_path):
    pytest.importorskip("IPython")
    script = _run(tmp_path, "cache", backends=("numpy",))
    shell = _run(tmp_path, "other", ipython=True, backends=("numpy",))
    assert shell == script
