"""Work counts that once were test assertions: how many steps, factorizations and
seconds a few runs take, printed next to the bound a test used to impose.

Step counts and times depend on rounding (dense and sparse LU round differently, which
moves accept/reject decisions) and on the machine, so the test suite asserts only what
the physics fixes; a performance regression shows up here instead.  Nothing is asserted.

Runs (the problems of ``tests/solvers/problems.py``):

* ``y' = -y`` on [0, 20] at rtol 1e-10: LU factorizations per step (the iteration
  matrix is reused over many steps; once bounded by 1/4);
* the heat equation on 200 nodes at rtol 1e-8, sparse and dense LU: steps of each
  (once required to agree within 10 %);
* 40 undamped oscillators up to 1e5 rad/s on [0, 0.2] at rtol 1e-4 (see
  ``OscillatorChain``): steps with ``max_order=2`` (once < 12 000) and with stability
  limit detection (once < 50 000);
* an undamped oscillator resolved on purpose, with and without stability limit
  detection: the ratio of steps (once <= 1.1);
* Pantelides on the structure of a 300-link pendulum chain: time (once < 2 s).

The comparison of step counts with SUNDIALS IDA is in ``bench_solvers.py``.

Usage: ``python benchmarks/bench_counts.py``.
"""
from __future__ import annotations

import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))

from acausal.compiler.structure.pantelides import pantelides  # noqa: E402
from acausal.solvers import integrate  # noqa: E402
from acausal.tests.solvers.problems import (DampedOscillator, Decay,  # noqa: E402
                                            HeatChain, OscillatorChain)
from bench_structure import pendulum_chain  # noqa: E402

__all__ = ["main"]


def _row(label: str, value: float, former: str, fmt: str = "{:.3g}") -> None:
    print(f"  {label:<52s} {fmt.format(value):>10s}   (test bound was {former})")


def factorizations_per_step() -> None:
    st = integrate(Decay(), (0.0, 20.0), [1.0], rtol=1e-10, atol=1e-12).stats
    print(f"y' = -y, rtol 1e-10: {st.steps} steps, {st.lu_factorizations} LU")
    _row("LU factorizations per step", st.lu_factorizations / st.steps, "< 0.25")


def heat_chain_sparse_and_dense() -> None:
    n = 200
    u0 = np.zeros(n)
    u0[0] = 1.0
    steps = {}
    for sparse in (True, False):
        out = integrate(HeatChain(n, sparse=sparse), (0.0, 1.0), u0, rtol=1e-8, atol=1e-10)
        steps[out.stats.linear_solver] = out.stats.steps
    print(f"heat chain n={n}, rtol 1e-8: steps sparse {steps['sparse']}, "
          f"dense {steps['dense']}")
    _row("steps sparse / dense", steps["sparse"] / steps["dense"], "0.9 .. 1.1")


def oscillator_chain() -> None:
    p = OscillatorChain(N=40, w=5e4, d=0.0, a=20.0)
    print("oscillator chain N=40 on [0, 0.2], rtol 1e-4:")
    for label, options, former in (("steps, max_order=2", {"max_order": 2}, "< 12000"),
                                   ("steps, stald=True", {"stald": True}, "< 50000")):
        out = integrate(p, (0.0, 0.2), *p.initial(), rtol=1e-4, atol=1e-6, **options)
        _row(label, out.stats.steps, former, "{:.0f}")


def stald_on_a_resolved_oscillation() -> None:
    p = DampedOscillator(w=2.0, zeta=0.0)
    runs = [integrate(p, (0.0, 20.0), [1.0, 0.0], [0.0, -4.0], rtol=1e-6, atol=1e-8,
                      stald=stald) for stald in (False, True)]
    print(f"resolved oscillator, rtol 1e-6: steps {runs[0].stats.steps} without, "
          f"{runs[1].stats.steps} with stald")
    _row("steps with / without stald", runs[1].stats.steps / runs[0].stats.steps, "<= 1.1")


def pantelides_on_a_long_chain(n: int = 300) -> None:
    structure = pendulum_chain(n)
    t0 = time.perf_counter()
    pantelides(structure)
    elapsed = time.perf_counter() - t0
    print(f"Pantelides, pendulum chain of {n} links ({structure.n_eqs} equations):")
    _row("time [s]", elapsed, "< 2 s")


def main() -> None:
    for run in (factorizations_per_step, heat_chain_sparse_and_dense, oscillator_chain,
                stald_on_a_resolved_oscillation, pantelides_on_a_long_chain):
        run()
        sys.stdout.flush()


if __name__ == "__main__":
    main()
