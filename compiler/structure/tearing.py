"""Tearing of an algebraic loop.

A greedy heuristic in the line of Cellier & Kofman, "Continuous System Simulation",
Springer 2006, ch. 7 (tearing by causalization with heuristic choice of tearing
variables; see also Carpanzano, "Order reduction of general nonlinear DAE systems by
automatic tearing", Math. Comput. Model. Dyn. Syst. 6(2), 2000):

1. Causalize: while some equation has exactly one unknown left and can be solved for
   it explicitly, assign it (smallest equation index first).
2. If unknowns remain, declare one of them an iteration variable: the one that would
   make the most equations solvable at once (ties: more occurrences, then lower index),
   and go to 1.
3. Equations that are not assigned when all their unknowns are known are residuals.

Every variable ends up assigned or an iteration variable and every equation assigned or
a residual, and assignments pair one equation with one variable, so there are exactly
as many residuals as iteration variables.
"""
from __future__ import annotations

import heapq
from dataclasses import dataclass
from typing import Callable, Optional, Sequence

from .graph import LINEAR_PARAM, LINEAR_VAR, Structure

__all__ = ["Tearing", "tear"]


@dataclass
class Tearing:
    """Result of :func:`tear`.

    Attributes
    ----------
    iteration_vars : list of int
        Variables guessed by the nonlinear solver.
    residual_eqs : list of int
        Equations left as residuals, ``len(residual_eqs) == len(iteration_vars)``.
    inner : list of (int, int)
        ``(eq, var)``: solve eq explicitly for var, in this order; each uses only
        variables known outside the block, iteration variables and earlier inner vars.
    """

    iteration_vars: list
    residual_eqs: list
    inner: list


class _State:
    def __init__(self, s: Structure, eqs, vars, ok: Callable):
        self.ok = ok
        self.unknown = set(vars)
        self.uvars = {e: [v for v in s.graph[e] if v in self.unknown] for e in eqs}
        self.cnt = {e: len(vs) for e, vs in self.uvars.items()}
        self.var_eqs = {v: [] for v in vars}
        for e in sorted(eqs):
            for v in self.uvars[e]:
                self.var_eqs[v].append(e)
        self.done = set()                 # equations assigned or residual
        self.heap = [e for e in sorted(eqs) if self.cnt[e] == 1]
        self.inner, self.residuals, self.tears = [], [], []
        # candidate tearing variables: lazy heap of (-enables, -occurs, v); a var's
        # score changes only when an equation containing it changes, so only those
        # are re-scored ("dirty") before the next choice
        self.dirty, self.scores = set(vars), []

    def last_unknown(self, e: int) -> int:
        return next(v for v in self.uvars[e] if v in self.unknown)

    def make_known(self, v: int) -> None:
        self.unknown.discard(v)
        for e in self.var_eqs[v]:
            if e in self.done:
                continue
            self.dirty.update(self.uvars[e])
            self.cnt[e] -= 1
            if self.cnt[e] == 1:
                heapq.heappush(self.heap, e)
            elif self.cnt[e] == 0:        # step 3: nothing left to solve for
                self.done.add(e)
                self.residuals.append(e)

    def causalize(self) -> None:
        """Step 1."""
        while self.heap:
            e = heapq.heappop(self.heap)
            if e in self.done or self.cnt[e] != 1:
                continue
            v = self.last_unknown(e)
            if self.ok(e, v):
                self.dirty.update(self.uvars[e])
                self.done.add(e)
                self.inner.append((e, v))
                self.make_known(v)

    def score(self, v: int) -> tuple:
        enables = occurs = 0
        for e in self.var_eqs[v]:
            if e in self.done:
                continue
            occurs += 1
            if self.cnt[e] == 2:
                w = next(u for u in self.uvars[e] if u in self.unknown and u != v)
                enables += self.ok(e, w)
        return (-enables, -occurs, v)

    def pick_tear(self) -> int:
        """Step 2: the unknown whose guess enables the most assignments."""
        for v in sorted(self.dirty):
            if v in self.unknown:
                heapq.heappush(self.scores, self.score(v))
        self.dirty.clear()
        while True:
            key = heapq.heappop(self.scores)
            if key[2] in self.unknown and key == self.score(key[2]):
                return key[2]


def tear(s: Structure, eqs: Sequence[int], vars: Sequence[int],
         allow_linear_var: bool = False,
         solvable: Optional[Callable[[int, int], bool]] = None) -> Tearing:
    """Tear the algebraic block (`eqs`, `vars`) of `s`.

    Parameters
    ----------
    s : Structure
    eqs, vars : sequence of int
        The block: as many equations as unknowns.  Other variables are known.
    allow_linear_var : bool
        Also solve explicitly where the coefficient is LINEAR_VAR (valid while that
        coefficient is non-zero).  By default only LINEAR_CONST and LINEAR_PARAM.
    solvable : callable, optional
        ``solvable(eq, var) -> bool`` overrides the coefficient test.

    Returns
    -------
    Tearing
    """
    if len(eqs) != len(vars):
        raise ValueError(f"block is not square: {len(eqs)} equations, {len(vars)} vars")
    kmax = LINEAR_VAR if allow_linear_var else LINEAR_PARAM
    ok = solvable or (lambda e, v: s.coeff[e].get(v, kmax + 1) <= kmax)
    st = _State(s, eqs, vars, ok)
    st.causalize()
    while st.unknown:
        v = st.pick_tear()
        st.tears.append(v)
        st.make_known(v)
        st.causalize()
    st.residuals += [e for e in sorted(eqs) if e not in st.done]
    return Tearing(st.tears, st.residuals, st.inner)
