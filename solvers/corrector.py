"""The BDF corrector: simplified Newton on ``F(t, y_pred + e, y'_pred + cj e) = 0``.

Method
------
IDA's nonlinear solve (Hindmarsh et al. 2005, and the IDA user guide, "Mathematical
considerations"; Brenan, Campbell & Petzold 1996, sec. 5.2): the iteration matrix
``dF/dy + cj dF/dy'`` is factored at a predicted point and kept while ``cj`` stays within
``[(1 - XRATE)/(1 + XRATE), (1 + XRATE)/(1 - XRATE)]`` of the value it was factored
with; a correction computed with an older ``cj`` is scaled by ``2/(1 + cjratio)``; the
iteration stops when the estimated distance to the corrector's solution,
``ss ||delta||`` with ``ss = rate/(1 - rate)`` and ``rate`` the observed contraction,
is below ``EPCON`` of the local error test.

Two rules differ from IDA's; both come from index-reduced mechanical models (the
Cartesian pendulum with dummy derivatives), on which IDA's rules accepted iterates up to
two to three error-test units (weighted RMS) away from the corrector's solution: the
constraint force then carried that noise into the history (its defining relation
lam L^2 = m v^2 - m g y was off by four times the tolerance), and the error test of the
following steps failed on it (16 of 623 steps, all on lam).

* ``ss`` carried from an earlier step is measured by the rate of *that* step's
  iteration, often the one in which the matrix was fresh (a contraction of 1e-6 on a
  mildly nonlinear system).  Some steps later the same matrix is stale and converges
  far more slowly, so a carried ``ss`` counts as at least ``SS_FLOOR`` (that of a
  contraction rate of 1/11): the first correction alone is accepted only if it is
  within ``EPCON/SS_FLOOR`` = 3.3 units of the error test.  (Within one iteration the
  measured rate is used, as in IDA.)  A floor of 0.25 saved a few more pendulum steps
  but cost accuracy on the van der Pol and oscillator problems of tests/solvers, which
  0.1 leaves as they were.
* The norm of the test covers the ``self_scaled`` components (derivatives solved as
  unknowns, solver contract item 6) at their own scale, ``1/(rtol |y_i| + atol_i)``;
  the local error test leaves them out (:mod:`acausal.solvers.bdf`).  Left out of the
  Newton test as well, they can still be far from converged when the other components'
  corrections are small, and the next iterations would have moved those too.  Where
  they cannot converge at that scale -- a derivative at 0 at t0 while moving at 1e6/s,
  held to an absolute tolerance below its own round-off -- their corrections stop
  contracting; then the iterate is accepted by the test without them, which judges them
  through the unknowns they determine, as before.

Glossary (IDA's names): ``cj`` the leading coefficient ``-alpha_s/h``; ``cjold`` the
``cj`` the matrix was factored with; ``cjratio = cj/cjold``; ``ss`` the convergence
factor ``rate/(1 - rate)``; ``ee`` the accumulated correction.
"""
from __future__ import annotations

import math

import numpy as np

from .linalg import iteration_matrix

__all__ = ["NewtonFail", "EPCON", "SS_FLOOR", "setup", "solve_corrector"]

EPCON = 0.33         # Newton tolerance relative to the error test (IDA's epcon)
_MAXCOR = 4          # Newton iterations per attempt (IDA's maxcor)
_RATEMAX = 0.9       # a Newton rate above this is divergence
_XRATE = 0.25        # cj may change by (1-XRATE)/(1+XRATE) .. inverse before re-factoring
SS_FLOOR = 0.1       # least ss credited to a rate carried from an earlier step (rate 1/11)
_TINY = 1e-8         # a first correction this far below the tolerance ends the iteration


class NewtonFail(Exception):
    """The corrector did not converge; ``weighted`` is the last weighted correction."""

    def __init__(self, weighted):
        super().__init__("corrector did not converge")
        self.weighted = weighted


def _wrms(v: np.ndarray, w: np.ndarray) -> float:
    x = v * w
    return math.sqrt(x.dot(x) / x.size)


def setup(bdf, t, y, yp) -> None:
    """Evaluate and factor the iteration matrix at the predicted point."""
    st = bdf.stats
    st.jacobian_evaluations += 1
    J = iteration_matrix(bdf.problem, bdf.lin, t, y, yp, bdf.cj)
    st.lu_factorizations += 1
    bdf.lin.factor(J, bdf.ewt_newton)     # a consistent rank deficiency allowed
    bdf.cjold = bdf.cj
    bdf.cjratio = 1.0
    bdf.ss = 20.0
    bdf.force_setup = False


