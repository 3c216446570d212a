"""Time to first result: ``import acausal`` and a whole RC circuit in a cold process.

Each measurement starts a new Python process (no module is imported yet, as for a user
who runs a script), so what is timed includes every import the call needs:

* ``import acausal`` alone;
* ``import acausal`` + the electrical library, ``ac.compile(..., cache="tree")`` of an
  RC circuit (a step source, a resistor, a capacitor and ground: 20 equations after
  flattening, 4 after alias elimination, one state) and ``ac.simulate`` of it, timed as
  a whole and per phase inside the child, whose result is checked against
  v_C = 1 - exp(-t/RC); for the numpy and the C backend, each with a **cold** compile
  cache (empty: the model is compiled, and with C its library built) and a **warm** one
  (the entry the cold run stored, found by the instance tree: no sympy).  The script is
  a file, since the tree key needs the model class's source.

The runs are interleaved, ``--repeat`` times (default 3), and the medians printed, with
the modules of sympy and scipy the warm run loaded; wall times on a shared machine are
noisy, so the CPU time (user + system) of the child is printed too.  Each run is broken
down into its import, compile (the passes, the C compiler for the model's library, and
the rest: mostly the imports the compile makes, sympy's above all), simulate, and the
interpreter's teardown after the script's last statement (the time from the child's
last clock reading to its exit as the parent sees it).  (The compiled step loop's
library is part of the installation: no run builds it.)  The children keep
their compiled bytecode in a temporary directory, as an installed package has it
(``--source`` compiles the modules in every run instead, as an environment with
PYTHONDONTWRITEBYTECODE does).  Then ``python -X importtime`` is run once on each script
(warm cache, C backend when it works), and on a cold run of each backend, and its ten
most expensive modules (own time) printed, with the time spent in each top-level
package.

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

from acausal.tests.rc_script import RC_CLASS

__all__ = ["RC_SCRIPT", "IMPORT_SCRIPT", "run_child", "environment", "import_times", "main"]

# The child prints the times of its phases as JSON on its last line.  Its arguments: the
# backend and the cache mode.  Nothing timed is a module constant (the tree key reads
# those: a time would make every run's key new).
RC_SCRIPT = """
import json, sys, time
_clock = [time.perf_counter()]
""" + RC_CLASS + """
_clock.append(time.perf_counter())     # the imports, and the class's components made


def main(backend, cache):
    compiled = ac.compile(RC(), backend=backend, cache={"tree": "tree", "flat": True}[cache])
    _clock.append(time.perf_counter())
    res = ac.simulate(compiled, t_end=5.0e-3, rtol=1e-6)
    _clock.append(time.perf_counter())
    # v_C = V (1 - exp(-t/RC)): a wrong run must not pass for a fast one
    import math
    err = abs(float(res["C1.v"][-1]) - (1.0 - math.exp(-5.0)))
    assert err < 1e-3, err
    counts = compiled.report.counts
    heavy = ("sympy", "sympy.physics.units", "scipy.sparse", "scipy.linalg", "scipy.optimize")
    t = _clock
    cached = any("compile cache" in n for n in compiled.report.notes)
    timings = {} if cached else compiled.report.timings
    print(json.dumps({"import": t[1] - t[0], "compile": t[2] - t[1], "simulate": t[3] - t[2],
                      "gcc": timings.get("c_backend", 0.0),
                      "passes": sum(v for k, v in timings.items() if k != "c_backend"),
                      "equations": [counts["flatten"]["equations"],
                                    counts["alias"]["equations"]],
                      "backend": compiled.backend, "step_loop": res.stats["step_loop"],
                      "module": ac.__file__,
                      "loaded": [m for m in heavy if m in sys.modules],
                      "end": time.time()}))


main(*sys.argv[1:3])
"""

IMPORT_SCRIPT = "import acausal"


def run_child(code: str, *flags: str, env: dict | None = None, file: bool = False,
              args=()) -> tuple:
    """Run ``code`` (with ``file``, the script of that path) in a new interpreter:
    (wall s, cpu s, stdout, stderr)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    source = [code] if file else ["-c", code]
    proc = subprocess.run([sys.executable, *flags, *source, *args], capture_output=True,
                          text=True, env=env if env is not None else environment())
    wall = time.perf_counter() - start
    run_child.ended = time.time()         # when the child had exited, for its teardown
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
        script = os.path.join(cache, "rc_first_result.py")
        with open(script, "w") as f:
            f.write(RC_SCRIPT)
        _report(args.repeat, env, script, cache, "compiled from source in every run"
                if args.source else "bytecode cached, as for an installed package")


