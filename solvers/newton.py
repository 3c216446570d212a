"""Damped Newton for nonlinear algebraic systems, with a homotopy fallback.

Used for consistent initialization and re-initialization after events, where a
single, accurate solve is wanted (a full Newton method: the Jacobian is re-evaluated
every iteration).  The damping is a backtracking line search on the row-scaled
residual norm ``||D G(x)||`` with an Armijo-type sufficient-decrease test (Dennis &
Schnabel 1996, ch. 6), in the spirit of the line search of IDA's ``IDACalcIC`` (Brown,
Hindmarsh & Petzold 1998).

When damped Newton fails from the given guess, :func:`homotopy` follows the Newton
(global) homotopy ``H(x, lam) = G(x) - (1 - lam) G(x0)`` from ``lam = 0``, where ``x0``
is a solution, to ``lam = 1`` (Allgower & Georg 1990, ch. 1), correcting with
Newton at each ``lam`` and adapting the ``lam`` step.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .linalg import SPARSE_THRESHOLD, LinearSolver, SingularMatrixError, issparse

__all__ = ["NewtonResult", "damped_newton", "homotopy"]

# A weighted step that no longer contracts is accepted below this size (a tenth of the
# error scale the weights describe)
_STALL_FLOOR = 0.1


@dataclass
class NewtonResult:
    """Outcome of :func:`damped_newton` / :func:`homotopy`.

    ``x`` is the last iterate, ``residual`` ``G(x)``, ``step`` the last weighted Newton
    step (componentwise, for naming what did not converge).
    """

    x: np.ndarray
    converged: bool
    iterations: int
    residual: np.ndarray
    step: np.ndarray
    message: str = ""
    evaluations: int = 0


def _rms(v: np.ndarray) -> float:
    return float(np.sqrt(np.mean(v * v))) if v.size else 0.0


def _solve(J, b: np.ndarray, singular_ok: bool = False) -> np.ndarray:
    """Solve J dx = b: LU when square, least squares (minimum norm) otherwise.

    ``singular_ok``: a square J that LU finds singular is solved in the least-squares
    sense too (rows equilibrated), so that a point that already solves a system whose
    Jacobian is singular there -- node charges given with potentials that only the
    charges' balance relates, q = g(U) with dg/dU singular -- is kept; the caller
    checks the residual (:func:`damped_newton`)."""
    m, n = J.shape
    if n == 0:   # nothing unknown (a model without states at steady state)
        return np.zeros(0)
    if m == n:
        lin = LinearSolver(n, issparse(J) and n > SPARSE_THRESHOLD)
        try:
            lin.factor(J)
        except SingularMatrixError:
            if not singular_ok or n > _LSTSQ_LIMIT:
                raise
            A = J.toarray() if issparse(J) else np.asarray(J)
            _finite(A, b)
            D = _row_scale(J)
            return np.linalg.lstsq(A * D[:, None], b * D, rcond=None)[0]
        return lin.solve(b)
    A = J.toarray() if issparse(J) else np.asarray(J)
    _finite(A, b)
    return np.linalg.lstsq(A, b, rcond=None)[0]


def _finite(A, b) -> None:
    """A least-squares solve needs finite numbers: LAPACK's SVD does not converge on a
    NaN (numpy's LinAlgError); a non-finite Jacobian or residual is a singular system."""
    if not (np.all(np.isfinite(A)) and np.all(np.isfinite(b))):
        raise SingularMatrixError("the Jacobian or the residual has non-finite entries")


_LSTSQ_LIMIT = 4000      # a singular square Jacobian up to this size is solved by lstsq
_CONSISTENT = 1e-10      # ... and the point accepted where its row-scaled residual is below


def _row_scale(J) -> np.ndarray:
    a = abs(J).max(axis=1)
    a = a.toarray().ravel() if issparse(a) else np.asarray(a).ravel()
    return 1.0 / np.where(a > 0, a, 1.0)


def damped_newton(fun, jac, x0, *, weights=None, tol: float = 1e-6, max_iter: int = 50,
                  min_damping: float = 1e-6) -> NewtonResult:
    """Solve ``fun(x) = 0`` by Newton's method with backtracking.

    Parameters
    ----------
    fun : callable ``x -> ndarray(m)``
    jac : callable ``x -> ndarray | sparse (m, n)``
    x0 : array_like
        Initial guess.
    weights : callable ``x -> ndarray(n)`` or ndarray or None
        Error weights (``1/(rtol |x| + atol)``); convergence is
        ``||dx * w||_rms <= tol``.  None means unit weights.
    tol : float
        Tolerance on the weighted step.
    max_iter : int
        Newton iterations allowed.
    min_damping : float
        Smallest line-search factor before declaring failure.

    Returns
    -------
    NewtonResult

    Raises
    ------
    SingularMatrixError
        If the Jacobian is singular at an iterate.
    """
    x = np.array(x0, dtype=float)
    g = np.asarray(fun(x), float)
    nev = 1
    step = np.zeros_like(x)
    last = np.inf
    pending = None        # the singular Jacobian met on the way, if it never converges
    for it in range(1, max_iter + 1):
        if not np.all(np.isfinite(g)):
            return NewtonResult(x, False, it, g, step, "non-finite residual", nev)
        J = jac(x)
        try:
            dx, singular = _solve(J, -g), None
        except SingularMatrixError as exc:
            # a singular J at a point that solves the system is no failure: keep it
            # when the least-squares step is below the tolerance and the residual nil
            dx, singular = _solve(J, -g, singular_ok=True), exc
        w = weights(x) if callable(weights) else (1.0 if weights is None else weights)
        step = dx * w
        size = _rms(step)
        if singular is not None:
            D = _row_scale(J)
            if size <= tol and np.max(np.abs(g) * D, initial=0.0) <= _CONSISTENT:
                return NewtonResult(x, True, it, g, step, "converged (singular)", nev)
            # Gauss-Newton: the least-squares step, while it reduces the residual
            found, xt, gt, n_ls = _line_search(fun, x, dx, g, D, min_damping)
            nev += n_ls
            if not found or not np.all(np.isfinite(gt)):
                raise singular
            x, g, last, pending = xt, gt, size, singular
            continue
        # Converged: the step is below tol, or it has stopped contracting while far
        # below the error scale (round-off in an ill-conditioned J: iterating more
        # only moves x around within that noise)
        stalled = it > 2 and _STALL_FLOOR >= size >= 0.5 * last
        if size <= tol or stalled:
            # a merit decrease cannot be asked for at the round-off level
            x = x + dx
            g = np.asarray(fun(x), float)
            return NewtonResult(x, True, it, g, step, "converged", nev + 1)
        last = size
        found, xt, gt, n_ls = _line_search(fun, x, dx, g, _row_scale(J), min_damping)
        nev += n_ls
        if not found and size <= _STALL_FLOOR:
            # x is already within a tenth of the error scale of the root the step
            # points to, and no point along the step lowers the residual: it is at its
            # round-off floor (weights of a tight tolerance ask for a step below the
            # round-off of x itself: rtol 1e-12 times the Newton tolerance)
            return NewtonResult(x, True, it, g, step, "converged", nev)
        if not found:
            return NewtonResult(x, False, it, g, step, "line search failed", nev)
        x, g = xt, gt
    if pending is not None:
        raise pending
    return NewtonResult(x, False, max_iter, g, step, "too many iterations", nev)


def _line_search(fun, x, dx, g, D, min_damping):
    """Backtrack on ``x + lam dx`` until the scaled residual decreases (Armijo).

    Returns (success, x_new, g_new, evaluations).  A point that fails the Armijo test
    at the smallest ``lam`` is still taken if it lowers the merit at all.
    """
    merit = _rms(D * g)
    lam, nev = 1.0, 0
    while True:
        xt = x + lam * dx
        gt = np.asarray(fun(xt), float)
        nev += 1
        finite = np.all(np.isfinite(gt))
        if finite and _rms(D * gt) <= (1.0 - 1e-4 * lam) * merit:
            return True, xt, gt, nev
        if merit == 0.0 or lam <= min_damping:
            return bool(finite and _rms(D * gt) <= merit), xt, gt, nev
        lam *= 0.5


def homotopy(fun, jac, x0, *, weights=None, tol: float = 1e-6, max_steps: int = 200,
             min_dlam: float = 1e-6) -> NewtonResult:
    """Newton homotopy from ``x0`` (trivially a solution at ``lam = 0``) to ``fun = 0``.

    Parameters are as for :func:`damped_newton`; ``max_steps`` bounds the number of
    continuation steps and ``min_dlam`` the smallest continuation step.

    Returns
    -------
    NewtonResult
        ``converged`` is True only if ``lam = 1`` was reached and the final damped
        Newton solve converged.
    """
    x = np.array(x0, dtype=float)
    g0 = np.asarray(fun(x), float)
    nev = 1
    lam, dlam = 0.0, 0.1
    x_prev, lam_step = None, 1.0
    for _ in range(max_steps):
        target = min(1.0, lam + dlam)
        guess = x if x_prev is None else x + (x - x_prev) * (dlam / max(lam_step, 1e-300))
        shift = (1.0 - target) * g0
        try:
            res = damped_newton(lambda z: fun(z) - shift, jac, guess, weights=weights,
                                tol=tol, max_iter=8)
        except SingularMatrixError:
            res = None
        nev += res.evaluations if res is not None else 0
        if res is not None and res.converged:
            x_prev, x = x, res.x
            lam_step, lam = target - lam, target
            if lam >= 1.0:
                res.evaluations = nev
                res.message = "converged by homotopy"
                return res
            dlam = min(2.0 * dlam, 0.5)
        else:
            dlam *= 0.25
            if dlam < min_dlam:
                break
    g = np.asarray(fun(x), float)
    return NewtonResult(x, False, max_steps, g, np.zeros_like(x),
                        f"homotopy stalled at lambda={lam:.3g}", nev + 1)
