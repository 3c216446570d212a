"""Time to first result: ``import acausal`` and a whole RC circuit in a cold process.

Each measurement starts a new Python process (no module is imported yet, as for a user
who runs a script), so what is timed includes every import the call needs:

* ``import acausal`` alone;
* ``import acausal`` + the electrical library, ``ac.compile`` of an RC circuit (a step
  source, a resistor, a capacitor and ground: 20 equations after flattening, 4 after
  alias elimination, one state) and ``ac.simulate`` of it, timed as a whole and per
  phase inside the child, whose result is checked against v_C = 1 - exp(-t/RC).

The two are run interleaved, ``--repeat`` times (default 3), and the medians printed;
wall times on a shared machine are noisy, so the CPU time (user + system) of the child
is printed too.  The children keep their caches in a temporary directory: compiled
bytecode, as an installed package has it (``--source`` compiles the modules in every
run instead, as an environment with PYTHONDONTWRITEBYTECODE does), and the C backend's
library of the model, built by the model's first run (printed on its own).  Then
``python -X importtime`` is run once on each script and its ten most expensive modules
(own time) printed, with the time spent in each top-level package.

    python benchmarks/first_result.py [--repeat N] [--source]
"""
from __future__ import annotations

import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

__all__ = ["RC_SCRIPT", "IMPORT_SCRIPT", "run_child", "environment", "import_times", "main"]

# The child prints the times of its phases as JSON on its last line.
RC_SCRIPT = """
import json, time
t0 = time.perf_counter()
import acausal as ac
from acausal.library.electrical import Capacitor, Ground, Resistor, StepVoltage
t1 = time.perf_counter()

class RC(ac.Component):
    src = StepVoltage(V=1.0)
    R1 = Resistor(R=1.0e3)
    C1 = Capacitor(C=1.0e-6)
    gnd = Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.R1.p), ac.connect(self.R1.n, self.C1.p),
                ac.connect(self.C1.n, self.src.n, self.gnd.p)]

compiled = ac.compile(RC())
t2 = time.perf_counter()
res = ac.simulate(compiled, t_end=5.0e-3, rtol=1e-6)
t3 = time.perf_counter()
# v_C = V (1 - exp(-t/RC)): a wrong run must not pass for a fast one
import math
err = abs(float(res["C1.v"][-1]) - (1.0 - math.exp(-5.0)))
assert err < 1e-3, err
counts = compiled.report.counts
print(json.dumps({"import": t1 - t0, "compile": t2 - t1, "simulate": t3 - t2,
                  "equations": [counts["flatten"]["equations"],
                                counts["alias"]["equations"]],
                  "backend": getattr(compiled, "backend", "numpy")}))
"""

IMPORT_SCRIPT = "import acausal"


