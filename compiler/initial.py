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

from ..solvers.base import SimulationError
from ..solvers.newton import damped_newton, homotopy

__all__ = ["InitialConditions", "InitializationFailed", "solve_initial"]


class InitializationFailed(SimulationError):
    """The initial values could not be made consistent (names what was involved)."""


class InitialConditions:
    """The initial-condition rows as generated code over the solver vector z."""

    def __init__(self, code, descriptions):
        self.code = code
        self.descriptions = descriptions      # one text per row, for messages

    @property
    def n(self) -> int:
        return self.code.n_rows

    def residual(self, t, z, p, m):
        return self.code.residual(t, z, p, m, np.empty(self.code.n_rows))

    def jacobian(self, t, z, p, m, n):
        c = self.code
        vals = c.jacobian(t, z, p, m, np.empty(len(c.jac_rows)))
        return sps.csr_matrix((vals, (c.jac_rows, c.jac_cols)), shape=(self.n, n))


def solve_initial(model, init: InitialConditions, t0: float, z_guess: np.ndarray,
                  tol: float = 1e-10, max_iter: int = 60) -> np.ndarray:
    """Damped Newton on [G; I](z) = 0, then a homotopy from the guess if that fails."""
    if model.n == 0:
        return z_guess

    def F(z):
        return np.concatenate([model.G(t0, z), init.residual(t0, z, model.p, model.m)])

    def J(z):
        return sps.vstack([model.dG_dy(t0, z),
                           init.jacobian(t0, z, model.p, model.m, model.n)]).tocsc()

    weights = 1.0 / (1e-10 * np.abs(z_guess) + 1e-10 * model.nominal)
    out = damped_newton(F, J, z_guess.copy(), weights=weights, tol=1.0, max_iter=max_iter)
    if not out.converged:
        out = homotopy(F, J, z_guess.copy(), weights=weights, tol=1.0)
    if not out.converged or np.max(np.abs(out.residual), initial=0) > 1e-6:
        r = F(out.x)
        worst = [k for k in np.argsort(-np.abs(r))[:5] if abs(r[k]) > tol]
        names = [_row_name(model, init, k) for k in worst]
        raise InitializationFailed(
            f"initialization failed at t = {t0}: {out.message or 'no convergence'}; "
            "largest residuals in: " + "; ".join(names), t=t0, variables=names)
    return out.x


def _row_name(model, init, k):
    g_names = model.meta.get("equation_names", [])
    if k < model.n_g:
        return g_names[k] if k < len(g_names) else f"equation {k}"
    return init.descriptions[k - model.n_g]