def _rc(script: str, backend: str, env: dict, *flags: str) -> tuple:
    """One run of the RC script: (wall s, cpu s, the child's phases with ``teardown``,
    its stderr)."""
    wall, cpu, out, err = run_child(script, *flags, env=env, file=True, args=(backend, "tree"))
    phases = json.loads(out.strip().splitlines()[-1])
    phases["teardown"] = run_child.ended - phases["end"]
    return wall, cpu, phases, err


def _report(repeat: int, env: dict, script: str, cache: str, mode: str) -> None:
    if "PYTHONPYCACHEPREFIX" in env:       # compile every module once, sympy's included
        _rc(script, "numpy", {**env, "ACAUSAL_CACHE": os.path.join(cache, "warm-up")})
    imports, runs = [], {}
    for i in range(repeat):                # interleaved: load changes hit all alike
        w, c, _, _ = run_child(IMPORT_SCRIPT, env=env)
        imports.append((w, c))
        for backend in ("numpy", "c"):
            fresh = {**env, "ACAUSAL_CACHE": os.path.join(cache, f"models-{backend}-{i}")}
            for state in ("cold", "warm"):  # the cold run stores what the warm one finds
                runs.setdefault((backend, state), []).append(_rc(script, backend, fresh)[:3])
    median = statistics.median
    empty = median(run_child("pass", env=env)[0] for _ in range(repeat))
    print(f"cold-process timings, medians of {repeat} (interleaved), {mode}; "
          f"an empty interpreter takes {empty:.3f} s wall")
    print(f"  import acausal                      wall {median(w for w, _ in imports):.3f} s"
          f"   cpu {median(c for _, c in imports):.3f} s")
    first = runs["numpy", "cold"][0][2]
    print(f"  acausal from {os.path.dirname(first['module'])}")
    print(f"  RC circuit ({first['equations'][0]} equations after flattening, "
          f"{first['equations'][1]} after alias elimination), import + compile + simulate "
          "+ teardown:")
    for (backend, state), rows in runs.items():
        phases = [r[2] for r in rows]
        m = {k: median(p[k] for p in phases) for k in
             ("import", "compile", "simulate", "teardown", "passes", "gcc")}
        print(f"    {backend:<5} {state} cache   wall {median(r[0] for r in rows):.3f} s"
              f"   cpu {median(r[1] for r in rows):.3f} s   (inside: " + ", ".join(
                  f"{k} {m[k]:.3f}" for k in ("import", "compile", "simulate"))
              + f"; teardown {m['teardown']:.3f}; backend {phases[-1]['backend']}, step "
              f"loop {phases[-1]['step_loop']})")
        if state == "cold":
            rest = m["compile"] - m["passes"] - m["gcc"]
            print(f"      compile: passes {m['passes']:.3f}, C compiler for the model "
                  f"{m['gcc']:.3f}, the rest (imports: sympy, the compiler) {rest:.3f}")
        if state == "warm":
            loaded = ", ".join(phases[-1]["loaded"]) or "none of them"
            print(f"      sympy, sympy.physics.units, scipy.sparse/linalg/optimize loaded: "
                  f"{loaded}")

    _, _, _, err = run_child(IMPORT_SCRIPT, "-X", "importtime", env=env)
    _print_import_profile("python -X importtime -c 'import acausal'", import_times(err))
    for backend in ("numpy", "c"):
        cold = {**env, "ACAUSAL_CACHE": os.path.join(cache, f"importtime-{backend}")}
        _, _, _, err = _rc(script, backend, cold, "-X", "importtime")
        _print_import_profile(f"python -X importtime (RC, {backend}, cold cache: import, "
                              "compile, simulate)", import_times(err))
    warm = {**env, "ACAUSAL_CACHE": os.path.join(cache, "models-c-0")}
    _, _, _, err = _rc(script, "c", warm, "-X", "importtime")
    _print_import_profile("python -X importtime (RC, c, warm cache: import, compile, simulate)",
                          import_times(err))


if __name__ == "__main__":
    main()