def solve_corrector(bdf, tnew, ypred, yppred):
    """The correction ``e`` (``y = y_pred + e``, ``y' = y'_pred + cj e``) of the step to
    ``tnew`` (IDA's IDANls); raises :class:`NewtonFail`.  The matrix is re-factored
    when ``cj`` has moved too far, when the step forces it, and once more after a
    failure with a stale one."""
    cj = bdf.cj
    bdf.cjratio = cj / bdf.cjold
    lo = (1.0 - _XRATE) / (1.0 + _XRATE)
    call_setup = bdf.force_setup or not (lo <= bdf.cjratio <= 1.0 / lo)
    if cj != bdf.cjlast:
        bdf.ss = 100.0
    fresh = False
    while True:
        if call_setup:
            setup(bdf, tnew, ypred, yppred)
            fresh = True
        ok, ee, last, fallback = _iterate(bdf, tnew, ypred, yppred, cj)
        if ok:
            if bdf.cjratio != 1.0 and bdf.alg.any():
                ee = _unscaled_correction(bdf, tnew, ypred, yppred, cj, ee)
            return ee
        if fresh:
            if fallback is not None:   # stalled at round-off with an exact matrix
                return fallback
            raise NewtonFail(last)
        call_setup = True   # a stale matrix may be the cause: retry with a new one


def _unscaled_correction(bdf, tnew, ypred, yppred, cj, ee):
    """One more Newton correction, not scaled.  The rows of an algebraic equation do
    not contain cj, so in them the stale matrix is exact and an unscaled correction
    satisfies a linear constraint exactly; the scaled ones leave it off by the factor
    2/(1+cjratio) times the last correction, at every step (a Dirichlet row
    u0 - 1 = 0 drifting off 1 by a few rtol, and dense and sparse LU steering on
    that noise differently)."""
    bdf.stats.residual_evaluations += 1
    bdf.stats.newton_iterations += 1
    delta = bdf.lin.solve(bdf.problem.residual(tnew, ypred + ee, yppred + cj * ee))
    if np.all(np.isfinite(delta)):
        ee = ee - delta
    return ee


def _iterate(bdf, tnew, ypred, yppred, cj):
    """(converged, e, weighted last correction, fallback) of one simplified-Newton
    iteration; ``fallback`` is the iterate the test without the self-scaled components
    accepted (or None), for a caller whose matrix is fresh (module docstring)."""
    st = bdf.stats
    F = bdf.problem.residual
    w = bdf.ewt_newton
    # the test without the self-scaled components, for where they stall (docstring)
    w_rest = bdf.ewt if bdf.self_scaled.any() else None
    # IDA's scalesol: with a matrix factored at cjold, the correction of a
    # differential component is about cjold/cj too large, which 2/(1+cjratio)
    # corrects (on the whole correction: scaling only part of a coupled correction
    # distorts it, and leaves lightly damped modes undamped)
    scale = 2.0 / (1.0 + bdf.cjratio) if bdf.cjratio != 1.0 else 1.0
    ee, fallback = None, None
    first = first_rest = 0.0
    ss0 = bdf.ss
    for m in range(_MAXCOR):
        if ee is None:   # first iterate: the prediction itself
            r = F(tnew, ypred, yppred)
        else:
            r = F(tnew, ypred + ee, yppred + cj * ee)
        st.residual_evaluations += 1
        st.newton_iterations += 1
        delta = bdf.lin.solve(r)
        delta *= -scale           # -J^{-1} F, scaled when J was factored with cjold
        ee = delta if ee is None else ee + delta
        delnrm = _wrms(delta, w)
        if not np.isfinite(delnrm):
            return False, ee, None, None
        if m == 0:
            first = delnrm
            if delnrm <= _TINY * EPCON or max(bdf.ss, SS_FLOOR) * delnrm <= EPCON:
                return True, ee, None, None
        else:
            rate = (delnrm / first) ** (1.0 / m) if first > 0 else 0.0
            if rate > _RATEMAX:
                return False, ee, delta * w, fallback
            bdf.ss = rate / (1.0 - rate)
            if bdf.ss * delnrm <= EPCON:
                return True, ee, None, None
        if w_rest is not None and fallback is None:
            # the same test without them (its own rate), remembered for a caller whose
            # matrix is fresh: if they stall at round-off, this iterate is accepted
            rest = _wrms(delta, w_rest)
            if m == 0:
                first_rest = rest
                ok_rest = rest <= _TINY * EPCON or max(ss0, SS_FLOOR) * rest <= EPCON
            else:
                rate = (rest / first_rest) ** (1.0 / m) if first_rest > 0 else 0.0
                ok_rest = rate <= _RATEMAX and rate / (1.0 - rate) * rest <= EPCON
            if ok_rest:
                fallback = ee.copy()
    return False, ee, delta * w, fallback
