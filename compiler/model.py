"""CompiledModel: the reduced index-1 DAE, as a DAEProblem, with the user's names.

Formulation (see the README's design section for why).  Every remaining variable,
derivative variables der(x) included, is a component of the solver vector y.  The
equations G(t, y, p) = 0 contain no y' at all; instead each selected state s has a
*linking row*

    y'[s] - y[der(s)] = 0,

so F(t, y, y') = [G(t, y, p); y'[S] - y[D]].  A dummy derivative (Mattsson & Söderlind
1993) is then simply a derivative variable without a linking row.  Dynamic state
selection (Mattsson, Olsson & Elmqvist 2000) only changes which candidates carry the
linking rows of their state set; the generated code and the vector y stay the same.
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sps

from ..solvers.base import DAEProblem, EventAction
from .graph import UNASSIGNED

__all__ = ["CompiledModel", "DynamicStateSelection"]


class DynamicStateSelection:
    """Dummy derivatives re-chosen numerically at run time (Mattsson et al. 2000).

    The levels of Mattsson & Söderlind's procedure are fixed by the structure: level 1
    rows are the tops of the differentiated equation chains, each next level the
    equations they were differentiated from.  At run time each level's block of the
    Jacobian dG/dy (rows x candidate derivative columns) is factorized by QR with
    column pivoting; the first pivot columns are the best-conditioned dummies.  The
    next level's candidates are the antiderivatives of this level's dummies, as in the
    paper's step 3.  ``weights`` scale columns by the user's state_select hint.
    """

    def __init__(self, levels, row_vars, var_to_diff, diff_to_var, weights, names):
        self.levels = [list(rows) for rows, _ in levels]
        self.row_vars = row_vars              # row -> derivative variables in it
        self.var_to_diff = var_to_diff
        self.diff_to_var = diff_to_var
        self.weights = np.asarray(weights, dtype=float)
        self.names = names
        self.switches = []                    # (time, new dummies)

    def choose(self, J, current: set, hysteresis: float) -> set:
        dummies, allowed = set(), None
        for rows in self.levels:
            # level 1: the highest derivatives; below: antiderivatives of the last dummies
            cols = sorted({v for r in rows for v in self.row_vars[r]
                           if (v in allowed if allowed is not None
                               else self.var_to_diff[v] is UNASSIGNED)})
            block = J[rows][:, cols].toarray() * self.weights[cols]
            pick = _pivot_columns(block, len(rows))
            keep = [k for k, c in enumerate(cols) if c in current]
            if len(keep) == len(rows) and _well_enough(block, keep, pick, hysteresis):
                pick = keep
            chosen = [cols[k] for k in pick]
            dummies.update(chosen)
            allowed = {self.diff_to_var[c] for c in chosen}
        return dummies


def _pivot_columns(block, k):
    import scipy.linalg as sla
    _, _, piv = sla.qr(block, pivoting=True, mode="economic")
    return sorted(piv[:k].tolist())


def _well_enough(block, keep, best, hysteresis):
    """Keep the current dummies unless the best choice is clearly better conditioned."""
    cur = abs(np.linalg.det(block[:, keep]))
    new = abs(np.linalg.det(block[:, best]))
    return cur >= hysteresis * new


class CompiledModel(DAEProblem):
    """F(t, y, y') = [G(t, y, p); y'[S] - y[D]] with names, parameters and modes."""

    def __init__(self, code, y_names, params, param_values, pairs, dummies,
                 dynamic=None, nominal=None, report=None, meta=None):
        super().__init__(len(y_names), y_names)
        self.code = code
        self.param_names = list(params)
        self.p = np.asarray(param_values, dtype=float)
        # every derivative link v -> der(v); a link is a linking row unless der(v) is a dummy
        self.pair_s = np.asarray([a for a, _ in pairs], dtype=np.int64)
        self.pair_d = np.asarray([b for _, b in pairs], dtype=np.int64)
        self.dummies = set(dummies)
        self.dynamic = dynamic
        self.m = np.zeros(code.n_roots, dtype=bool)
        self.n_roots = code.n_roots
        self.n_g = code.n_rows
        if nominal is not None:
            self.nominal = np.asarray(nominal, dtype=float)
        self.outputs = {}
        self.report = report
        self.meta = meta or {}
        self._update_links()

    # -- the linking rows ----------------------------------------------------------------
    def _update_links(self):
        active = np.array([d not in self.dummies for d in self.pair_d], dtype=bool)
        self.link_s = self.pair_s[active] if len(active) else self.pair_s
        self.link_d = self.pair_d[active] if len(active) else self.pair_d
        self.algebraic = np.ones(self.n, dtype=bool)
        self.algebraic[self.link_s] = False
        c = self.code
        rows_link = self.n_g + np.arange(len(self.link_s))
        self.jac_pattern = (np.concatenate([c.jac_rows, rows_link, rows_link]),
                            np.concatenate([c.jac_cols, self.link_s, self.link_d]))

    @property
    def states(self) -> list:
        return [self.names[k] for k in self.link_s]

    # -- DAEProblem ----------------------------------------------------------------------
    def G(self, t, y):
        return self.code.residual(t, y, self.p, self.m, np.empty(self.n_g))

    def residual(self, t, y, yp):
        out = np.empty(self.n)
        self.code.residual(t, y, self.p, self.m, out)
        out[self.n_g:] = yp[self.link_s] - y[self.link_d]
        return out

    def jacobian(self, t, y, yp, cj):
        c = self.code
        vals = c.jacobian(t, y, self.p, self.m, np.empty(len(c.jac_rows)))
        k = len(self.link_s)
        rows_link = self.n_g + np.arange(k)
        rows = np.concatenate([c.jac_rows, rows_link, rows_link])
        cols = np.concatenate([c.jac_cols, self.link_s, self.link_d])
        data = np.concatenate([vals, np.full(k, cj), -np.ones(k)])
        return sps.csc_matrix((data, (rows, cols)), shape=(self.n, self.n))

    def dG_dy(self, t, y):
        c = self.code
        vals = c.jacobian(t, y, self.p, self.m, np.empty(len(c.jac_rows)))
        return sps.csr_matrix((vals, (c.jac_rows, c.jac_cols)), shape=(self.n_g, self.n))

    def roots(self, t, y, yp):
        return self.code.roots(t, y, self.p, self.m, np.empty(self.n_roots))

    def init_modes(self, t, y):
        """Relations take the values they have at the initial point."""
        if self.n_roots:
            g = self.roots(t, y, None)
            self.m[:] = self.code_relation_values(g)

    def code_relation_values(self, g):
        strict = self.meta.get("relation_greater", np.ones(self.n_roots, dtype=bool))
        return np.where(strict, g > 0, g < 0)

    def handle_event(self, t, y, yp, crossed):
        self.m[crossed] = ~self.m[crossed]
        return EventAction(changed=True)

    # -- dynamic state selection ----------------------------------------------------------
    def reselect_states(self, t, y, hysteresis=0.5) -> bool:
        """Re-choose the dummy derivatives; True when the choice (and so F) changed."""
        if self.dynamic is None:
            return False
        new = self.dynamic.choose(self.dG_dy(t, y).tocsr(), self.dummies, hysteresis)
        if new == self.dummies:
            return False
        self.dummies = new
        self.dynamic.switches.append((t, sorted(self.names[d] for d in new)))
        self._update_links()
        return True

    def after_step(self, t, y, yp) -> bool:
        """Called by the driver after each accepted step (dynamic state selection)."""
        return self.reselect_states(t, y)

    def set_parameters(self, values: dict) -> None:
        for name, value in values.items():
            try:
                k = self.param_names.index(name)
            except ValueError:
                raise KeyError(f"the model has no parameter '{name}'") from None
            self.p[k] = float(value)
