"""The first step of the BDF integrator (:mod:`acausal.solvers.bdf`), at t0 and after
events.

* :func:`initial_step`: IDA's rule (Hindmarsh et al., SUNDIALS IDA user guide, the
  initial step): 0.001 of the interval, at most 0.5/||y'0||_wrms.
* :func:`probed_step`: after an event, one trial backward-Euler step (docstring below).
"""
from __future__ import annotations

import math

import numpy as np

from .linalg import iteration_matrix

__all__ = ["initial_step", "probed_step"]


def _wrms(v: np.ndarray, w: np.ndarray) -> float:
    x = v * w
    return math.sqrt(x.dot(x) / x.size)


def initial_step(bdf) -> float:
    """IDA's first step: 0.001 of the interval, and at most 0.5/||y'0||_wrms."""
    span = bdf.t_stop - bdf.tn if np.isfinite(bdf.t_stop) else 1.0
    h = 1e-3 * abs(span) if span > 0 else 1e-6
    ypnorm = _wrms(bdf.yp, bdf.ewt_err)
    if ypnorm > 0.5 / h:
        h = 0.5 / ypnorm
    return h


def probed_step(bdf, h0: float) -> float:
    """First step from one trial backward-Euler step of size ``h0``.

    IDA's heuristic bounds only the first-order change ``h ||y'||``, while the
    error of the first (order-1) step is ``h^2 ||y''|| / 2``: after an event at a
    tight tolerance it starts far too small and the step then needs many doublings,
    each with a new iteration matrix.  One corrector iteration from the predictor
    ``(y + h0 y', y')`` gives the correction ``d ~ h0^2 y''`` for the differential
    components (and ``h0 y'`` for the algebraic ones, whose derivative it also
    supplies, so that the predictor of the real first step is second order too);
    the step is then chosen for an error of about 1/8 of the tolerance, never
    below ``h0`` nor above the IDA bound ``0.001 |t_stop - t|``.
    """
    p, st = bdf.problem, bdf.stats
    t1, y1 = bdf.tn + h0, bdf.y + h0 * bdf.yp
    try:
        st.jacobian_evaluations += 1
        st.lu_factorizations += 1
        bdf.lin.factor(iteration_matrix(p, bdf.lin, t1, y1, bdf.yp, 1.0 / h0))
        st.residual_evaluations += 1
        d = -bdf.lin.solve(p.residual(t1, y1, bdf.yp))
    except Exception:   # only an estimate: the real first step will report it
        return h0
    alg = np.asarray(p.algebraic, bool)
    if alg.all() or not np.all(np.isfinite(d)):
        return h0
    dif_err = _wrms(np.where(alg, 0.0, d), bdf.ewt)
    bdf.yp = bdf.yp + np.where(alg, d / h0, 0.0)
    span = bdf.t_stop - bdf.tn if np.isfinite(bdf.t_stop) else np.inf
    # y'' = 0 (a linear stretch): only the IDA interval bound applies
    h = 0.5 * h0 / math.sqrt(dif_err) if dif_err > 0.0 else np.inf
    return float(max(min(h, 1e-3 * span, bdf.max_step), h0))
