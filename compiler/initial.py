"""The initialization problem, the way Modelica tools pose it.

At t0 the unknowns are all of y (variables and derivative variables).  The equations are
the model's G(t0, y) = 0 plus as many *initial conditions* as there are states:

1. the user's initial equations (e.g. ``der(w) = 0`` for steady state);
2. ``v = start`` for every variable with ``fixed=True``;
3. ``s = start`` for the selected states that are still free (Modelica's rule that a
   state's start value is used when nothing else fixes it), in declaration order.

Start values of everything else are only guesses for Newton's method.  Too many fixed
conditions, or an initial problem whose Jacobian is singular, is an
``InitializationFailed`` that names the variables involved.
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sps
import scipy.sparse.linalg as spla

from ..solvers.base import SimulationError

__all__ = ["InitialConditions", "InitializationFailed", "solve_initial"]


class InitializationFailed(SimulationError):
    """The initial values could not be made consistent (names what was involved)."""


class InitialConditions:
    """Initial-condition rows: generated code for user initial equations + fixed values."""

    def __init__(self, code, fixed_index, fixed_value, descriptions):
        self.code = code                      # GeneratedCode of the user initial equations
        self.fixed_index = np.asarray(fixed_index, dtype=np.int64)
        self.fixed_value = np.asarray(fixed_value, dtype=float)
        self.descriptions = descriptions      # one text per row, for messages

    @property
    def n(self) -> int:
        return self.code.n_rows + len(self.fixed_index)

    def residual(self, t, y, p, m):
        r = self.code.residual(t, y, p, m, np.empty(self.code.n_rows))
        return np.concatenate([r, y[self.fixed_index] - self.fixed_value])

    def jacobian(self, t, y, p, m, n):
        c = self.code
        vals = c.jacobian(t, y, p, m, np.empty(len(c.jac_rows)))
        k = len(self.fixed_index)
        rows = np.concatenate([c.jac_rows, c.n_rows + np.arange(k)])
        cols = np.concatenate([c.jac_cols, self.fixed_index])
        data = np.concatenate([vals, np.ones(k)])
        return sps.csr_matrix((data, (rows, cols)), shape=(self.n, n))


def solve_initial(model, init: InitialConditions, t0: float, y_guess: np.ndarray,
                  tol: float = 1e-10, max_iter: int = 60) -> np.ndarray:
    """Damped Newton on [G; I](y) = 0, then a homotopy from the guess if that fails."""
    def F(y):
        return np.concatenate([model.G(t0, y), init.residual(t0, y, model.p, model.m)])

    def J(y):
        return sps.vstack([model.dG_dy(t0, y), init.jacobian(t0, y, model.p, model.m, model.n)]).tocsc()

    scale = np.maximum(np.abs(y_guess), model.nominal)
    y, ok, why = _damped_newton(F, J, y_guess.copy(), scale, tol, max_iter)
    if not ok:
        y, ok, why2 = _homotopy(F, J, y_guess.copy(), scale, tol)
        why = why2 or why
    if not ok:
        r = F(y)
        worst = np.argsort(-np.abs(r))[:5]
        names = [_row_name(model, init, k) for k in worst if abs(r[k]) > tol]
        raise InitializationFailed(
            f"initialization failed at t = {t0}: {why}; largest residuals in: "
            + "; ".join(names), t=t0, variables=names)
    return y


def _row_name(model, init, k):
    g_names = model.meta.get("equation_names", [])
    if k < model.n_g:
        return g_names[k] if k < len(g_names) else f"equation {k}"
    return init.descriptions[k - model.n_g]


def _solve(Jm, r):
    try:
        with np.errstate(all="ignore"):
            lu = spla.splu(Jm)
            dx = lu.solve(r)
        if np.all(np.isfinite(dx)):
            return dx
    except RuntimeError:
        pass
    # singular: least squares, so Newton can still make progress on a rank-deficient step
    return spla.lsqr(Jm, r, atol=1e-14, btol=1e-14)[0]


def _damped_newton(F, J, y, scale, tol, max_iter):
    r = F(y)
    for _ in range(max_iter):
        if np.max(np.abs(r)) < tol:
            return y, True, ""
        dx = _solve(J(y), r)
        lam, norm0 = 1.0, np.linalg.norm(r)
        while lam > 1e-4:
            y_new = y - lam * dx
            r_new = F(y_new)
            if np.all(np.isfinite(r_new)) and np.linalg.norm(r_new) < (1 - 1e-4 * lam) * norm0:
                break
            lam *= 0.5
        else:
            return y, False, "damped Newton made no progress (singular or no solution)"
        y, r = y_new, r_new
        if np.max(np.abs(dx * lam) / scale) < 1e-14 and np.max(np.abs(r)) < 1e3 * tol:
            return y, True, ""
    return y, np.max(np.abs(r)) < tol, "Newton did not converge"


def _homotopy(F, J, y0, scale, tol, steps=20):
    """Fixed-point homotopy H(y, l) = F(y) - (1 - l) F(y0), followed from l = 0 to 1."""
    r0 = F(y0)
    y = y0
    for lam in np.linspace(0, 1, steps + 1)[1:]:
        y, ok, why = _damped_newton(lambda q: F(q) - (1 - lam) * r0, J, y, scale, tol, 40)
        if not ok:
            return y, False, f"homotopy stopped at lambda = {lam:.2f}: {why}"
    return y, True, ""
