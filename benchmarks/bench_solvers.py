"""Benchmark of the acausal BDF against scipy's BDF (and SUNDIALS IDA when installed).

Run:  python benchmarks/bench_solvers.py [--rtol 1e-4 1e-6 1e-8]

Problems (same tolerances for every solver, analytic Jacobians everywhere):

* Van der Pol, mu = 1000, y1' = y2, y2' = mu((1 - y1^2) y2 - y1) on [0, 3] (two periods,
  four fast jumps), and the classic form y2' = mu (1 - y1^2) y2 - y1 on [0, 3000];
* Robertson's kinetics on [0, 4e5]: a DAE (conservation law as the third equation) for
  acausal and IDA, the ODE form for scipy (which has no DAE solver);
* a damped oscillator on [0, 10];
* a chain of 40 undamped oscillators (modes up to 1e5 rad/s) moved slowly at one end,
  on [0, 0.2]: the high modes, excited to about the tolerance, are not damped by BDF
  orders 3-5.  Also run with stability limit detection (``stald=True``) and with
  ``max_order=2``.

Printed per problem and tolerance: accepted steps, residual (right-hand side)
evaluations, Jacobian evaluations, wall time, and the ratios acausal/scipy and
acausal/IDA.  IDA (``scikit-sundae``) is optional and skipped when not importable.
"""
from __future__ import annotations

import argparse
import os
import sys
import time

import numpy as np
from scipy.integrate import solve_ivp

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))

from acausal.solvers import integrate  # noqa: E402
from acausal.tests.solvers.problems import (DampedOscillator,  # noqa: E402
                                            OscillatorChain, Robertson, VanDerPol,
                                            VanDerPolClassic)

try:
    from sksundae.ida import IDA
except ImportError:  # optional
    IDA = None


def _cases():
    vdp = VanDerPol(1000.0)
    classic = VanDerPolClassic(1000.0)
    rob = Robertson()
    osc = DampedOscillator()
    chain = OscillatorChain(N=40, w=5e4, d=0.0, a=20.0)
    rob_atol = np.array([1e-8, 1e-14, 1e-8])
    return [
        ("Van der Pol mu=1000 [0,3]", vdp, (0.0, 3.0), [2.0, 0.0], [0.0, -2000.0],
         1e-8, vdp.ode, vdp.ode_jac, None),
        ("Van der Pol classic mu=1000 [0,3000]", classic, (0.0, 3000.0), [2.0, 0.0],
         [0.0, -2.0], 1e-8, classic.ode, classic.ode_jac, None),
        ("Robertson DAE [0,4e5]", rob, (0.0, 4e5), [1.0, 0.0, 0.0], [-0.04, 0.04, 0.0],
         rob_atol, rob.ode, rob.ode_jac, [2]),
        ("damped oscillator [0,10]", osc, (0.0, 10.0), [1.0, 0.0], [0.0, -4.0],
         1e-8, osc.ode, lambda t, y: [[0.0, 1.0], [-4.0, -0.4]], None),
        ("oscillator chain N=40 [0,0.2]", chain, (0.0, 0.2), *chain.initial(), 1e-6,
         chain.ode, chain.ode_jac, [0]),
    ]


REPEATS = 3   # wall time is the best of this many runs (the machine may be shared)


def _timed(fn):
    best, result = np.inf, None
    for _ in range(REPEATS):
        t0 = time.perf_counter()
        result = fn()
        best = min(best, time.perf_counter() - t0)
    return result, best


def run_ours(p, span, y0, yp0, rtol, atol, **options):
    out, dt = _timed(lambda: integrate(p, span, y0, yp0, rtol=rtol, atol=atol,
                                       **options))
    s = out.stats
    return s.steps, s.residual_evaluations, s.jacobian_evaluations, dt, out.y[-1]


def run_scipy(fun, jac, span, y0, rtol, atol):
    sol, dt = _timed(lambda: solve_ivp(fun, span, y0, method="BDF", rtol=rtol,
                                       atol=atol, jac=jac))
    return sol.t.size - 1, sol.nfev, sol.njev, dt, sol.y[:, -1]


def run_ida(p, span, y0, yp0, rtol, atol, alg):
    def res(t, y, yp, r):
        r[:] = p.residual(t, y, yp)

    def jac(t, y, yp, r, cj, JJ):
        JJ[:, :] = p.jacobian(t, y, yp, cj)

    solver = IDA(res, rtol=rtol, atol=atol, jacfn=jac, algebraic_idx=alg,
                 max_num_steps=10 ** 7)
    sol, dt = _timed(lambda: solver.solve(list(span), np.array(y0, float),
                                          np.array(yp0, float)))
    return len(sol.t) - 1, sol.nfev, sol.njev, dt, sol.y[-1]


def _row(name, r):
    steps, nres, njac, dt, _ = r
    return f"    {name:<8} {steps:7d} {nres:9d} {njac:5d} {dt * 1e3:9.1f} ms"


def _ratios(ours, other, label):
    return (f"   {label}: steps x{ours[0] / other[0]:.2f}, residuals "
            f"x{ours[1] / other[1]:.2f}, time x{ours[3] / other[3]:.2f}")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rtol", type=float, nargs="+", default=[1e-4, 1e-6, 1e-8])
    args = ap.parse_args(argv)
    print("IDA (scikit-sundae):", "available" if IDA is not None else "not installed")
    print("    solver     steps  residuals  jacs      time")
    warm = _cases()[0]
    run_ours(warm[1], (0.0, 0.1), warm[3], warm[4], 1e-4, warm[5])   # imports, caches
    for name, p, span, y0, yp0, atol, fun, jac, alg in _cases():
        for rtol in args.rtol:
            print(f"{name}, rtol={rtol:.0e}")
            ours = run_ours(p, span, y0, yp0, rtol, atol)
            sci = run_scipy(fun, jac, span, y0, rtol, atol)
            print(_row("acausal", ours))
            if isinstance(p, OscillatorChain):
                for label, opt in [("stald", {"stald": True}),
                                   ("maxord2", {"max_order": 2})]:
                    print(_row(label, run_ours(p, span, y0, yp0, rtol, atol, **opt)))
            print(_row("scipy", sci) + _ratios(ours, sci, "acausal/scipy"))
            if IDA is not None:
                ida = run_ida(p, span, y0, yp0, rtol, atol, alg)
                print(_row("IDA", ida) + _ratios(ours, ida, "acausal/IDA"))

if __name__ == "__main__":
    main()
