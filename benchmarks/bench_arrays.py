"""Compile time of a mass-spring chain written with array variables against the same
chain built from N Mass and N Spring components of the translational library
(``tests/models/array_models.py``), and the time of one simulation of each.

Both flatten to the same scalar equations up to the connection equations and aliases of
the component form (the array form has no ports), so the difference is the cost of the
instance tree and of alias elimination.  Times are measured in this process, after one
small compile that loads the compiler; the compile cache is off.

    python benchmarks/bench_arrays.py [N ...]       (default N = 1000)
"""
from __future__ import annotations

import sys
import time

import acausal as ac
from acausal.tests.models.array_models import (ArrayChain, ComponentChain, chain_masses,
                                               chain_start, chain_stiffnesses)


def _array_chain(n):
    return ArrayChain(n, m=chain_masses(n), c=chain_stiffnesses(n),
                      s={"start": chain_start(n)})


def _time_compile(model, backend):
    t0 = time.perf_counter()
    compiled = ac.compile(model, backend=backend, cache=False)
    return time.perf_counter() - t0, compiled


def main(sizes, backend="numpy"):
    _time_compile(_array_chain(3), backend)          # loads sympy, scipy, the compiler
    _time_compile(ComponentChain(3), backend)
    for n in sizes:
        for name, make in (("arrays", _array_chain), ("components", ComponentChain)):
            seconds, compiled = _time_compile(make(n), backend)
            passes = ", ".join(f"{k} {v:.2f}" for k, v in compiled.report.timings.items()
                               if v >= 0.05)
            t0 = time.perf_counter()
            ac.simulate(compiled, t_end=0.1, rtol=1e-6, raise_on_failure=True)
            run = time.perf_counter() - t0
            print(f"N = {n:5d}  {name:10s}  compile {seconds:6.2f} s  "
                  f"({len(compiled.states)} states; {passes})  simulate 0.1 s: {run:.2f} s")


if __name__ == "__main__":
    main([int(a) for a in sys.argv[1:]] or [1000])
