"""Dynamic state selection: dummy derivatives re-chosen numerically while the model runs.

Mattsson, Olsson & Elmqvist, "Dynamic selection of states in Dymola", Modelica Workshop
2000, on the levels of Mattsson & Söderlind's dummy-derivative procedure (SIAM J. Sci.
Comput. 14(3), 1993).  The levels are fixed by the structure: level 1 rows are the tops
of the differentiated equation chains, each next level the equations they were
differentiated from; a level's candidate columns are the highest derivatives (level 1)
or the antiderivatives of the dummies picked one level up (MS93 step 3).

Which candidates become dummies is decided on the level's Jacobian block, *scaled*:

    B = D_r  J_level  D_c,    (D_c)_jj = nominal_b(j),

with ``nominal_b(j)`` the nominal value of the base variable whose derivative chain
column j belongs to (picking column j as a dummy makes that variable algebraic) and D_r
scaling every row to a largest entry of one, so that neither the units of an equation
nor those of a variable decide.  Columns are picked greedily, Businger-Golub style (QR
with column pivoting: the column of largest remaining norm, then orthogonalization);
among columns within ``TIE`` of the largest, the user's state_select hint decides (a
variable to avoid as a state is a dummy first), then the derivative order (a
higher-order antiderivative becomes the dummy, so declared positions and speeds stay
states, and a rod's elongation is not computed as the difference of its end positions),
then the column norm.  (Scaling columns by the variables' current magnitudes was tried
and rejected: a velocity passing through zero then flips the choice for no geometric
reason, and a double pendulum switched 34 times instead of twice.)

Hysteresis: the current dummies are kept unless the best choice is clearly better
conditioned (|det| of the scaled block), and the search runs again only when the current
choice's quality -- |det| of its columns over the product of the norms of the whole
rows, a Hadamard ratio that sees a row's chosen entries shrink next to its alternatives
-- has fallen to half the quality of the *best* choice at the last search.  (Measured
against the kept choice's own quality instead, each search that keeps it lowers the
bar by half again: the Cartesian pendulum then kept x as a state until 76 degrees from
the vertical, where the constraint force's sensitivity to x, ~1/y^4, is 290 times its
value at the bottom, instead of switching at ~64 degrees.)
"""
from __future__ import annotations

import math

import numpy as np

__all__ = ["DynamicStateSelection"]

TIE = 0.5              # columns within this factor of the best count as tied
_DEGRADED = 0.5        # search again below half the best Hadamard ratio of the last search
_ALWAYS = 4            # state_select index of "always" (never a dummy)
_SMALL = 8             # levels up to this size: the keep-or-search test in plain floats


