"""The first compile that loads sympy exempts what is alive from the cyclic collector
(``gc.freeze``), once, in a script: sympy's objects are then neither walked by later
collections nor taken apart at exit.  What was garbage is collected first, garbage made
later is still collected, an interactive session is left alone, and the run is still
right (the RC circuit's v_C = V (1 - exp(-t/RC))).  No time is asserted."""
from __future__ import annotations

import json
import os
import subprocess
import sys

from acausal.tests.rc_script import RC_CLASS

SCRIPT = '''
import gc, json, math, sys, weakref
''' + RC_CLASS + '''

class Node:
    pass


def cycle():
    a, b = Node(), Node()
    a.other, b.other = b, a
    return weakref.ref(a)


freezes = []
_freeze = gc.freeze
gc.freeze = lambda: (freezes.append(1), _freeze())[1]
gc.disable()                 # nothing but an explicit collection frees a cycle
before = cycle()             # garbage when the compile starts
compiled = ac.compile(RC(), backend="numpy", cache=False)
frozen = gc.get_freeze_count()
after = cycle()              # garbage made after the exemption
gc.collect()
compiled2 = ac.compile(RC(), backend="numpy", cache=False)
res = ac.simulate(compiled, t_end=5.0e-3, rtol=1e-6)
exact = 1.0 - math.exp(-5.0)
print(json.dumps({"frozen": frozen, "freezes": len(freezes),
                  "before_collected": before() is None, "after_collected": after() is None,
                  "error": abs(float(res["C1.v"][-1]) - exact) / exact}))
'''


def _run(tmp_path, *flags) -> dict:
    path = tmp_path / "collector.py"
    path.write_text(SCRIPT)
    env = dict(os.environ, ACAUSAL_CACHE=str(tmp_path / "cache"))
    out = subprocess.run([sys.executable, *flags, str(path)], capture_output=True, text=True,
                         check=True, env=env, stdin=subprocess.DEVNULL, timeout=300).stdout
    return json.loads([ln for ln in out.splitlines() if ln.startswith("{")][-1])


def test_a_script_freezes_once_after_collecting(tmp_path):
    found = _run(tmp_path)
    assert found["error"] < 1e-4
    assert found["frozen"] > 10_000                      # sympy's modules, at least
    assert found["freezes"] == 1                         # once: not by the second compile
    assert found["before_collected"] and found["after_collected"]


def test_an_interactive_session_is_left_alone(tmp_path):
    found = _run(tmp_path, "-i")
    assert found["error"] < 1e-4
    assert found["frozen"] == 0 and found["freezes"] == 0
    assert found["after_collected"]


LADDER_SCRIPT = '''
import gc, json, sys
import acausal as ac
from acausal.compiler import gcpause
from acausal.library.electrical import Capacitor, Ground, Inductor, Resistor, StepVoltage


class Ladder(ac.Component):
    def __init__(self, n, **mods):
        super().__init__(**mods)
        self.src, self.gnd = StepVoltage(V=1.0), Ground()
        self.R = [Resistor(R=1.0) for _ in range(n)]
        self.L = [Inductor(L=1e-3) for _ in range(n)]
        self.C = [Capacitor(C=1e-3) for _ in range(n)]

    def equations(self):
        eqs = [ac.connect(self.src.n, self.gnd.p, *[c.n for c in self.C])]
        node = self.src.p
        for r, l, c in zip(self.R, self.L, self.C):
            eqs += [ac.connect(node, r.p), ac.connect(r.n, l.p), ac.connect(l.n, c.p)]
            node = c.p
        return eqs


gcpause.YOUNG_ENOUGH = 1000          # this compile counts as a large one
full = []
gc.callbacks.append(lambda phase, info: full.append(gc.get_count()[0])
                    if phase == "start" and info["generation"] == 2 else None)
compiled = ac.compile(Ladder(40), backend="numpy", cache=False)
first = list(full)
alive = []
for _ in range(5):
    compiled = ac.compile(Ladder(40), backend="numpy", cache=False)
    gc.collect()
    alive.append(len(gc.get_objects()) + gc.get_freeze_count())
print(json.dumps({"first": first, "frozen": gc.get_freeze_count(), "alive": alive}))
'''


def test_the_first_compile_freezes_what_it_keeps_unwalked(tmp_path):
    """The one full collection of the first compile runs before it (with only the
    objects made since the last young collection pending, at most CPython's threshold
    of 700), not over the compile's objects; and compiling the model again and again,
    keeping the last, keeps the number of live objects: the compile leaves no garbage
    that accumulates (the first compile's model, frozen, is freed when let go)."""
    path = tmp_path / "ladder.py"
    path.write_text(LADDER_SCRIPT)
    env = dict(os.environ, ACAUSAL_CACHE=str(tmp_path / "cache"))
    out = subprocess.run([sys.executable, str(path)], capture_output=True, text=True,
                         check=True, env=env, stdin=subprocess.DEVNULL, timeout=300).stdout
    found = json.loads([ln for ln in out.splitlines() if ln.startswith("{")][-1])
    assert len(found["first"]) == 1 and found["first"][0] < 2000
    assert found["frozen"] > 10_000
    alive = found["alive"]
    assert max(alive) < 1.02 * alive[0], alive


TREE_SCRIPT = '''
import gc, json, sys
''' + RC_CLASS + '''

full = []
gc.callbacks.append(lambda phase, info: full.append(1)
                    if phase == "start" and info["generation"] == 2 else None)
counts = []
for _ in range(3):           # found by the instance tree: no sympy, no freeze
    ac.compile(RC(), backend="numpy", cache="tree")
    counts.append(len(full))
sympy_before = "sympy" in sys.modules
ac.compile(RC(), backend="numpy", cache=False)
print(json.dumps({"counts": counts, "sympy_before": sympy_before,
                  "frozen": gc.get_freeze_count()}))
'''


def test_loads_without_sympy_collect_once_and_a_later_compile_still_freezes(tmp_path):
    """Models found by their instance tree load no sympy and are not followed by the
    freeze: only the first of them is preceded by a full collection (not every load,
    over a heap that grows with the models loaded); the compile that loads sympy later
    collects and freezes as before."""
    path = tmp_path / "tree.py"
    path.write_text(TREE_SCRIPT)
    env = dict(os.environ, ACAUSAL_CACHE=str(tmp_path / "cache"))
    subprocess.run([sys.executable, str(path)], check=True, env=env, capture_output=True,
                   stdin=subprocess.DEVNULL, timeout=300)        # fills the cache
    out = subprocess.run([sys.executable, str(path)], capture_output=True, text=True,
                         check=True, env=env, stdin=subprocess.DEVNULL, timeout=300).stdout
    found = json.loads([ln for ln in out.splitlines() if ln.startswith("{")][-1])
    assert not found["sympy_before"]
    first, _, last = found["counts"]
    assert first >= 1 and last - first <= 1     # (one may be CPython's own schedule)
    assert found["frozen"] > 10_000
