"""Mode search: an equilibrium or operating point in the modes it satisfies.

A model with relations (``if_else``, ``sign``, ``abs``, ``min``/``max``: limiters,
friction, switches, diodes) is a different smooth system in each *mode*, an assignment
of values to its relations and frozen floor values (``CompiledModel.m``).  A point
computed with the modes frozen solves the model only if it satisfies them: every
relation, evaluated at the point, has the value it was frozen at, judged on its own
scale (``CompiledModel.contradicted``).  The search, as Modelica's initialization
settles its relations (Modelica Language Specification 3.6, sec. 8.6), with a
safeguard against the cycles of a plain fixed-point iteration:

1. freeze the modes the start point has and solve;
2. evaluate the relations at the solution; if none is contradicted, that is the answer;
3. otherwise the candidates for the next solve are the mode with *every* contradicted
   item switched to its value at the solution (the fixed-point step), then the modes
   with *one* of them switched, in order.  Candidates are tried breadth first and a
   mode is never solved twice, so the two saturations of a limiter, each pointing at
   the other, end in the unsaturated mode between them instead of a cycle;
4. a mode in which the solve fails contributes the modes its last iterate contradicts;
5. at most ``max_solves`` solves.  A search that finds no consistent mode raises
   :class:`ModeConflict`, naming the relations that were contradicted on the way
   (``compiled.relation_text(k)``), or :class:`NoSolution` when no mode could be solved.
"""
from __future__ import annotations

import re
from collections import deque

import numpy as np
from ..errors import ModeConflict

__all__ = ["ModeConflict", "NoSolution", "search_modes", "relations_at_switch",
           "mode_values", "describe_items", "user_text"]


class NoSolution(Exception):
    """The frozen-mode system has no solution from this guess: ``message`` says why,
    ``z`` is the last iterate (or None)."""

    def __init__(self, message: str, z=None):
        super().__init__(message)
        self.message, self.z = message, z


def search_modes(compiled, t: float, z0: np.ndarray, solve, *, modes=None,
                 max_solves: int | None = None, prefix: str = ""):
    """(z, m, solves): a solution of ``solve`` in modes m that it satisfies.

    ``solve(z_guess)`` solves the model with ``compiled.m`` frozen and returns the full
    solver vector, or raises :class:`NoSolution`.  ``modes`` are the first modes tried
    (default: those of the start point, ``init_modes(t, z0)``).  ``compiled.m`` is left
    as the caller had it; ``prefix`` is taken off the names in messages.
    """
    c = compiled
    saved = c.m.copy()
    n_items = len(c.m)
    budget = max_solves if max_solves is not None else min(64, 4 * n_items + 8)
    try:
        if modes is None:
            c.init_modes(t, z0)
            first = c.m.copy()
        else:
            first = np.array(modes, dtype=float)
        frontier = deque([(first, np.array(z0, dtype=float))])
        tried, solves = set(), 0
        contradicted = np.zeros(n_items, dtype=bool)
        failures = []
        while frontier and solves < budget:
            m, guess = frontier.popleft()
            if m.tobytes() in tried:
                continue
            tried.add(m.tobytes())
            c.m[:] = m
            solves += 1
            try:
                z, solved = solve(guess), True
            except NoSolution as err:
                z, solved = err.z, False
                failures.append(err)
            if z is None or not np.all(np.isfinite(z)):
                continue
            c.m[:] = m
            bad = c.contradicted(t, z)
            if solved and not bad.any():
                return z, m.copy(), solves
            contradicted |= bad
            frontier.extend((cand, z) for cand in _successors(c, t, z, m, bad)
                            if cand.tobytes() not in tried)
    finally:
        c.m[:] = saved
    if not contradicted.any() and failures:
        raise failures[0]
    names = describe_items(c, np.flatnonzero(contradicted), prefix)
    why = (f"; {len(failures)} of the modes tried had no solution ({failures[0].message})"
           if failures else "")
    raise ModeConflict(
        f"no mode of the relations is consistent with its own solution after {solves} "
        f"solves (each solution contradicted the relation values it was computed with): "
        + "; ".join(names) + why, names, solves)


def _successors(c, t, z, m, bad):
    """The modes to try next: every contradicted item switched, then each alone."""
    masks = [bad]
    if bad.sum() > 1:
        masks += [_only(k, len(bad)) for k in np.flatnonzero(bad)]
    out = []
    for which in masks:
        c.m[:] = m
        c.discrete.settle(t, z, c.p, which, lambda: np.zeros(len(m)))
        out.append(c.m.copy())
    c.m[:] = m
    return out


def _only(k, n):
    mask = np.zeros(n, dtype=bool)
    mask[k] = True
    return mask


def describe_items(c, items, prefix: str = "") -> list:
    """The user's text of relations and floor values, by item index (names inside an
    analysis harness have ``prefix`` removed)."""
    return [user_text(c.relation_text(int(k)), prefix) for k in items]


def user_text(text: str, prefix: str = "") -> str:
    """``text`` with ``prefix`` taken off the dotted names that start with it."""
    if not prefix:
        return text
    return re.sub(r"(?<![\w.])" + re.escape(prefix), "", text)


def mode_values(c, prefix: str = "") -> dict:
    """{relation text: value} of the current modes (relations, then floor values)."""
    R = c.discrete.n_rel
    out = {}
    for k in range(len(c.m)):
        text = user_text(c.relation_text(k), prefix)
        out[text] = bool(c.m[k] > 0.5) if k < R else float(c.m[k])
    return out


def relations_at_switch(c, t, z) -> list:
    """Items that sit at their switching point at (t, z), within their tolerance, and
    whose value matters there: the other value changes the Jacobian of the model (a
    kink: the linearization depends on the side)."""
    if not len(c.m):
        return []
    R = c.discrete.n_rel
    v = c.discrete.values(t, z, c.p)
    tol = c.discrete.tolerance(t, z, c.p, v)
    dist = np.concatenate([v[:R], v[R:] - np.round(v[R:])])
    # an infinite limit (yMax = inf) has an infinite tolerance: never at its switch
    close = np.flatnonzero(np.isfinite(dist) & np.isfinite(tol) & (np.abs(dist) <= tol))
    if not close.size:
        return []
    zp = np.zeros(c.n)
    J0 = c.jacobian(t, z, zp, 0.0).toarray()
    saved = c.m.copy()
    out = []
    try:
        for k in close:
            c.m[k] = (1.0 - saved[k]) if k < R else saved[k] - 1.0
            J1 = c.jacobian(t, z, zp, 0.0).toarray()
            c.m[:] = saved
            scale = np.max(np.abs(J0), initial=0.0) + np.max(np.abs(J1), initial=0.0)
            if np.max(np.abs(J1 - J0), initial=0.0) > 1e-12 * scale:
                out.append(int(k))
    finally:
        c.m[:] = saved
    return out