def run_child(code: str, *flags: str, env: dict | None = None) -> tuple:
    """Run ``code`` in a new interpreter: (wall s, cpu s, stdout, stderr)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    proc = subprocess.run([sys.executable, *flags, "-c", code], capture_output=True,
                          text=True, env=env if env is not None else environment())
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if proc.returncode != 0:
        raise RuntimeError(f"child failed ({proc.returncode}):\n{proc.stderr}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu, proc.stdout, proc.stderr


def environment(cache: str, bytecode: bool = True) -> dict:
    """The children's environment, with their caches in the directory ``cache``: the
    C backend's shared libraries, and with ``bytecode`` the compiled modules (as an
    installed package has them); without, this process's environment decides
    (PYTHONDONTWRITEBYTECODE makes every run compile acausal's modules from source)."""
    env = dict(os.environ)
    # a user's PYTHONSTARTUP or an inherited importtime flag would distort the timing
    env.pop("PYTHONSTARTUP", None)
    env.pop("PYTHONPROFILEIMPORTTIME", None)
    env["ACAUSAL_CACHE"] = os.path.join(cache, "models")
    if bytecode:
        env.pop("PYTHONDONTWRITEBYTECODE", None)
        env["PYTHONPYCACHEPREFIX"] = os.path.join(cache, "bytecode")
    return env


def import_times(stderr: str) -> list:
    """Parse ``-X importtime`` output: (self s, cumulative s, depth, module), in order."""
    rows = []
    for line in stderr.splitlines():
        if not line.startswith("import time:") or "self [us]" in line:
            continue
        own, cumulative, name = line[len("import time:"):].split("|")
        depth = (len(name) - len(name.lstrip(" ")) - 1) // 2
        rows.append((int(own) * 1e-6, int(cumulative) * 1e-6, depth, name.strip()))
    return rows


def _print_import_profile(title: str, rows: list, top: int = 10) -> None:
    print(f"\n{title}: {len(rows)} modules, "
          f"{sum(r[0] for r in rows):.3f} s of module bodies")
    print(f"  top {top} by own time{'':<29} own [s]   cumulative [s]")
    for own, cumulative, _, name in sorted(rows, key=lambda r: -r[0])[:top]:
        print(f"  {name:<46} {own:8.3f}   {cumulative:8.3f}")
    packages = {}
    for own, _, _, name in rows:
        root = name.split(".")[0]
        packages[root] = packages.get(root, 0.0) + own
    heavy = sorted(packages.items(), key=lambda kv: -kv[1])[:top]
    print("  own time by top-level package [s]: "
          + ", ".join(f"{n} {t:.3f}" for n, t in heavy))


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--source", action="store_true",
                        help="no bytecode cache: compile acausal's modules in every run")
    args = parser.parse_args(argv)
    with tempfile.TemporaryDirectory(prefix="acausal-bench-") as cache:
        env = environment(cache, bytecode=not args.source)
        _report(args.repeat, env, "compiled from source in every run" if args.source
                else "bytecode cached, as for an installed package")


def _report(repeat: int, env: dict, mode: str) -> None:
    if "PYTHONPYCACHEPREFIX" in env:       # compile every module once, sympy's included
        run_child(RC_SCRIPT, env={**env, "ACAUSAL_CACHE": env["ACAUSAL_CACHE"] + "-warm-up"})
    # the first run of the model builds its C library (with the C backend), then cached
    wall, cpu, out, _ = run_child(RC_SCRIPT, env=env)
    first = json.loads(out.strip().splitlines()[-1])
    imports, rcs, phases = [], [], []
    for _ in range(repeat):                # interleaved: load changes hit both alike
        w, c, _, _ = run_child(IMPORT_SCRIPT, env=env)
        imports.append((w, c))
        w, c, out, _ = run_child(RC_SCRIPT, env=env)
        rcs.append((w, c))
        phases.append(json.loads(out.strip().splitlines()[-1]))
    median = statistics.median
    empty = median(run_child("pass", env=env)[0] for _ in range(repeat))
    print(f"cold-process timings, medians of {repeat} (interleaved), {mode}; "
          f"an empty interpreter takes {empty:.3f} s wall")
    print(f"  import acausal                      wall {median(w for w, _ in imports):.3f} s"
          f"   cpu {median(c for _, c in imports):.3f} s")
    print(f"  import + compile + simulate (RC)    wall {median(w for w, _ in rcs):.3f} s"
          f"   cpu {median(c for _, c in rcs):.3f} s")
    for key in ("import", "compile", "simulate"):
        print(f"    {key:<10} (inside the child) {median(p[key] for p in phases):.3f} s")
    flat, reduced = first["equations"]
    print(f"    the RC circuit has {flat} equations after flattening, {reduced} after "
          f"alias elimination; backend {first['backend']}")
    print(f"  the model's first run (cache of C libraries empty): wall {wall:.3f} s, "
          f"cpu {cpu:.3f} s, compile {first['compile']:.3f} s (one run, not a median)")

    _, _, _, err = run_child(IMPORT_SCRIPT, "-X", "importtime", env=env)
    _print_import_profile("python -X importtime -c 'import acausal'", import_times(err))
    _, _, _, err = run_child(RC_SCRIPT, "-X", "importtime", env=env)
    _print_import_profile("python -X importtime (RC: import, compile, simulate)",
                          import_times(err))


if __name__ == "__main__":
    main()
