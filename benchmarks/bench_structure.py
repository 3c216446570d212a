"""Scaling of the integer structural passes on chains of constrained bodies.

Models (built directly as Structures, no symbolic layer):

* ``pendulum``: N point masses on rigid massless links, each link
  ``(x_i - x_{i-1})^2 + (y_i - y_{i-1})^2 = L^2`` (index 3; 5 equations per link);
* ``gears``: N inertias coupled by N-1 ideal gears ``phi_{i+1} = n*phi_i``
  (index 3; 3 equations per inertia).

For each N the script times Pantelides, dummy-derivative state selection, the index-1
matching and the BLT sort, and prints ``t / (N log N)``, which stays roughly constant
when the passes scale as N log N; then, separately, the tearing of every block.

Usage: ``python benchmarks/bench_structure.py [N ...]``.
"""
from __future__ import annotations

import math
import sys
import time

from acausal.compiler.structure.blt import blt
from acausal.compiler.structure.graph import LINEAR_CONST as C, LINEAR_PARAM as P
from acausal.compiler.structure.graph import LINEAR_VAR as V, NONLINEAR as N
from acausal.compiler.structure.pantelides import pantelides
from acausal.compiler.structure.states import index1_matching, select_states
from acausal.compiler.structure.matching import make_structure
from acausal.compiler.structure.tearing import tear

__all__ = ["pendulum_chain", "gear_chain", "run"]


def _chain_ders(names: list) -> dict:
    return {a: f"der({a})" for a in names}


def pendulum_chain(n: int):
    """Structure of n point masses hanging on a chain of rigid links."""
    eqs, ders = [], {}
    for i in range(1, n + 1):
        x, y, vx, vy, lam = f"x{i}", f"y{i}", f"vx{i}", f"vy{i}", f"lam{i}"
        ders.update(_chain_ders([x, y, vx, vy]))
        fx = {f"der({vx})": P, lam: V, x: V}
        fy = {f"der({vy})": P, lam: V, y: V}
        c = {x: N, y: N}
        if i < n:                       # the next link pulls back on this mass
            fx.update({f"lam{i + 1}": V, f"x{i + 1}": V})
            fy.update({f"lam{i + 1}": V, f"y{i + 1}": V})
        if i > 1:
            c.update({f"x{i - 1}": N, f"y{i - 1}": N})
        eqs += [{f"der({x})": C, vx: C}, {f"der({y})": C, vy: C}, fx, fy, c]
    return make_structure(eqs, derivatives=ders)


def gear_chain(n: int):
    """Structure of n inertias coupled by n-1 ideal gears."""
    eqs, ders = [], {}
    for i in range(1, n + 1):
        phi, w = f"phi{i}", f"w{i}"
        ders.update(_chain_ders([phi, w]))
        m = {f"der({w})": P}
        if i > 1:
            m[f"tau{i - 1}"] = P
        if i < n:
            m[f"tau{i}"] = C
        eqs += [{f"der({phi})": C, w: C}, m]
        if i < n:
            eqs.append({f"phi{i + 1}": C, phi: P})
    return make_structure(eqs, derivatives=ders)


def run(build, n: int) -> dict:
    """Time the passes on ``build(n)``."""
    s = build(n)
    t0 = time.perf_counter()
    p = pantelides(s)
    sel = select_states(p)
    _, eq_to_var = index1_matching(p, sel)
    blocks = blt(p.structure, eq_to_var)
    t1 = time.perf_counter()
    tears = [tear(p.structure, b.eqs, b.vars) for b in blocks if len(b.eqs) > 1]
    t2 = time.perf_counter()
    return {"eqs": s.n_eqs, "time": t1 - t0, "states": len(sel.states),
            "blocks": len(blocks), "largest": max(len(b.eqs) for b in blocks),
            "tear_time": t2 - t1, "iteration_vars": sum(len(t.iteration_vars) for t in tears)}


def main(sizes: list) -> None:
    print(f"{'model':9s} {'N':>6s} {'eqs':>7s} {'time [s]':>9s} {'t/(N log N) [us]':>17s} "
          f"{'states':>7s} {'blocks':>7s} {'largest':>8s} {'tearing [s]':>12s} "
          f"{'iter vars':>10s}")
    for name, build in (("pendulum", pendulum_chain), ("gears", gear_chain)):
        for n in sizes:
            r = run(build, n)
            print(f"{name:9s} {n:6d} {r['eqs']:7d} {r['time']:9.3f} "
                  f"{1e6 * r['time'] / (n * math.log(n)):17.2f} {r['states']:7d} "
                  f"{r['blocks']:7d} {r['largest']:8d} {r['tear_time']:12.3f} "
                  f"{r['iteration_vars']:10d}")


if __name__ == "__main__":
    main([int(a) for a in sys.argv[1:]] or [100, 300, 1000, 3000])
