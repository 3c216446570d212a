"""Compile time of each pass as models grow: the size families of ``families.py``.

For each family (``ladder``: RLC ladder on one ground; ``chain``: mass-spring chain;
``network``: random R/L/C network) and each size N the model is compiled in a fresh
Python process (no sympy cache or import left over from the previous size), which
reports the time of every pass (``report.timings``), its peak resident memory
(``resource.getrusage``) and the number of flat equations n.  Between successive sizes
the growth exponent of each pass is

    k = log(t2 / t1) / log(n2 / n1),

1 for linear growth, 2 for quadratic; on times below a few milliseconds it is noise.
Every (family, N) is run ``--repeat`` times, the repetitions interleaved (all sizes
once, then again), and the median of each time is printed: the machine is shared, and
single timings are noisy.  ``total`` is the wall time of ``compile_model``, ``cpu`` the
processor time of the process during it (less sensitive to other load), ``sub cpu`` that
of its child processes -- the C compiler's (all translation units) and the compile's side
jobs (:mod:`acausal.compiler.sidejobs`: the cache key, the index as written and the cache
store, in forked copies) -- user + system; ``RSS MB`` is the Python process's peak
memory, ``sub MB`` the largest child's (a forked child shares the parent's pages until
it writes them, so this over-counts what it adds), and a line per size says
how the C library was built (translation units, compilers at once, flags, seconds
compiling and linking; :mod:`acausal.native.build`) and the load average then.

``--front`` stops after index reduction: code generation is replaced by a stand-in
that builds nothing (the report is still filled, so the cost of its texts is measured),
for sizes where code generation would dominate the run.

    python benchmarks/bench_scale.py [--families ladder,chain,network]
                                     [--sizes 100,300,1000,3000] [--repeat 3] [--front]
"""
from __future__ import annotations

import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import time

__all__ = ["measure_once", "main"]

_HERE = os.path.dirname(os.path.abspath(__file__))
_last_report = None       # the report of a --front compile (the stand-in code has none)
_FAMILIES = ("ladder", "chain", "network")


def _front_only() -> None:
    """Replace code generation (and the binding of a backend to it) by stand-ins; the
    stand-in code has the fields the report reads."""
    import importlib
    from types import SimpleNamespace
    from acausal.compiler import pipeline

    def assemble(system, reduction, reduced, flat, aliases, report, discretes, *rest):
        global _last_report
        _last_report = report
        return SimpleNamespace(names=[], state_z=[], pairs=[], dummies=[],
                               relations=SimpleNamespace(n_relations=0, n_discrete=0))
    pipeline._assemble = assemble
    try:
        cbackend = importlib.import_module("acausal.compiler.backends.cbackend")
    except ImportError:
        return
    cbackend.bind = lambda *args, **kwargs: None


def _preload() -> None:
    """Import what the passes import on first use (scipy's assignment and graph
    solvers): an import is paid once per process, it is not compile time."""
    import scipy.optimize  # noqa: F401
    import scipy.sparse.csgraph  # noqa: F401


