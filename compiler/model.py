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
        self.entry = {}                       # (row, col) -> index into Jacobian values
        self._reference = []                  # block quality at the last pivoting search

    def bind(self, jac_rows, jac_cols) -> None:
        """Locate the level blocks in the generated Jacobian's value array (once)."""
        wanted = {r for rows in self.levels for r in rows}
        self.entry = {(int(r), int(c)): k for k, (r, c) in enumerate(zip(jac_rows, jac_cols))
                      if r in wanted}

    def choose(self, vals, current: set, hysteresis: float) -> set:
        """The dummies for the Jacobian values ``vals``: ``current`` unless clearly worse."""
        ratios = [_hadamard_ratio(block[:, keep]) for block, _, keep in self._blocks(vals, current)]
        if current and len(ratios) == len(self._reference) and all(
                r >= _DEGRADED * r0 for r, r0 in zip(ratios, self._reference)):
            return current   # the current blocks have not degraded since the last search
        dummies, allowed = set(), None
        for rows in self.levels:
            cols = self._columns(rows, allowed)
            block = self._block(vals, rows, cols)
            pick = _pivot_columns(block, len(rows))
            keep = [k for k, c in enumerate(cols) if c in current]
            if len(keep) == len(rows) and _well_enough(block, keep, pick, hysteresis):
                pick = keep
            chosen = [cols[k] for k in pick]
            dummies.update(chosen)
            allowed = {self.diff_to_var[c] for c in chosen}
        self._reference = [_hadamard_ratio(block[:, keep])
                           for block, _, keep in self._blocks(vals, dummies)]
        return dummies

    def _columns(self, rows, allowed):
        """Level 1: the highest derivatives; below: antiderivatives of the last dummies."""
        return sorted({v for r in rows for v in self.row_vars[r]
                       if (v in allowed if allowed is not None
                           else self.var_to_diff[v] is UNASSIGNED)})

    def _block(self, vals, rows, cols):
        block = np.zeros((len(rows), len(cols)))
        for i, r in enumerate(rows):
            for j, c in enumerate(cols):
                k = self.entry.get((r, c))
                if k is not None:
                    block[i, j] = vals[k] * self.weights[c]
        return block

    def _blocks(self, vals, dummies):
        allowed = None
        for rows in self.levels:
            cols = self._columns(rows, allowed)
            keep = [k for k, c in enumerate(cols) if c in dummies]
            if len(keep) != len(rows):
                yield np.zeros((len(rows), len(rows))), cols, list(range(len(rows)))
                return
            yield self._block(vals, rows, cols), cols, keep
            allowed = {self.diff_to_var[cols[k]] for k in keep}


# The pivoting search runs again only once a dummy block's Hadamard ratio
# |det B| / prod ||b_i|| has fallen below this fraction of its value at the last search:
# a block that has not degraded cannot have become (near) singular.
_DEGRADED = 0.5


def _hadamard_ratio(B) -> float:
    norms = np.prod(np.linalg.norm(B, axis=1))
    return abs(np.linalg.det(B)) / norms if norms > 0 else 0.0


def _pivot_columns(block, k):
    import scipy.linalg as sla
    _, _, piv = sla.qr(block, pivoting=True, mode="economic")
    return sorted(piv[:k].tolist())


def _well_enough(block, keep, best, hysteresis):
    """Keep the current dummies unless the best choice is clearly better conditioned."""
    cur = abs(np.linalg.det(block[:, keep]))
    new = abs(np.linalg.det(block[:, best]))
    return cur >= hysteresis * new


# A relation lhs OP rhs holds when g = lhs - rhs satisfies OP 0.
_RELATION = {"StrictGreaterThan": lambda g: g > 0, "GreaterThan": lambda g: g >= 0,
             "StrictLessThan": lambda g: g < 0, "LessThan": lambda g: g <= 0}


