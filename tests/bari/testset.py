"""The DAE problems of the Bari test set, as acausal models, and its measure of accuracy.

F. Mazzia and C. Magherini, *Test Set for Initial Value Problem Solvers*, release 2.4,
Department of Mathematics, University of Bari, 2008 (www.dm.uniba.it/~testset): each
problem is given as Fortran (``Ex_*.f`` in the R package deTestSet, rforge ``bvpsolve``
``pkg/deTestSet/src``; the drivers of the MEBDFI runs in ``fons/JavaOdeInt``
``fodeint/mebdfi/txt``) with its parameters, consistent initial values and a reference
solution at the end point computed at very tight tolerances.

Every model under ``problems/`` is the problem written the way the test set states it:
the same unknowns, the same equations (matrices written out as the Fortran assembles
them, no hand reduction of the index, no ``state_select`` hints), the test set's initial
values as start values and, on every component whose derivative the formulation
contains, as ``fixed=True`` initial conditions -- as the test set's y(0) fixes them.
Where a formulation fixes more components than it has degrees of freedom, the extra
conditions are redundant (consistent, since the test set's y(0) is); acausal checks and
drops them (:mod:`acausal.runtime.redundant`).

Accuracy is the test set's *significant correct digits* at the end point,

    scd = -log10( max_i |y_i - yref_i| / |yref_i| ),

over the components the test set uses (its drivers' ``SKIPI``: the positions only for
the index-3 mechanisms ANDREWS and CRANK (R driver) and FEKETE, the output nodes of
NAND and the two-bit adder, all but y9 of the charge pump) whose reference is not zero;
and beside it the *mixed error* significant correct digits that the test set's R
drivers print for a run at ``rtol``, ``atol`` (deTestSet, ``printpr`` in
``pkg/deTestSet/R/functions.R``; ``ex_crank.R``),

    mescd = -log10( max_i |y_i - yref_i| / (atol/rtol + |yref_i|) ),

over the same components: a component small beside ``atol/rtol`` is judged by its
absolute error, as the tolerance asked for it.
"""
from __future__ import annotations

import importlib
import time
from dataclasses import dataclass, field

import numpy as np

__all__ = ["BariProblem", "PROBLEMS", "problem", "scd", "mescd", "solve", "Run"]

# the modules under problems/, in the test set's order of DAE problems
_MODULES = ("chemakzo", "andrews", "caraxis", "crank", "fekete", "pump", "transamp",
            "tube", "twobit", "wheelset", "nand")


@dataclass
class BariProblem:
    """One problem of the test set.

    ``reference``: the test set's solution at ``t_end`` by acausal name, in the test
    set's order; ``scd_names``: the components its scd uses (default: all); ``rtol``:
    the tolerance the test suite checks it at, with ``min_scd`` the digits it must give
    there (each set from the reference's own accuracy, said in the module);
    ``simulate``: extra ``ac.simulate`` options (none of them tighten the tolerance);
    ``bench_rtols``: the tolerances the benchmark runs it at."""

    name: str
    title: str
    model: type
    t_end: float
    reference: dict
    index: int
    scd_names: list = None
    rtol: float = 1e-8
    min_scd: float = 5.0
    simulate: dict = field(default_factory=dict)
    note: str = ""
    bench_rtols: tuple = (1e-6, 1e-8, 1e-10)     # benchmarks/bari.py runs these

    def __post_init__(self):
        if self.scd_names is None:
            self.scd_names = list(self.reference)


def problem(name: str) -> BariProblem:
    """The problem by its test-set name (case-insensitive)."""
    mod = importlib.import_module(f"{__package__}.problems.{name.lower()}")
    return mod.PROBLEM


def _all():
    return [problem(m) for m in _MODULES]


class _Problems:
    """``PROBLEMS``: every problem, imported on first use."""

    def __iter__(self):
        return iter(_all())

    def names(self):
        return [m.upper() for m in _MODULES]


PROBLEMS = _Problems()


def scd(values: dict, prob: BariProblem) -> float:
    """The test set's significant correct digits of ``values`` (name -> value at t_end)."""
    errs = [abs(values[k] - prob.reference[k]) / abs(prob.reference[k])
            for k in prob.scd_names if prob.reference[k] != 0.0]
    worst = max(errs)
    return float("inf") if worst == 0.0 else float(-np.log10(worst))


def mescd(values: dict, prob: BariProblem, rtol: float, atol: float = None) -> float:
    """The test set's mixed-error significant correct digits of ``values`` for a run at
    ``rtol`` and ``atol`` (default ``rtol``, as its drivers run)."""
    ratio = 1.0 if atol is None else atol / rtol
    worst = max(abs(values[k] - prob.reference[k]) / (ratio + abs(prob.reference[k]))
                for k in prob.scd_names)
    return float("inf") if worst == 0.0 else float(-np.log10(worst))


@dataclass
class Run:
    """One simulation of a problem: success, scd, accepted steps, seconds (the
    simulation, without the compile), the final values and the message."""

    success: bool
    scd: float
    steps: int
    seconds: float
    values: dict
    message: str = ""


def final_values(res, names) -> dict:
    return {k: float(res[k][-1]) for k in names}


def solve(compiled, prob: BariProblem, rtol: float) -> Run:
    """Simulate ``compiled`` (the problem's model) to ``t_end`` at ``rtol`` (atol = rtol,
    as the test set's drivers run it) and measure it."""
    import acausal as ac
    t0 = time.perf_counter()
    res = ac.simulate(compiled, t_end=prob.t_end, rtol=rtol, n_points=2, **prob.simulate)
    seconds = time.perf_counter() - t0
    steps = int(res.stats["steps"])
    if not res.success:
        return Run(False, float("nan"), steps, seconds, {}, res.message)
    values = final_values(res, prob.reference)
    return Run(True, scd(values, prob), steps, seconds, values)


def compile_problem(prob: BariProblem, **options):
    import acausal as ac
    return ac.compile(prob.model(), check_units="off", **options)
