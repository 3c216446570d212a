"""The initialization problem, the way Modelica tools pose it.

At t0 the unknowns are the solver vector z (the states and tearing variables; every
other variable follows from z).  The equations are the model's residual rows G(t0, z) = 0
plus as many *initial conditions* as there are states:

1. the user's initial equations (e.g. ``der(w) = 0`` for steady state);
2. ``v = start`` for every variable with ``fixed=True``;
3. ``s = start`` for states that nothing else fixes (Modelica's rule that a state's start
   value is used then): a start-value row is generated for every other state, and those
   that complete a perfect structural matching of the initial system are kept, in state
   order (:meth:`InitialConditions.choose_rows`).  So ``der(w) = 0`` fixes the speed and
   leaves the angle to its start value.

Start values of everything else are only guesses for Newton's method.  Too many fixed
conditions, or an initial problem whose Jacobian is singular, is an
``InitializationFailed`` that names the variables involved.
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sps

from ..solvers.base import InitializationFailed
from ..solvers.initialization import solve_with_fallback

__all__ = ["InitialConditions", "InitializationFailed", "solve_initial"]


class InitialConditions:
    """The initial-condition rows as generated code over the solver vector z.

    ``rows`` selects which of the generated rows are used (all mandatory rows, and the
    optional start-value rows that :meth:`choose_rows` keeps).
    """

    def __init__(self, code, descriptions):
        self.code = code
        self.all_descriptions = descriptions
        self.rows = np.arange(code.n_rows)
        self._entries = np.ones(len(code.jac_rows), dtype=bool)
        self._renumber = np.arange(code.n_rows)

    @property
    def n(self) -> int:
        return len(self.rows)

    @property
    def descriptions(self) -> list:
        return [self.all_descriptions[k] for k in self.rows]

    def choose_rows(self, model_code, n_res, n_mandatory, n_states, n_z) -> None:
        """Keep the mandatory rows and those optional start-value rows (in state order)
        that complete a perfect matching of [G; initial rows] onto z (Modelica's rule:
        start values fix the states that nothing else determines)."""
        from .structure import _match
        keep = model_code.jac_rows < n_res
        adj = _adjacency(model_code.jac_rows[keep], model_code.jac_cols[keep], n_res)
        i_adj = _adjacency(self.code.jac_rows, self.code.jac_cols, self.code.n_rows)
        adj += i_adj[:n_mandatory]
        l2r, r2l = _match(adj, n_z)
        if min(l2r, default=0) < 0:
            bad = [self.all_descriptions[k - n_res] for k, v in enumerate(l2r)
                   if v < 0 and k >= n_res]
            raise InitializationFailed(
                "the initial conditions contradict the model equations structurally "
                "(they determine the same variables twice): " + "; ".join(bad or ["(model)"]))
        chosen = list(range(n_mandatory))
        for k in range(n_mandatory, self.code.n_rows):
            if len(chosen) == n_states:
                break
            adj.append(i_adj[k])
            l2r.append(-1)
            if _augment(len(adj) - 1, adj, l2r, r2l):
                chosen.append(k)
            else:
                adj.pop()
                l2r.pop()
        self._select(np.array(chosen, dtype=np.int64))

    def _select(self, rows) -> None:
        self.rows = rows
        self._renumber = np.full(self.code.n_rows, -1)
        self._renumber[rows] = np.arange(len(rows))
        self._entries = self._renumber[self.code.jac_rows] >= 0

    def residual(self, t, z, p, m):
        return self.code.residual(t, z, p, m, np.empty(self.code.n_rows))[self.rows]

    def jacobian(self, t, z, p, m, n):
        c = self.code
        vals = c.jacobian(t, z, p, m, np.empty(len(c.jac_rows)))[self._entries]
        rows = self._renumber[c.jac_rows[self._entries]]
        return sps.csr_matrix((vals, (rows, c.jac_cols[self._entries])), shape=(self.n, n))


def _augment(root, adj, l2r, r2l) -> bool:
    """One augmenting path from row ``root`` (iterative Kuhn search); flips it if found."""
    seen, stack, parent = {root}, [(root, iter(adj[root]))], {}
    while stack:
        u, it = stack[-1]
        v = next(it, None)
        if v is None:
            stack.pop()
            continue
        w = r2l[v]
        if w < 0:
            while True:             # flip the path back to the root
                prev = l2r[u]
                l2r[u], r2l[v] = v, u
                if u == root:
                    return True
                u, v = parent[u], prev
        if w not in seen:
            seen.add(w)
            parent[w] = u
            stack.append((w, iter(adj[w])))
    return False


def _adjacency(rows, cols, n_rows) -> list:
    adj = [[] for _ in range(n_rows)]
    for r, c in zip(rows.tolist(), cols.tolist()):
        adj[r].append(c)
    return [sorted(set(a)) for a in adj]


def solve_initial(model, init: InitialConditions, t0: float, z_guess: np.ndarray) -> np.ndarray:
    """[G; I](z) = 0 by damped Newton, then a homotopy from the guess (the solver
    package's :func:`~acausal.solvers.initialization.solve_with_fallback`); a failure
    names the equations and initial conditions involved in the user's words."""
    if model.n == 0:
        return z_guess

    def F(z):
        return np.concatenate([model.G(t0, z), init.residual(t0, z, model.p, model.m)])

    def J(z):
        return sps.vstack([model.dG_dy(t0, z),
                           init.jacobian(t0, z, model.p, model.m, model.n)]).tocsc()

    # weighted steps below 1e-5 (the routine's tolerance) are then 1e-11 relative
    weights = 1.0 / (1e-6 * np.abs(z_guess) + 1e-6 * model.nominal)
    return solve_with_fallback(F, J, z_guess.copy(), weights, f"initialization at t = {t0}",
                               model.names, lambda k: _row_name(model, init, k), t0)


def _row_name(model, init, k):
    g_names = model.meta.get("equation_names", [])
    if k < model.n_g:
        return g_names[k] if k < len(g_names) else f"equation {k}"
    return init.descriptions[k - model.n_g]
