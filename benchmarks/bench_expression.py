"""Compile time and memory of one inline expression as it grows: 1e3 to 1e6 DAG nodes.

A user writes a long law inline, every intermediate quantity a Python variable holding an
expression (a wheelset's creep forces, say).  The model here is two states,

    der(x) = -x + 1e-3 e_n(x, y, time),    der(y) = -y + x,
    e_0 = x,   e_(k+1) = sin(c_k e_k + y) e_k + cos(e_k - time) d_k,

with c_k and d_k numbers: each step uses ``e_k`` three times, so the expression's DAG
grows by about nine nodes a step while its tree (every shared part counted where it is
used) doubles, and its depth grows by three or four a step.  The compile must take time
and memory linear in the DAG, whatever the tree and the depth
(:mod:`acausal.compiler.frontend.outline`, :mod:`acausal.compiler.algebra.dag`).

Each size is compiled in a fresh Python process (``cache=False``, the unit check off: it
reads the same DAG; the library cache an empty directory of its own, so the C compiler
runs every time), which reports the time to build the expression of plain sympy symbols
(sympy's own constructors: what the model's ``equations()`` costs its user, inside
``flatten``), the compile's wall time (that included), the C compiler's (``cc s``: its
units compiled side by side, partly while the compile goes on) and the generated
source's size, the slowest passes (``report.timings``), its peak resident memory and the
DAG's size, the tree's (as a power of ten) and the depth.  Between successive sizes the
growth exponents of the compile time and of the memory above the interpreter's are

    k = log(t2 / t1) / log(n2 / n1)     (n: DAG nodes; 1 is linear),

the compile's also without ``flatten``, the pass that runs the model's ``equations()``
(sympy's building of the user's expression, the ``build`` column's cost, is in it).

    python benchmarks/bench_expression.py [--steps 110,1100,11000,110000] [--simulate]
"""
from __future__ import annotations

import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
import time

__all__ = ["inline", "InlineLaw", "measure_once", "main"]


def inline(x, y, t, steps: int, sin, cos):
    """e_steps of the module docstring, built from ``sin``/``cos`` of the caller's kind."""
    e = x
    for k in range(steps):
        c = 1.0 + (k % 7) / 10
        d = (k % 3 + 1) / 4
        e = sin(c * e + y) * e + cos(e - t) * d
    return e


def InlineLaw(steps: int):
    """The model of the module docstring, as a user writes it."""
    import acausal as ac

    class InlineLaw(ac.Component):
        x = ac.Variable(start=0.5, fixed=True)
        y = ac.Variable(start=0.1, fixed=True)

        def equations(self):
            e = inline(self.x, self.y, ac.time, steps, ac.sin, ac.cos)
            return [ac.Eq(ac.der(self.x), -self.x + 1e-3 * e),
                    ac.Eq(ac.der(self.y), -self.y + self.x)]

    return InlineLaw()


def _shape(steps: int) -> dict:
    """DAG nodes, log10 of the tree's nodes and the depth of e_steps (built of sympy
    symbols: the construction is timed as the user's cost), over the DAG."""
    import sympy as sp

    from acausal.compiler.algebra.dag import postorder
    # other names than the model's: sympy's cache would compare the model's expression,
    # built later, with this one as deep as they go (beyond Python's recursion limit)
    x, y, t = sp.symbols("x_shape y_shape t_shape", real=True)
    e = inline(x, y, t, steps, sp.sin, sp.cos)
    nodes = postorder([e])
    log_tree, depth = {}, {}
    for node in nodes:          # log10 of the tree size, without its (huge) integer
        sizes = [log_tree[a] for a in node.args]
        top = max(sizes, default=0.0)
        log_tree[node] = top + math.log10(1 + sum(10 ** (s - top) for s in sizes))
        depth[node] = 1 + max((depth[a] for a in node.args), default=-1)
    return {"dag": len(nodes), "log10_tree": log_tree[e], "depth": depth[e]}