class CompiledModel(DAEProblem):
    """F(t, z, z') for the solver, with the user's names, parameters and modes.

    The generated code returns ``n_res`` residual rows R(t, z) followed by the values of
    der(s) for the code-linked states s (``state_z``).  Then

        F = [ R(t, z);  z'[state_z] - D(t, z);  z'[link_s] - z[link_d] ]

    The middle block is the causal form (der(s) computed by the BLT's assignments); the
    last block is the full form, where derivative variables are part of z and dynamic
    state selection switches which links are active.
    """

    def __init__(self, code, z_names, params, param_values, n_res, state_z=(),
                 pairs=(), dummies=(), dynamic=None, nominal=None, report=None, meta=None):
        super().__init__(len(z_names), z_names)
        self.code = code
        self.param_names = list(params)
        self.p = np.asarray(param_values, dtype=float)
        self.n_res = int(n_res)
        self.state_z = np.asarray(state_z, dtype=np.int64)
        self.pair_s = np.asarray([a for a, _ in pairs], dtype=np.int64)
        self.pair_d = np.asarray([b for _, b in pairs], dtype=np.int64)
        self.dummies = set(dummies)
        self.dynamic = dynamic
        self._time_idx = np.zeros(0, dtype=np.int64)
        self._time_f = None
        self.m = np.zeros(code.n_roots, dtype=bool)
        self.n_roots = code.n_roots
        self.n_g = self.n_res     # rows of the model equations proper (for initialization)
        if nominal is not None:
            self.nominal = np.asarray(nominal, dtype=float)
        self.outputs = {}
        self.report = report
        self.meta = meta or {}
        self._jac_split()
        if dynamic is not None:
            dynamic.bind(code.jac_rows, code.jac_cols)
        self._update_links()

    def _jac_split(self):
        c = self.code
        self._res_entries = c.jac_rows < self.n_res
        self._der_entries = ~self._res_entries

    # -- the linking rows ----------------------------------------------------------------
    def _update_links(self):
        active = np.array([d not in self.dummies for d in self.pair_d], dtype=bool)
        self.link_s = self.pair_s[active] if len(active) else self.pair_s
        self.link_d = self.pair_d[active] if len(active) else self.pair_d
        self.state_index = np.concatenate([self.state_z, self.link_s]).astype(np.int64)
        self.algebraic = np.ones(self.n, dtype=bool)
        self.algebraic[self.state_index] = False
        r0 = self.n_res + len(self.state_z)
        rows_link = r0 + np.arange(len(self.link_s))
        c = self.code
        self.jac_pattern = (
            np.concatenate([c.jac_rows, self.n_res + np.arange(len(self.state_z)), rows_link,
                            rows_link]),
            np.concatenate([c.jac_cols, self.state_z, self.link_s, self.link_d]))

    @property
    def states(self) -> list:
        return [self.names[k] for k in self.state_index]

    def state_derivatives(self, t, z) -> np.ndarray:
        """der(s) of every state, in the order of ``state_index`` (consistent z')."""
        out = self.code.residual(t, z, self.p, self.m, np.empty(self.code.n_rows))
        return np.concatenate([out[self.n_res:], z[self.link_d]])

    # -- DAEProblem ----------------------------------------------------------------------
    def G(self, t, z):
        out = self.code.residual(t, z, self.p, self.m, np.empty(self.code.n_rows))
        return out[: self.n_res]

    def residual(self, t, z, zp):
        c = self.code
        try:
            out = c.residual(t, z, self.p, self.m, np.empty(c.n_rows))
        except (ValueError, ZeroDivisionError, OverflowError):
            # outside the domain of a function (sqrt of a negative, ...): the iterate is
            # unusable, which the integrator treats like a failed Newton iteration
            return np.full(self.n, np.nan)
        F = np.empty(self.n)
        F[: self.n_res] = out[: self.n_res]
        k = self.n_res + len(self.state_z)
        F[self.n_res:k] = zp[self.state_z] - out[self.n_res:]
        F[k:] = zp[self.link_s] - z[self.link_d]
        return F

    def jacobian(self, t, z, zp, cj):
        c = self.code
        try:
            vals = c.jacobian(t, z, self.p, self.m, np.empty(len(c.jac_rows)))
        except (ValueError, ZeroDivisionError, OverflowError):
            vals = np.full(len(c.jac_rows), np.nan)
        vals[self._der_entries] *= -1.0
        n_sz, n_l = len(self.state_z), len(self.link_s)
        k = self.n_res + n_sz
        rows_link = k + np.arange(n_l)
        rows = np.concatenate([c.jac_rows, self.n_res + np.arange(n_sz), rows_link, rows_link])
        cols = np.concatenate([c.jac_cols, self.state_z, self.link_s, self.link_d])
        data = np.concatenate([vals, np.full(n_sz, cj), np.full(n_l, cj), -np.ones(n_l)])
        return sps.csc_matrix((data, (rows, cols)), shape=(self.n, self.n))

    def dG_dy(self, t, z):
        c = self.code
        vals = c.jacobian(t, z, self.p, self.m, np.empty(len(c.jac_rows)))
        keep = self._res_entries
        return sps.csr_matrix((vals[keep], (c.jac_rows[keep], c.jac_cols[keep])),
                              shape=(self.n_res, self.n))

    def relations(self, t, z):
        """lhs - rhs of every relation (the zero-crossing functions, unmasked)."""
        return self.code.roots(t, z, self.p, self.m, np.empty(self.n_roots))

    def roots(self, t, z, zp):
        g = self.relations(t, z)
        g[self._time_idx] = 1.0   # relations of time alone are time events, not roots
        return g

    # -- relations of time alone: events known before integrating --------------------------
    def set_time_relations(self, idx, f) -> None:
        self._time_idx = np.asarray(idx, dtype=np.int64)
        self._time_f = f
        self.time_events = ()

    def scan_time_events(self, t0, t1, samples: int = 20000) -> list:
        """Every crossing of a time-only relation in (t0, t1]: sampled at (t1-t0)/samples,
        then refined by Brent's method.  (Two crossings closer than the sampling interval
        may be missed; such a signal needs its own time-event description.)"""
        from scipy.optimize import brentq
        if self._time_f is None:
            return []
        grid = np.linspace(t0, t1, samples + 1)
        G = np.atleast_2d(np.asarray(self._time_f(grid, self.p), dtype=float))
        events = []
        for row, k in zip(G, range(len(self._time_idx))):
            s = np.sign(row)
            for j in np.flatnonzero(s[1:] * s[:-1] < 0):
                fk = lambda tt, k=k: float(np.asarray(self._time_f(np.array([tt]), self.p))[k][0])
                events.append(brentq(fk, grid[j], grid[j + 1], xtol=1e-14, rtol=1e-15))
            events += [grid[j] for j in np.flatnonzero(s == 0) if grid[j] > t0]
        return sorted(set(events))

    def expand(self, t, z) -> np.ndarray:
        """All variables of the reduced system (states, assigned and torn) from z."""
        if self.code.expand is None:
            return z
        return self.code.expand(t, z, self.p, self.m, np.empty(self.meta["n_all"]))

    def init_modes(self, t, z):
        """Relations take the values they have at the initial point."""
        for _ in range(10):   # relations may depend on variables computed in other modes
            if not self.n_roots:
                return
            g = self.relations(t, z)
            new = [_RELATION[op](x) for op, x in zip(self.meta["relations"], g)]
            if np.array_equal(new, self.m):
                return
            self.m[:] = new

    def set_whens(self, code, n_when, targets, owners) -> None:
        """When-clauses: rows 0..n_when-1 of ``code`` are the conditions (1/0), then one
        reinit value per action, applied to z[targets[k]] when its clause owners[k] fires."""
        self.when_code = code
        self.n_when = n_when
        self.when_targets = np.asarray(targets, dtype=np.int64)
        self.when_owners = np.asarray(owners, dtype=np.int64)
        self.when_log = []

    def _when_values(self, t, z, m):
        c = self.when_code
        return c.residual(t, z, self.p, m, np.empty(c.n_rows))

    def handle_event(self, t, z, zp, crossed):
        """Switch the relations that crossed; fire when-clauses whose condition became true."""
        m_old = self.m.copy()
        which = np.array(crossed, dtype=bool, copy=True)
        which[self._time_idx] = True     # a time event: settle the relations of time
        for _ in range(10):
            self._settle_modes(t, z, which)
            # event iteration: a relation on a variable that jumped at this event may now
            # clearly contradict its frozen value without having crossed; relations that
            # sit at zero keep theirs (their side was decided when they crossed)
            which = self._contradicted(t, z)
            if not which.any():
                break
        if getattr(self, "when_code", None) is None:
            return EventAction(changed=not np.array_equal(m_old, self.m))
        before = self._when_values(t, z, m_old)
        after = self._when_values(t, z, self.m)
        fired = (before[: self.n_when] < 0.5) & (after[: self.n_when] > 0.5)
        if not fired.any():
            return EventAction(changed=not np.array_equal(m_old, self.m))
        new = z.copy()
        act = fired[self.when_owners]
        new[self.when_targets[act]] = before[self.n_when:][act]   # values before the event
        self.when_log.append((t, np.flatnonzero(fired).tolist()))
        self._settle_modes(t, new, np.ones(self.n_roots, dtype=bool))
        return EventAction(y=new, changed=True)

    def _contradicted(self, t, z) -> np.ndarray:
        g = self.relations(t, z)
        tiny = 1e-9 * (1.0 + np.abs(g).max(initial=0.0))
        truth = np.array([_RELATION[op](x) for op, x in zip(self.meta["relations"], g)],
                         dtype=bool)
        return (np.abs(g) > tiny) & (truth != self.m)

    def settle_modes(self, t, z) -> None:
        """Every relation takes the value it has just after t (see _settle_modes)."""
        if self.n_roots:
            self._settle_modes(t, z, np.ones(self.n_roots, dtype=bool))

    def _settle_modes(self, t, z, which):
        """Relations in ``which`` take the value they have just after t.

        Where g is clearly non-zero that is its sign; where it sits at zero (the event
        point itself, or a ball reinitialized at h = 0 with v > 0) it is the sign a
        short step along z' gives.
        """
        g = self.relations(t, z)
        ops = self.meta["relations"]
        at_zero = which & (np.abs(g) <= 1e-9 * (1.0 + np.abs(g).max(initial=0.0)))
        for k in np.flatnonzero(which & ~at_zero):
            self.m[k] = _RELATION[ops[k]](g[k])
        if not at_zero.any():
            return
        zp = np.zeros_like(z)
        zp[self.state_index] = self.state_derivatives(t, z)
        dt = 1e-7 * (1.0 + abs(t))
        g_next = self.relations(t + dt, z + dt * zp)
        for k in np.flatnonzero(at_zero):
            self.m[k] = _RELATION[ops[k]](g_next[k])

    # -- dynamic state selection ----------------------------------------------------------
    def reselect_states(self, t, z, hysteresis=0.5) -> bool:
        """Re-choose the dummy derivatives; True when the choice (and so F) changed."""
        if self.dynamic is None:
            return False
        c = self.code
        vals = c.jacobian(t, z, self.p, self.m, np.empty(len(c.jac_rows)))
        new = self.dynamic.choose(vals, self.dummies, hysteresis)
        if new == self.dummies:
            return False
        self.dummies = new
        self.dynamic.switches.append((t, sorted(self.names[d] for d in new)))
        self._update_links()
        return True

    def after_step(self, t, z, zp) -> bool:
        """Called by the driver after each accepted step (dynamic state selection)."""
        return self.reselect_states(t, z)

    def set_parameters(self, values: dict) -> None:
        for name, value in values.items():
            try:
                k = self.param_names.index(name)
            except ValueError:
                zeros = self.meta.get("structural_zeros", ())
                why = (" (it was 0 at compile time and was evaluated as a structural zero: "
                       "compile with a non-zero value to tune it)") if name in zeros else ""
                raise KeyError(f"the model has no tunable parameter '{name}'{why}") from None
            self.p[k] = float(value)
