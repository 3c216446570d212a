"""A failed step in the user's words: what :func:`acausal.solvers.integrate` raises.

The integrator knows rows and columns; the problem knows names (solver contract items 7
and 10).  A singular or non-finite iteration matrix names its equations and variables;
a step that fails because the residual itself is undefined at the last accepted point
names those equations; a step that fails the error or Newton test names the
components with the largest weighted errors.
"""
from __future__ import annotations

import numpy as np

from .base import equation_label
from .bdf import StepFailure

__all__ = ["failure_message"]

_N_NAMED = 3      # variables named where the weighted errors are largest


def failure_message(problem, solver, exc: StepFailure) -> tuple:
    """(message, t, variables named) of the step failure ``exc`` of ``solver``."""
    names = problem.names
    if exc.kind == "singular":
        variables = [names[c] for c in exc.cols]
        equations = [equation_label(problem, r) for r in exc.rows]
        if "non-finite" in str(exc):
            # not a structural matter: a derivative that is infinite there
            msg = (f"the iteration matrix has non-finite entries at t={exc.t:.10g}: "
                   f"the derivatives of equations {equations} with respect to "
                   f"{variables} are not finite (a function at the edge of its "
                   f"domain, such as sqrt(x) at x = 0, or a division by a variable "
                   f"that reached 0)")
        else:
            msg = (f"singular iteration matrix at t={exc.t:.10g}: variables "
                   f"{variables}, equations {equations} (a higher-index or "
                   f"structurally singular model, or a singular configuration of it)")
        return msg, exc.t, variables
    undefined = _non_finite_residuals(problem, solver)
    if undefined:
        msg = (f"the residuals of equations {undefined} are not finite at "
               f"t={solver.t:.10g} (an undefined value where the solution is: "
               f"a division by zero or a function outside its domain, possibly in "
               f"the branch of an if-expression or min/max that was just taken)")
        return msg, exc.t, []
    variables = _dominant(problem, exc.weighted)
    what = {"step_size": "step size too small",
            "error_test": "repeated local error test failures",
            "newton": "repeated corrector (Newton) convergence failures"}.get(
                exc.kind, exc.kind)
    ahead = _undefined_ahead(problem, solver, exc.h)
    if ahead is not None:
        msg = (f"{what} at t={exc.t:.10g} (h={exc.h:.3g}); the largest weighted errors "
               f"are in {variables}. Just after it the model is undefined ({ahead}): the "
               f"solution leaves the domain of a function there")
        return msg, exc.t, variables
    msg = (f"{what} at t={exc.t:.10g} (h={exc.h:.3g}); the largest weighted errors "
           f"are in {variables}. The solution may blow up, be non-smooth, or the "
           f"model may switch without an event there")
    return msg, exc.t, variables


def _undefined_ahead(problem, solver, h) -> str | None:
    """What fails when the residual is evaluated a little past the last accepted point,
    along its derivative (a function outside its domain: log of a negative, the
    equation named by ``problem.evaluation_errors``), or None.  The step that failed
    tried such points; the compiled loop's C code computes NaN there without a word."""
    errors = getattr(problem, "evaluation_errors", None)
    if solver is None or errors is None:
        return None
    t0, y, yp = solver.t, np.asarray(solver.y, float), np.asarray(solver.yp, float)
    dt = max(abs(h), 8 * np.finfo(float).eps * max(1.0, abs(t0)))
    # the notes of the failed step may say the same words: set them aside to see these
    kept = list(errors)
    errors.clear()
    try:
        for _ in range(12):
            try:
                with np.errstate(all="ignore"):
                    r = np.asarray(problem.residual(t0 + dt, y + dt * yp, yp), float)
            except Exception:  # noqa: BLE001 - the failure is reported as it was
                return None
            if errors:
                return errors[-1]
            if not np.all(np.isfinite(r)):
                rows = [equation_label(problem, i) for i in np.flatnonzero(~np.isfinite(r))]
                return f"equations {rows[:3]} are not finite at t = {t0 + dt:.10g}"
            dt *= 10.0
            if dt > 1e-6 * max(1.0, abs(t0)):
                break
        return None
    finally:
        errors[:] = kept + [e for e in errors if e not in kept]


def _non_finite_residuals(problem, solver) -> list:
    """The equations whose residual is NaN or infinite at the last accepted point
    (a failed step leaves the solver there): no step can succeed from there."""
    if solver is None:
        return []
    try:
        with np.errstate(all="ignore"):
            r = np.asarray(problem.residual(solver.t, solver.y, solver.yp), float)
    except Exception:   # a residual that raises is reported by the step failure
        return []
    return [equation_label(problem, i) for i in np.flatnonzero(~np.isfinite(r))]


def _dominant(problem, weighted) -> list:
    if weighted is None:
        return []
    v = np.nan_to_num(np.abs(weighted), nan=np.inf)
    order = np.argsort(-v, kind="stable")[:_N_NAMED]
    return [problem.names[i] for i in order if v[i] > 0]
