"""Compile and run times of the n-mass pendulum chain, in two forms
(``acausal.library.multibody.examples.pendulums``):

* ``PendulumChain``: revolute joints, bars and bodies; the joint angles are the states;
* ``PointMassChain`` (``--point-masses``): the DAE notes' point masses on rods, one
  distance constraint per rod, the states chosen at run time.

For each n the script prints the size of the flattened model, the compile time (the
passes and the sympy code generation, split as the index report times them), the time
to simulate the chain's stop time (2 s, released horizontally) at rtol 1e-6, and the
largest drift of the total energy relative to the potential energy of the full fall
(g (1 + 2 + ... + n) for unit masses and lengths).

Usage: ``python benchmarks/bench_multibody.py [--point-masses] [n ...]``
(default 2 5 10 20 50).
"""
from __future__ import annotations

import sys
import time

import numpy as np

import acausal as ac
from acausal.library.multibody.examples.pendulums import PendulumChain, PointMassChain

__all__ = ["run"]

G = 9.81


def _energy(res, n: int, point_masses: bool) -> np.ndarray:
    mass = "masses[{}]" if point_masses else "links[{}].mass"
    return sum(0.5 * (res[mass.format(i) + ".vx"]**2 + res[mass.format(i) + ".vy"]**2)
               + G * res[mass.format(i) + ".y"] for i in range(n))


def run(sizes=(2, 5, 10, 20, 50), rtol: float = 1e-6, point_masses: bool = False) -> list:
    """Time compile and simulation for each chain length; return the rows printed."""
    rows = []
    print(f"{'n':>4} {'equations':>10} {'states':>7} {'compile s':>10} {'codegen s':>10} "
          f"{'run s':>8} {'steps':>6} {'energy drift':>13}")
    for n in sizes:
        t0 = time.perf_counter()
        model = PointMassChain(n) if point_masses else PendulumChain(n)
        compiled = ac.compile(model)
        t1 = time.perf_counter()
        res = ac.simulate(compiled, t_end=model.stop_time, rtol=rtol, atol=rtol,
                          n_points=201)
        t2 = time.perf_counter()
        rep = compiled.report
        codegen = sum(v for k, v in rep.timings.items() if "codegen" in k)
        e = _energy(res, n, point_masses)
        scale = G * sum(i + 1 for i in range(n))     # potential energy drop of the fall
        row = (n, rep.counts["flatten"]["equations"], len(rep.states), t1 - t0, codegen,
               t2 - t1, res.stats["steps"], float(np.max(np.abs(e - e[0])) / scale))
        rows.append(row)
        print(f"{row[0]:>4} {row[1]:>10} {row[2]:>7} {row[3]:>10.2f} {row[4]:>10.2f} "
              f"{row[5]:>8.2f} {row[6]:>6} {row[7]:>13.2e}", flush=True)
    return rows


if __name__ == "__main__":
    args = sys.argv[1:]
    flag = "--point-masses" in args
    run([int(a) for a in args if a != "--point-masses"] or (2, 5, 10, 20, 50), point_masses=flag)
