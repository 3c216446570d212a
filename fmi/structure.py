"""Structural dependencies of an exported model, for ``ModelStructure``.

From the expressions of the generated :class:`~acausal.compiler.backends.codegen.Program` (what
every output, row and assigned variable reads, through the assignments in BLT order):

* continuous time: the algebraic unknowns z[A] solved from G(t, z) = 0 depend on what
  the rows of their block read (the states, parameters) and on the unknowns of the
  blocks before them; found as the least fixed point of
      dep(a) = direct(row(a)) U  union of dep(a') over the unknowns a' that row(a) reads,
  with row(a) a perfect matching of G's rows to A (Hopcroft & Karp 1973, scipy), which
  on the condensation of the block graph is the BLT order's transitive closure;
* initialization: the same over every z with the rows [G; initial rows], whose knowns
  are the parameters alone.
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sps
from scipy.sparse.csgraph import maximum_bipartite_matching

__all__ = ["Reads", "solved_dependencies"]


class Reads:
    """What each expression of a Program reads, directly and through the assignments:
    ``of(expr) -> (set of z indices, set of parameter indices)``; ``modes(expr)``: the
    discrete-state entries (relation values, frozen floor values) it reads."""

    def __init__(self, prog):
        self.prog = prog
        self._assigned = []
        for k, e in enumerate(prog.assigned):
            ys, ps, ms = self._direct(e)
            for b in prog.reads[k]:          # assigned variables come in BLT order
                ys |= self._assigned[b][0]
                ps |= self._assigned[b][1]
                ms |= self._assigned[b][2]
            self._assigned.append((ys, ps, ms))

    def _direct(self, e):
        out = {"y": set(), "p": set(), "m": set()}
        for q in e.free_symbols:
            where = self.prog.refs.get(q)
            if where is None:
                continue
            if where[0] in out:
                out[where[0]].add(where[1])
            elif where[0] == "a" and where[1] < len(self._assigned):
                for into, got in zip(out.values(), self._assigned[where[1]]):
                    into |= got
        return out["y"], out["p"], out["m"]

    def of(self, expr):
        return self._direct(expr)[:2]

    def modes(self, expr):
        return self._direct(expr)[2]


def solved_dependencies(row_reads, unknowns, n_z):
    """For square rows over ``unknowns`` (z indices), each unknown's dependencies on the
    z entries that are not unknowns and on parameters: ``{z index: (zs, ps)}``.

    ``row_reads[r] = (zs, ps)`` is what row r reads."""
    unknowns = list(unknowns)
    col = {z: j for j, z in enumerate(unknowns)}
    n = len(unknowns)
    if n == 0:
        return {}
    rows, cols = [], []
    for r, (zs, _) in enumerate(row_reads):
        for z in zs:
            if z in col:
                rows.append(r)
                cols.append(col[z])
    graph = sps.csr_matrix((np.ones(len(rows)), (rows, cols)), shape=(len(row_reads), n))
    match = maximum_bipartite_matching(graph, perm_type="row")   # column j -> its row
    deps = {}
    for j, z in enumerate(unknowns):
        r = match[j]
        if r < 0:
            # structurally singular here: depends on everything its rows could read
            deps[z] = (set(range(n_z)) - set(unknowns), set().union(*(p for _, p in row_reads)))
        else:
            zs, ps = row_reads[r]
            deps[z] = ({k for k in zs if k not in col}, set(ps))
    reads_of = {z: {k for k in row_reads[match[j]][0] if k in col and k != z}
                for j, z in enumerate(unknowns) if match[j] >= 0}
    changed = True
    while changed:                      # least fixed point: the closure over the blocks
        changed = False
        for z, before in reads_of.items():
            zs, ps = deps[z]
            n0 = len(zs) + len(ps)
            for b in before:
                zs |= deps[b][0]
                ps |= deps[b][1]
            if len(zs) + len(ps) != n0:
                changed = True
    return deps
