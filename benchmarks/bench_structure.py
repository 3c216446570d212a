"""Scaling of the integer structural passes on chains of constrained bodies.

Models (built directly as Structures, no symbolic layer):

* ``pendulum``: N point masses on rigid massless links, each link
  ``(x_i - x_{i-1})^2 + (y_i - y_{i-1})^2 = L^2`` (index 3; 5 equations per link);
* ``gears``: N inertias coupled by N-1 ideal gears ``phi_{i+1} = n*phi_i``
  (index 3; 3 equations per inertia).

For each N the script times Pantelides, dummy-derivative state selection, the index-1
matching and the BLT sort, and prints ``t / (N log N)``, which stays roughly constant
when the passes scale as N log N.

Usage: ``python benchmarks/bench_structure.py [N ...]``.
"""
from __future__ import annotations

import math
import sys
import time

from acausal.compiler.blt import blt
from acausal.compiler.graph import LINEAR_CONST as C, LINEAR_PARAM as P
from acausal.compiler.graph import LINEAR_VAR as V, NONLINEAR as N
from acausal.compiler.pantelides import pantelides
from acausal.compiler.states import index1_matching, select_states
from acausal.compiler.structure import make_structure

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


def run(build, n: int) -> tuple:
    """Time the passes on ``build(n)``; return (seconds, number of states, blocks)."""
    s = build(n)
    t0 = time.perf_counter()
    p = pantelides(s)
    sel = select_states(p)
    _, eq_to_var = index1_matching(p, sel)
    blocks = blt(p.structure, eq_to_var)
    return time.perf_counter() - t0, len(sel.states), len(blocks)


def main(sizes: list) -> None:
    print(f"{'model':9s} {'N':>6s} {'eqs':>7s} {'time [s]':>9s} {'states':>7s} "
          f"{'blocks':>7s} {'t/(N log N) [us]':>17s}")
    for name, build in (("pendulum", pendulum_chain), ("gears", gear_chain)):
        for n in sizes:
            t, states, blocks = run(build, n)
            eqs = build(n).n_eqs
            print(f"{name:9s} {n:6d} {eqs:7d} {t:9.3f} {states:7d} {blocks:7d} "
                  f"{1e6 * t / (n * math.log(n)):17.2f}")


if __name__ == "__main__":
    main([int(a) for a in sys.argv[1:]] or [100, 300, 1000, 3000])
