"""Consistent systems whose Jacobian is singular: statically indeterminate forces.

Two friction elements locked on one motion (a lossy gear and a bearing on the same
shaft, two clutches in parallel) each impose the same constraint, a = 0; the force
balance then fixes the sum of their locking torques but not how it is split.  The
equations are consistent and the motion is determined, but the Jacobian with respect
to the unknowns is singular, so Newton's method with an LU fails although solutions
exist.  The MSL documents the case (Modelica.Mechanics.Rotational.Examples
.LossyGearDemo2: "If both friction models are stuck, there is no unique solution.
Still a reliable Modelica simulator should be able to handle this situation"), and
Modelica tools solve such a singular linear system for one of its solutions.

Here the solution taken is the one nearest the guess: Gauss-Newton with the minimum-norm
step of the Jacobian (equilibrated, its rank decided by its singular values), in the
variables scaled by their nominal values,

    dx = D_c (D_r J D_c)^+ (-D_r G),

which for a linear system from a zero guess is the minimum-norm solution (the locking
torques shared equally where the elements are alike).  It is accepted only when the
residual vanishes (the system is consistent: an inconsistent singular system, a genuine
modelling error, is still refused), and the variables left indeterminate are named in
the index report.  The modes then judge the solution as any other: an element whose
share exceeds what it holds breaks away, and the event iteration settles the modes
(:mod:`acausal.runtime.initial`).
"""
from __future__ import annotations

import numpy as np

from ..solvers.linalg import equilibrate

__all__ = ["minimum_norm_newton", "null_variables"]

_RANK_RTOL = 1e-10    # singular values below this times the largest are zero
_MAX_ITER = 30
_CONSISTENT = 1e-8   # a residual row this small against its terms is zero


def _dense(J):
    return J.toarray() if hasattr(J, "toarray") else np.asarray(J, dtype=float)


def _pinv_step(J, g, scale):
    """The minimum-norm solution of J dx = -g in the variables dx / scale, with the
    rows equilibrated; also the rank deficiency and the null-space basis."""
    A = _dense(J) * scale
    r, c = equilibrate(A)
    B = A * r[:, None] * c
    u, s, vt = np.linalg.svd(B, full_matrices=True)
    keep = s > _RANK_RTOL * (s[0] if s.size else 1.0)
    y = vt[:keep.sum()].T @ ((u[:, :keep.sum()].T @ (-r * g)) / s[keep])
    return y * c * scale, vt[keep.sum():] * (c * scale)


def minimum_norm_newton(fun, jac, x0, weights, scale, tol=1e-5):
    """(x, null) where fun(x) = 0 by minimum-norm Gauss-Newton steps, or None when
    it does not converge (an inconsistent system among them).  ``null``: rows that
    span the directions left indeterminate at the solution (in x)."""
    x = np.array(x0, dtype=float)
    g = np.asarray(fun(x), float)
    for _ in range(_MAX_ITER):
        if not np.all(np.isfinite(g)):
            return None
        J = jac(x)
        dx, null = _pinv_step(J, g, scale)
        x = x + dx
        g = np.asarray(fun(x), float)
        w = weights if not callable(weights) else weights(x)
        size = float(np.sqrt(np.mean((dx * w) ** 2))) if dx.size else 0.0
        if size <= tol:
            # consistent: what is left of each row is small against its terms
            terms = np.abs(_dense(J)) @ (np.abs(x) + scale)
            if np.all(np.abs(g) <= _CONSISTENT * np.maximum(terms, 1e-300)):
                return x, null
            return None
    return None


def null_variables(null, names, limit=4):
    """The names of the unknowns that the indeterminate directions move."""
    if null is None or not len(null):
        return []
    size = np.abs(null).max(axis=0)
    picked = np.flatnonzero(size > 0.1 * size.max())
    return [names[k] for k in picked[:limit]]