def measure_once(family: str, n: int, front: bool) -> dict:
    """Compile ``family(n)`` in this process; times in seconds, memory in MB."""
    import resource
    sys.path.insert(0, _HERE)
    import families
    from acausal.compiler.pipeline import compile_model
    if front:
        _front_only()
    _preload()
    model = getattr(families, family)(n)
    kids0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0, c0 = time.perf_counter(), time.process_time()
    code = compile_model(model)
    total = time.perf_counter() - t0
    report = _last_report if front else code.report
    usage = resource.getrusage(resource.RUSAGE_SELF)
    from acausal.compiler import sidejobs
    sidejobs.settle()        # the cache store beside the compile: its time and memory too
    kids = resource.getrusage(resource.RUSAGE_CHILDREN)
    try:
        from acausal.native.build import last_build
    except ImportError:
        last_build = {}
    return {"family": family, "n": n, "flat": report.counts["flatten"]["equations"],
            "total": total, "cpu": time.process_time() - c0, "timings": dict(report.timings),
            "rss_mb": usage.ru_maxrss / 1024.0, "child_rss_mb": kids.ru_maxrss / 1024.0,
            "cc_cpu": (kids.ru_utime - kids0.ru_utime) + (kids.ru_stime - kids0.ru_stime),
            "c_build": dict(last_build),
            "load": os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")}


def _child(family: str, n: int, front: bool) -> dict:
    cmd = [sys.executable, os.path.abspath(__file__), "--child", family, str(n)]
    if front:
        cmd.append("--front")
    out = subprocess.run(cmd, capture_output=True, text=True, check=False)
    if out.returncode != 0:
        raise RuntimeError(f"{family}({n}) failed:\n{out.stderr[-3000:]}")
    return json.loads(out.stdout.strip().splitlines()[-1])


def _exponent(t1: float, t2: float, n1: int, n2: int) -> float:
    if t1 <= 0 or t2 <= 0 or n1 == n2:
        return float("nan")
    return math.log(t2 / t1) / math.log(n2 / n1)


def _table(family: str, runs: list) -> str:
    """One row per size: median time of each pass, then the exponents to the previous size."""
    passes = []
    for r in runs:
        for k in r[0]["timings"]:
            if k not in passes:
                passes.append(k)
    med = []
    for reps in runs:
        m = {k: statistics.median(r["timings"].get(k, 0.0) for r in reps) for k in passes}
        m["total"] = statistics.median(r["total"] for r in reps)
        m["cpu"] = statistics.median(r["cpu"] for r in reps)
        m["sub cpu"] = statistics.median(r.get("cc_cpu", 0.0) for r in reps)
        m["sub MB"] = max(r.get("child_rss_mb", 0.0) for r in reps)
        med.append((reps[0]["n"], reps[0]["flat"], m,
                    max(r["rss_mb"] for r in reps)))
    cols = passes + ["total", "cpu", "sub cpu", "sub MB"]
    width = max(9, *(len(c) + 1 for c in cols))
    head = f"{'N':>6} {'flat eqs':>9} {'RSS MB':>7} " + "".join(f"{c:>{width}}" for c in cols)
    lines = [f"{family}: median seconds of {len(runs[0])} run(s) per size", head]
    for k, (n, flat, m, rss) in enumerate(med):
        lines.append(f"{n:>6} {flat:>9} {rss:>7.0f} "
                     + "".join(f"{m[c]:>{width}.3f}" for c in cols))
        if k:
            _, flat0, m0, _ = med[k - 1]
            lines.append(f"{'':>6} {'exponent':>9} {'':>7} " + "".join(
                f"{_exponent(m0[c], m[c], flat0, flat):>{width}.2f}" for c in cols))
    for reps in runs:
        b = reps[-1].get("c_build")
        if b:
            load = statistics.median(r.get("load", float("nan")) for r in reps)
            lines.append(f"  N = {reps[-1]['n']}: C library from "
                         f"{b['characters'] / 1e6:.2f} MB of C in {b['units']} translation "
                         f"unit(s), {b['jobs']} compiler(s) at once, {b['flags']}: "
                         f"{b['compile_s']:.2f} s compiling, {b['link_s']:.2f} s linking; "
                         f"load average {load:.1f}")
    per = med[-1][2]["total"] / med[-1][1] * 1e6
    lines.append(f"  largest size: {per:.0f} us per flat equation in total")
    return "\n".join(lines)


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--families", default=",".join(_FAMILIES))
    ap.add_argument("--sizes", default="100,300,1000,3000")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--front", action="store_true",
                    help="stop after index reduction (no code generation)")
    ap.add_argument("--json", help="also write the raw measurements to this file")
    ap.add_argument("--child", nargs=2, metavar=("FAMILY", "N"), help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    if args.child:
        print(json.dumps(measure_once(args.child[0], int(args.child[1]), args.front)))
        return
    fams = [f for f in args.families.split(",") if f]
    sizes = [int(s) for s in args.sizes.split(",") if s]
    results = {(f, n): [] for f in fams for n in sizes}
    for _ in range(args.repeat):          # interleaved: every size once per round
        for f in fams:
            for n in sizes:
                results[(f, n)].append(_child(f, n, args.front))
    for f in fams:
        print(_table(f, [results[(f, n)] for n in sizes]))
        print()
    if args.json:
        with open(args.json, "w") as fh:
            json.dump([r for reps in results.values() for r in reps], fh, indent=1)


if __name__ == "__main__":
    main()