def measure_once(steps: int, simulate: bool) -> dict:
    """Compile ``InlineLaw(steps)`` in this process; times in seconds, memory in MB."""
    import acausal as ac
    t0 = time.perf_counter()
    shape = _shape(steps)       # builds the same expression of sympy symbols
    build = time.perf_counter() - t0
    try:
        import resource
        rss0 = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    except ImportError:         # not on Windows: memory is not reported there
        resource, rss0 = None, float("nan")
    model = InlineLaw(steps)
    t0 = time.perf_counter()
    compiled = ac.compile(model, cache=False, check_units="off")
    total = time.perf_counter() - t0
    rss = (resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0 if resource
           else float("nan"))
    from acausal.native import build as native_build
    row = {"steps": steps, **shape, "build": build, "compile": total,
           "timings": dict(compiled.report.timings), "rss_mb": rss, "rss0_mb": rss0,
           "equations": compiled.report.counts["flatten"]["equations"],
           "cc": dict(native_build.last_build)}
    if simulate:
        res = ac.simulate(compiled, t_end=1.0)
        row["x_end"] = float(res["x"][-1]) if res.success else res.message
    return row


def _child(steps: int, simulate: bool) -> dict:
    cmd = [sys.executable, os.path.abspath(__file__), "--child", str(steps)]
    if simulate:
        cmd.append("--simulate")
    with tempfile.TemporaryDirectory(prefix="acausal-bench-cache-") as cache:
        # no library built by an earlier run: the C compiler's time is measured
        out = subprocess.run(cmd, capture_output=True, text=True, check=False,
                             env=dict(os.environ, ACAUSAL_CACHE=cache))
    if out.returncode != 0:
        raise RuntimeError(f"InlineLaw({steps}) failed:\n{out.stderr[-3000:]}")
    return json.loads(out.stdout.strip().splitlines()[-1])


def _exponent(a: float, b: float, n1: int, n2: int) -> float:
    if not (a > 0 and b > 0) or n1 == n2:
        return float("nan")
    return math.log(b / a) / math.log(n2 / n1)


def _passes(*rows) -> list:
    """The compile's time after ``flatten`` (which runs the model's ``equations()``, where
    sympy builds the user's expression) of each row."""
    return [r["compile"] - r["timings"].get("flatten", 0.0) for r in rows]


def _table(rows: list) -> str:
    head = (f"{'steps':>7} {'DAG':>8} {'tree':>8} {'depth':>7} {'build s':>8} "
            f"{'compile s':>9} {'us/node':>8} {'cc s':>6} {'C MB':>6} {'RSS MB':>7}"
            "  slowest passes (s)")
    lines = [head]
    prev = None
    for r in rows:
        slow = sorted(r["timings"].items(), key=lambda kv: -kv[1])[:4]
        lines.append(f"{r['steps']:>7} {r['dag']:>8} {'1e%d' % round(r['log10_tree']):>8} "
                     f"{r['depth']:>7} {r['build']:>8.2f} {r['compile']:>9.2f} "
                     f"{1e6 * r['compile'] / r['dag']:>8.0f} "
                     f"{r['cc'].get('compile_s', float('nan')):>6.1f} "
                     f"{r['cc'].get('characters', float('nan')) / 1e6:>6.1f} "
                     f"{r['rss_mb']:>7.0f}  "
                     + ", ".join(f"{k} {v:.2f}" for k, v in slow))
        if "x_end" in r:
            lines[-1] += f"  x(1) = {r['x_end']}"
        if prev is not None:
            grow = (r["rss_mb"] - r["rss0_mb"], prev["rss_mb"] - prev["rss0_mb"])
            lines.append(f"{'':>7} exponents: compile "
                         f"{_exponent(prev['compile'], r['compile'], prev['dag'], r['dag']):.2f}"
                         f" (after flatten {_exponent(*_passes(prev, r), prev['dag'], r['dag']):.2f})"
                         f", build {_exponent(prev['build'], r['build'], prev['dag'], r['dag']):.2f}"
                         f", memory {_exponent(grow[1], grow[0], prev['dag'], r['dag']):.2f}")
        prev = r
    return "\n".join(lines)


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steps", default="110,1100,11000,110000",
                    help="steps of the recurrence, one size each (9 DAG nodes a step)")
    ap.add_argument("--simulate", action="store_true", help="also simulate 1 s")
    ap.add_argument("--child", type=int, help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    if args.child is not None:
        print(json.dumps(measure_once(args.child, args.simulate)))
        return
    rows = []
    for steps in (int(s) for s in args.steps.split(",")):
        rows.append(_child(steps, args.simulate))
        print(_table(rows).splitlines()[-1 if len(rows) == 1 else -2:][0], flush=True)
    print()
    print(_table(rows))


if __name__ == "__main__":
    main()
