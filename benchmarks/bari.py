"""The DAE problems of the Bari test set: significant correct digits, steps and time.

Run:  python benchmarks/bari.py [--rtol 1e-6 1e-8 1e-10] [--problems CRANK WHEELSET]
                                [--no-ida]

Every problem of ``tests/bari/problems`` -- written as the test set states it (Mazzia &
Magherini, *Test Set for IVP Solvers*, release 2.4, Bari) -- is compiled once and run
at each tolerance (atol = rtol, as the test set's drivers run them).  Printed per run:

* ``scd``: the test set's significant correct digits at the end point against its
  reference solution, over the components its drivers measure, and ``mescd``, the mixed
  error digits its R drivers print (a component small beside atol/rtol judged by its
  absolute error; both in ``tests/bari/testset.py``);
* ``steps`` (accepted) and ``s`` (seconds of the simulation, the compile not included;
  the compile time is printed once per problem);
* the same for SUNDIALS IDA (scikit-sundae, the ``ida`` extra) on the residual acausal
  generates, from the same consistent initial point, where it is installed
  (``tests/bari/ida.py``; a model whose states acausal re-chooses while it runs is
  given the choice made at t0).

A run that does not reach t_end prints its message.  A few runs are left out where
their cost is beyond a benchmark's patience, said in the table: the two-bit adding unit
(350 equations, ~10^4 events at the kinks of its transistor models) is run at the
tolerances its test set uses for it.
"""
from __future__ import annotations

import argparse
import os
import sys
import time
import warnings

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))

from acausal.tests.bari.ida import ida_available, run_ida  # noqa: E402
from acausal.tests.bari.testset import (PROBLEMS, compile_problem, mescd,  # noqa: E402
                                        problem, scd, solve)

RTOLS = (1e-6, 1e-8, 1e-10)


def _cell(ok, digits, mixed, steps, seconds, message="") -> str:
    if not ok:
        return f"{'fails: ' + message[:40]:>35}"
    return f"{digits:6.2f} {mixed:6.2f} {steps:8d} {seconds:8.2f}s"


def run(names, rtols, with_ida: bool) -> None:
    ida = with_ida and ida_available()
    head = f"{'problem':10} {'rtol':>7} | {'acausal: scd  mescd    steps        s':>35}"
    if ida:
        head += f" | {'IDA: scd  mescd    steps        s':>35}"
    print(head)
    print("-" * len(head))
    for name in names:
        prob = problem(name)
        t0 = time.perf_counter()
        compiled = compile_problem(prob)
        build = time.perf_counter() - t0
        print(f"{prob.name:10} compiled in {build:.1f} s, index {prob.index}, "
              f"{len(compiled.states)} states, {compiled.n} unknowns"
              + (", states chosen while it runs" if compiled.dynamic is not None else ""))
        for rtol in rtols:
            if rtol not in prob.bench_rtols:
                print(f"{'':10} {rtol:7.0e} | {'not run (see the module docstring)':>35}")
                continue
            r = solve(compiled, prob, rtol)
            mixed = mescd(r.values, prob, rtol) if r.success else 0.0
            line = (f"{'':10} {rtol:7.0e} | "
                    + _cell(r.success, r.scd, mixed, r.steps, r.seconds, r.message))
            if ida:
                ok, values, steps, seconds, msg = run_ida(compiled, prob.t_end, rtol,
                                                          list(prob.reference))
                line += " | " + (_cell(ok, scd(values, prob), mescd(values, prob, rtol),
                                       steps, seconds) if ok else
                                 _cell(ok, 0.0, 0.0, steps, seconds, msg))
            print(line, flush=True)


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rtol", type=float, nargs="+", default=list(RTOLS))
    ap.add_argument("--problems", nargs="+", default=PROBLEMS.names())
    ap.add_argument("--no-ida", action="store_true")
    args = ap.parse_args(argv)
    warnings.simplefilter("ignore")      # the redundant initial conditions are expected
    run([p.upper() for p in args.problems], args.rtol, not args.no_ida)


if __name__ == "__main__":
    main()
