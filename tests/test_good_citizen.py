"""acausal leaves its user's process as it found it.

In a fresh interpreter (this test process has imported and run everything already), a
script snapshots what acausal does not own -- sympy's classes, the garbage collector's
switch and frozen generation, the environment, child processes and threads -- then
imports acausal, compiles (while another thread watches sympy.Symbol), simulates,
exports an FMU and runs a sweep (in this process and on worker processes), and compares: nothing may have changed, and every process and
thread the calls started must have ended with them (daemon threads of the libraries
the calls import aside)."""
import json
import math
import os
import subprocess
import sys

from acausal import native
from acausal.tests.rc_script import RC_CLASS

SCRIPT = '''
import gc, json, os, sys, threading
import sympy

CLASSES = (sympy.Symbol, sympy.Expr, sympy.Basic, sympy.Add, sympy.Mul, sympy.Pow)
def methods():
    return {c.__name__: {k: id(v) for k, v in vars(c).items()} for c in CLASSES}

before = {"methods": methods(), "gc": gc.isenabled(), "environ": dict(os.environ),
          "threshold": gc.get_threshold()}
''' + RC_CLASS + '''
import tempfile, time


class Ladder(ac.Component):
    def __init__(self, n, **mods):
        super().__init__(**mods)
        self.src, self.gnd = StepVoltage(V=1.0), Ground()
        self.R = [Resistor(R=1.0) for _ in range(n)]
        self.C = [Capacitor(C=1e-3) for _ in range(n)]

    def equations(self):
        eqs = [ac.connect(self.src.n, self.gnd.p, *[c.n for c in self.C])]
        node = self.src.p
        for r, c in zip(self.R, self.C):
            eqs += [ac.connect(node, r.p), ac.connect(r.n, c.p)]
            node = c.p
        return eqs


# another thread that reads sympy's classes while a model is compiled sees them as they are
own = set(vars(sympy.Symbol))
changed, stop = [], threading.Event()
def watch():
    while not stop.is_set():
        if set(vars(sympy.Symbol)) != own:
            changed.append(1)
        time.sleep(0.0002)
watcher = threading.Thread(target=watch)
watcher.start()
ac.compile(Ladder(100), backend="numpy", cache=False)
stop.set()
watcher.join()
compiled = ac.compile(RC(), backend="auto")
res = ac.simulate(compiled, t_end=5e-3, n_points=11)
swept = ac.sweep(compiled, {"R1.R": [500.0, 1000.0]}, t_end=5e-3, n_points=11)
done = ["compile", "simulate", "sweep"]
if EXPORT:
    with tempfile.TemporaryDirectory() as d:
        ac.export_fmu(RC(), os.path.join(d, "rc.fmu"))
    done.append("export_fmu")
if PROCESSES:
    ac.sweep(compiled, {"R1.R": [500.0, 1000.0]}, t_end=5e-3, n_points=11,
             executor="processes")
    done.append("sweep on processes")

try:
    os.waitpid(-1, os.WNOHANG)
    children = True                 # a child of this process is still there
except ChildProcessError:
    children = False
import multiprocessing
after = {"methods": methods(), "gc": gc.isenabled(), "environ": dict(os.environ),
         "threshold": gc.get_threshold()}
print(json.dumps({
    "done": done, "same_methods": after["methods"] == before["methods"],
    "changed_meanwhile": bool(changed),
    "gc_as_before": after["gc"] == before["gc"], "gc": after["gc"],
    "threshold_as_before": after["threshold"] == before["threshold"],
    "freeze_count": gc.get_freeze_count(), "same_environ": after["environ"] == before["environ"],
    "children": children or bool(multiprocessing.active_children()),
    "threads": [t.name for t in threading.enumerate()
                if t is not threading.main_thread() and not t.daemon],
    "error": abs(float(res["C1.v"][-1]) - (1.0 - 2.718281828459045 ** -5.0)),
    "swept": [float(v) for v in swept["C1.v"].values[:, -1]]}))
'''


def _fmu_export_possible() -> bool:
    try:
        import fmpy  # noqa: F401
    except ImportError:
        return False
    return native.find_compiler() is not None


def _run(tmp_path, disable_gc: bool) -> dict:
    head = f"EXPORT = {_fmu_export_possible()}\nPROCESSES = True\n"
    if disable_gc:
        head += "import gc; gc.disable()\n"
    path = tmp_path / f"citizen_{int(disable_gc)}.py"   # a file: the classes have a source
    path.write_text(head + SCRIPT)
    env = dict(os.environ, ACAUSAL_CACHE=str(tmp_path / "cache"))
    out = subprocess.run([sys.executable, str(path)], capture_output=True, text=True,
                         check=True, env=env, stdin=subprocess.DEVNULL, timeout=600).stdout
    return json.loads(out.strip().splitlines()[-1])


def test_a_process_is_left_as_it_was_found(tmp_path):
    found = _run(tmp_path, disable_gc=False)
    # the runs were right: v_C = 1 - exp(-t/RC) at t = 5 ms, RC = 0.5 ms and 1 ms
    assert found["error"] < 1e-6
    exact = [1.0 - math.exp(-10.0), 1.0 - math.exp(-5.0)]
    assert max(abs(a - b) for a, b in zip(found["swept"], exact)) < 1e-6
    assert {"compile", "simulate", "sweep", "sweep on processes"} <= set(found["done"])
    assert found["same_methods"]            # sympy.Symbol & co keep their own methods,
    assert not found["changed_meanwhile"]   # also while a compile runs
    assert found["gc_as_before"] and found["gc"] is True and found["threshold_as_before"]
    assert found["freeze_count"] == 0       # nothing moved to the permanent generation
    assert found["same_environ"]
    assert not found["children"]            # no child process remains
    assert found["threads"] == []           # nor a thread that keeps the process alive


def test_a_collector_switched_off_by_the_caller_stays_off(tmp_path):
    found = _run(tmp_path, disable_gc=True)
    assert found["gc_as_before"] and found["gc"] is False
    assert found["freeze_count"] == 0 and not found["children"] and found["threads"] == []