class DynamicStateSelection:
    """The run-time choice of dummy derivatives (module docstring).

    Parameters
    ----------
    sets : acausal.compiler.modelcode.DynamicSets
    nominal : array of the nominal value of every variable (full form: z is every
        variable, so indices agree).
    """

    def __init__(self, sets, nominal):
        self.levels = [list(rows) for rows in sets.levels]
        self.row_vars = sets.row_vars
        self.var_to_diff = list(sets.var_to_diff)
        self.diff_to_var = list(sets.diff_to_var)
        self.priority = list(sets.priority)
        self.orders = list(sets.orders)
        self.names = sets.names
        self.nominal = np.asarray(nominal, dtype=float)
        self.base = self._bases()
        self.switches = []                    # (time, new dummies)
        self.entry = {}
        self._reference = []
        self._plan = None                     # (choice, its blocks' layout) for keeps()

    def forget(self) -> None:
        """No memory of earlier searches (a new run starts from here)."""
        self._reference = []
        self._plan = None

    def _bases(self) -> list:
        out = []
        for v in range(len(self.var_to_diff)):
            b = v
            while self.diff_to_var[b] >= 0:
                b = self.diff_to_var[b]
            out.append(b)
        return out

    def bind(self, jac_rows, jac_cols) -> None:
        """Locate the level blocks in the generated Jacobian's value array (once)."""
        wanted = {r for rows in self.levels for r in rows}
        self.entry = {(int(r), int(c)): k for k, (r, c) in enumerate(zip(jac_rows, jac_cols))
                      if r in wanted}

    def choose(self, vals, z, current: set, hysteresis: float) -> set:
        """The dummies for Jacobian values ``vals`` (at the point z): ``current`` unless
        clearly worse."""
        scale = self.nominal
        if self.keeps(vals, current):
            return current
        dummies, allowed, best = set(), None, []
        for rows in self.levels:
            cols = self._columns(rows, allowed)
            block = self._block(vals, scale, rows, cols)
            pick = self._pivot(block, cols, len(rows))
            best.append(_quality(block, pick))
            keep = [k for k, c in enumerate(cols) if c in current]
            if len(keep) == len(rows) and _well_enough(block, keep, pick, hysteresis):
                pick = keep
            chosen = [cols[k] for k in pick]
            dummies.update(chosen)
            allowed = {self.diff_to_var[c] for c in chosen}
        self._reference = best
        self._plan = None
        return dummies

    def keeps(self, vals, current: set) -> bool:
        """The test before a search: on every level the quality of ``current`` is at
        least half the best quality of the last search (module docstring).  The blocks
        of a choice are laid out once (:meth:`watch`), so the test costs a gather and a
        small determinant per level after every step."""
        key = frozenset(current)
        if self._plan is None or self._plan[0] != key:
            self._plan = (key, self.watch(current))
        plan = self._plan[1]
        if plan is None:
            return False
        v = vals.tolist()     # levels are small: float arithmetic beats numpy's calls
        for entries, scales, keep, threshold in plan:
            B, norms = [], 1.0
            for r in entries:
                row = [v[k] * sc if k >= 0 else 0.0 for k, sc in zip(r, scales)]
                peak = max(map(abs, row))
                if peak > 0:
                    row = [x / peak for x in row]
                norms *= math.sqrt(sum(x * x for x in row))
                B.append(row)
            if len(keep) <= _SMALL:
                det = _absdet([[row[j] for j in keep] for row in B])
            else:
                det = abs(float(np.linalg.det(np.array(B)[:, keep])))
            if not (det / norms if norms > 0 else 0.0) >= threshold:
                return False
        return True

    def watch(self, current: set):
        """What :meth:`choose` tests before it searches, laid out for a compiled step loop
        that tests it itself after every step (:mod:`acausal.solvers.cbdf_dyn`): per
        level ``(entries, scales, keep, threshold)`` -- each row's index into the
        Jacobian value array for every candidate column (-1: a structural zero), the
        columns' scales, the positions of the current dummies among the candidates and
        the least quality that keeps them.  None when :meth:`choose` would search at
        once (no search yet, or ``current`` is not one dummy per row of every level)."""
        if not current or len(self._reference) != len(self.levels):
            return None
        out, allowed = [], None
        for rows, r0 in zip(self.levels, self._reference):
            cols = self._columns(rows, allowed)
            keep = [k for k, c in enumerate(cols) if c in current]
            if len(keep) != len(rows):
                return None
            entries = [[self.entry.get((r, c), -1) for c in cols] for r in rows]
            scales = [float(self.nominal[self.base[c]]) for c in cols]
            out.append((entries, scales, keep, _DEGRADED * r0))
            allowed = {self.diff_to_var[cols[k]] for k in keep}
        return out

    def _columns(self, rows, allowed):
        return sorted({v for r in rows for v in self.row_vars[r]
                       if (v in allowed if allowed is not None else self.var_to_diff[v] < 0)})

    def _block(self, vals, scale, rows, cols):
        block = np.zeros((len(rows), len(cols)))
        for i, r in enumerate(rows):
            for j, c in enumerate(cols):
                k = self.entry.get((r, c))
                if k is not None:
                    block[i, j] = vals[k] * scale[self.base[c]]
        peak = np.abs(block).max(axis=1, keepdims=True)
        return block / np.where(peak > 0, peak, 1.0)

    def _pivot(self, block, cols, k) -> list:
        """Greedy column pivoting with the preference order of the module docstring."""
        R = block.copy()
        free = [j for j, c in enumerate(cols) if self.priority[self.diff_to_var[c]] < _ALWAYS]
        chosen = []
        for _ in range(k):
            norms = {j: float(np.linalg.norm(R[:, j])) for j in free if j not in chosen}
            if not norms:
                break
            best = max(norms.values())
            tied = [j for j, n in norms.items() if n >= TIE * best and n > 0]
            if not tied:
                tied = list(norms)
            j = min(tied, key=lambda j: (self.priority[self.diff_to_var[cols[j]]],
                                         -self.orders[self.diff_to_var[cols[j]]],
                                         -norms[j], j))
            chosen.append(j)
            q = R[:, j] / (np.linalg.norm(R[:, j]) or 1.0)
            R -= np.outer(q, q @ R)
        return sorted(chosen)


def _quality(B, keep) -> float:
    """|det| of the chosen columns over the product of the *whole* rows' norms (a
    Hadamard ratio that sees a row's chosen entries shrink next to its alternatives)."""
    norms = np.prod(np.sqrt((B * B).sum(axis=1)))
    if not norms > 0:
        return 0.0
    # a 1 x 1 determinant is its entry (LAPACK's LU gives exactly that, more slowly)
    det = B[0, keep[0]] if len(keep) == 1 else np.linalg.det(B[:, keep])
    return abs(float(det)) / norms


def _absdet(A) -> float:
    """|det| of a small square matrix (lists of floats, overwritten): Gaussian
    elimination with partial pivoting, as ``cbdf_dyn.c`` does in the compiled loop."""
    det, n = 1.0, len(A)
    for j in range(n):
        p = max(range(j, n), key=lambda i: abs(A[i][j]))
        if A[p][j] == 0.0:
            return 0.0
        A[j], A[p] = A[p], A[j]
        d = A[j][j]
        det *= d
        for i in range(j + 1, n):
            f = A[i][j] / d
            if f:
                A[i] = [a - f * b for a, b in zip(A[i], A[j])]
    return abs(det)


def _well_enough(block, keep, best, hysteresis):
    """Keep the current dummies unless the best choice is clearly better conditioned."""
    cur = abs(np.linalg.det(block[:, keep]))
    new = abs(np.linalg.det(block[:, best]))
    return cur >= hysteresis * new
