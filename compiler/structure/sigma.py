"""Pryce's Sigma-method of structural analysis.

Pryce, "A simple structural analysis method for DAEs", BIT Numer. Math. 41(2), 2001.
For the signature matrix ``sigma[i][j]`` (highest order of derivative of variable j in
equation i, -inf if absent):

1. find a highest-value transversal T (an assignment problem; the DAE is structurally
   nonsingular iff a finite one exists);
2. find the smallest offsets c (equations), d (variables) with
   ``d_j - c_i >= sigma_ij`` everywhere and equality on T, by the fixed-point
   iteration of the paper (section 3.4): start from c = 0, alternate
   ``d_j = max_i (sigma_ij + c_i)`` and ``c_i = d_T(i) - sigma_iT(i)``;
3. structural index ``nu = max c + (1 if some d_j == 0 else 0)`` (paper, eq. (13):
   an algebraic variable adds one to the index), degrees of freedom ``sum d - sum c``.

For a well-posed model ``c_i`` is the number of times Pantelides differentiates
equation i.
"""
from __future__ import annotations

import heapq
from dataclasses import dataclass

import numpy as np

from .graph import Structure
from .matching import _match, base_variables
from ...errors import StructurallySingular

__all__ = ["SigmaResult", "signature_matrix", "sigma_method"]

# Up to this size the assignment is solved densely (Hungarian method, O(n^2) vector
# operations); past it on the finite entries only (_sparse_transversal).  Neither needs
# scipy, whose import (0.3-0.5 s with scipy.sparse) is longer than the whole compile of
# a small model.
_OWN_LIMIT = 40


@dataclass
class SigmaResult:
    """Result of :func:`sigma_method`.

    Attributes
    ----------
    transversal : list of int
        ``transversal[i]``: the variable (column) assigned to equation i.
    c, d : list of int
        Canonical (smallest) equation and variable offsets.
    index : int
        Pryce's structural index.
    dof : int
        Degrees of freedom, ``sum(d) - sum(c)``.
    value : int
        Value of the transversal, ``sum sigma[i][transversal[i]]``.
    """

    transversal: list
    c: list
    d: list
    index: int
    dof: int
    value: int


def signature_matrix(s: Structure, sparse: bool = False) -> tuple:
    """Signature matrix of the DAE `s` over its base variables.

    Parameters
    ----------
    s : Structure
    sparse : bool
        Return a dict ``{(i, j): order}`` of the finite entries instead of a dense
        array (for large models; :func:`sigma_method` accepts both).

    Returns
    -------
    sigma : ndarray of float, shape (n_eqs, n_base), or dict
        Highest derivative order of each base variable's chain in each equation,
        ``-inf`` where the chain does not occur.
    columns : list of int
        The base variable (start of each derivative chain) of each column, ascending.
    """
    base = base_variables(s)
    columns = sorted({base[v] for v in range(s.n_vars)})
    col = {b: j for j, b in enumerate(columns)}
    column = [col[base[v]] for v in range(s.n_vars)]
    order = [s.order(v) for v in range(s.n_vars)]      # once per variable, not per entry
    entries = {}
    for e, vs in enumerate(s.graph):
        for v in vs:
            key = (e, column[v])
            k = order[v]
            if k > entries.get(key, -1):
                entries[key] = k
    if sparse:
        return entries, columns
    sigma = np.full((s.n_eqs, len(columns)), -np.inf)
    for (e, j), k in entries.items():
        sigma[e, j] = k
    return sigma, columns


def _entries(sigma) -> tuple:
    """(n_rows, n_cols, i, j, value) arrays of the finite entries, row-major order."""
    if isinstance(sigma, dict):
        keys = sorted(sigma)
        i = np.array([k[0] for k in keys], dtype=np.int64)
        j = np.array([k[1] for k in keys], dtype=np.int64)
        val = np.array([sigma[k] for k in keys], dtype=float)
        n = int(max(i.max(initial=-1), j.max(initial=-1))) + 1
        return n, n, i, j, val
    rows = [[-np.inf if x is None else x for x in row] for row in sigma]
    a = np.array(rows, float).reshape(len(rows), len(rows[0]) if rows else 0)
    i, j = np.nonzero(np.isfinite(a))
    return a.shape[0], a.shape[1], i, j, a[i, j]


def _certified(n: int, i, j, val, start):
    """The transversal of ``start = (transversal, c, d)`` if the offsets prove it one of
    highest value, else None.  The proof is the assignment problem's duality: offsets
    with ``d_j - c_i >= sigma_ij`` on every entry bound every transversal's value by
    ``sum d - sum c``, which a transversal on which they hold with equality reaches."""
    cols, c, d = (np.asarray(x, dtype=np.int64) for x in start)
    if cols.shape != (n,) or c.shape != (n,) or d.shape != (n,):
        return None
    if not np.array_equal(np.sort(cols), np.arange(n)):
        return None
    slack = d[j] - c[i] - val
    on_t = cols[i] == j
    if (slack < 0).any() or on_t.sum() != n or (slack[on_t] != 0).any():
        return None
    return cols


def _transversal(n: int, i, j, val) -> np.ndarray:
    """Step 1: column of each row in a maximum-value transversal."""
    if n <= _OWN_LIMIT:
        finite = np.zeros((n, n), bool)
        finite[i, j] = True
        top = val.max(initial=0.0)
        big = (n + 1) * (top - val.min(initial=0.0) + 1)
        a = np.full((n, n), -big)
        a[i, j] = val
        cols = _hungarian(-a)
        if not finite[np.arange(n), cols].all():
            raise StructurallySingular("signature matrix has no finite transversal")
        return cols
    return _sparse_transversal(n, i.tolist(), j.tolist(), [int(v) for v in val.tolist()])


def _sparse_transversal(n: int, rows: list, cols: list, vals: list) -> np.ndarray:
    """The primal-dual (Hungarian) method on the finite entries only, in integers.

    Offsets c (rows) and d (columns) with ``d_j - c_i >= sigma_ij`` are kept throughout
    (the dual of the assignment problem), starting from c = 0 and d_j the column
    maximum; the entries where equality holds (tight) are matched by Hopcroft-Karp,
    resumed from the previous matching.  While rows remain free, a Dijkstra search from
    them over the slacks ``d_j - c_i - sigma_ij`` (matched entries cost nothing) finds
    the distance D of the nearest free column, and each node reached closer than D has
    its offset raised by D minus its distance: the offsets stay feasible, matched
    entries stay tight and a shortest augmenting path becomes tight.  A perfect matching
    on tight entries is a transversal of highest value (its value equals
    ``sum d - sum c``, a bound for every transversal).  The rounds are about as many as
    the distinct distances, a few for a model: no dense n x n matrix and no solver
    import at any size."""
    adj = [[] for _ in range(n)]
    d = [None] * n
    for r, k, v in zip(rows, cols, vals):
        adj[r].append((k, v))
        if d[k] is None or v > d[k]:
            d[k] = v
    if None in d or not all(adj):
        raise StructurallySingular("signature matrix has no finite transversal")
    c = [0] * n
    l2r, r2l = [-1] * n, [-1] * n
    while True:
        tight = [[k for k, v in entries if d[k] - cr == v]
                 for entries, cr in zip(adj, c)]
        l2r, r2l = _match(tight, n, l2r, r2l)
        free = [r for r in range(n) if l2r[r] < 0]
        if not free:
            return np.array(l2r, dtype=np.int64)
        row_dist, col_dist, best = {}, {}, {}
        heap = [(0, 0, r) for r in free]          # (distance, 0 row / 1 column, index)
        reach = None
        while heap:
            dist, kind, x = heapq.heappop(heap)
            if kind == 0:
                if x in row_dist:
                    continue
                row_dist[x] = dist
                cx = c[x]
                for k, v in adj[x]:
                    nd = dist + d[k] - cx - v
                    if k not in col_dist and nd < best.get(k, nd + 1):
                        best[k] = nd
                        heapq.heappush(heap, (nd, 1, k))
            elif x not in col_dist and best[x] == dist:
                col_dist[x] = dist
                owner = r2l[x]
                if owner < 0:
                    reach = dist
                    break
                if owner not in row_dist:
                    heapq.heappush(heap, (dist, 0, owner))
        if reach is None:
            raise StructurallySingular("signature matrix has no finite transversal")
        for r, dist in row_dist.items():
            c[r] += reach - dist
        for k, dist in col_dist.items():
            d[k] += reach - dist


def _hungarian(cost: np.ndarray) -> np.ndarray:
    """Column of each row in a minimum-cost assignment of the square matrix ``cost``.

    The Hungarian method in its shortest-augmenting-path form (Kuhn 1955; Munkres 1957;
    O(n^3), with row potentials u and column potentials v, cost - u - v >= 0 throughout):
    each row in turn is added by growing a tree of tight edges Dijkstra-like from it
    until a free column is reached, then augmenting along the tree.  The costs here are
    integers, so the arithmetic is exact."""
    n = cost.shape[0]
    u, v = np.zeros(n + 1), np.zeros(n + 1)
    row_of = np.zeros(n + 1, dtype=np.int64)        # row_of[j]: row (1-based) of column j
    way = np.zeros(n + 1, dtype=np.int64)
    for i in range(1, n + 1):
        row_of[0], j0 = i, 0
        dist = np.full(n + 1, np.inf)
        used = np.zeros(n + 1, dtype=bool)
        while row_of[j0] != 0:
            used[j0] = True
            i0 = row_of[j0]
            reduced = cost[i0 - 1] - u[i0] - v[1:]
            better = ~used[1:] & (reduced < dist[1:])
            dist[1:][better] = reduced[better]
            way[1:][better] = j0
            free = np.where(used[1:], np.inf, dist[1:])
            j1 = int(np.argmin(free)) + 1
            delta = free[j1 - 1]
            u[row_of[used]] += delta
            v[used] -= delta
            dist[1:][~used[1:]] -= delta
            j0 = j1
        while j0:                                    # augment along the tree
            j1 = way[j0]
            row_of[j0] = row_of[j1]
            j0 = j1
    cols = np.empty(n, dtype=np.int64)
    cols[row_of[1:] - 1] = np.arange(n)
    return cols


def _offsets(n: int, i, j, val, cols) -> tuple:
    """Step 2: the fixed-point iteration for the smallest offsets, O(nnz) a sweep."""
    on_t = cols[i] == j
    s_t = np.empty(n)
    s_t[i[on_t]] = val[on_t]
    c = np.zeros(n)
    while True:
        d = np.full(n, -np.inf)
        np.maximum.at(d, j, val + c[i])
        c_new = d[cols] - s_t
        if np.array_equal(c_new, c):
            return c.astype(int), d.astype(int), int(s_t.sum())
        c = c_new


def sigma_method(sigma, start=None) -> SigmaResult:
    """Pryce's structural analysis of a square signature matrix.

    Parameters
    ----------
    sigma : array_like of shape (n, n), or dict
        ``sigma[i][j]``: order of variable j in equation i; ``None`` or ``-inf`` where
        absent.  Or a dict ``{(i, j): order}`` of the present entries.
    start : tuple, optional
        ``(transversal, c, d)`` found by other means (Pantelides' final matching and
        differentiation counts): taken as step 1's result when the offsets prove the
        transversal of highest value (:func:`_certified`), else step 1 runs.  The
        offsets returned are the smallest ones either way, computed from it.

    Returns
    -------
    SigmaResult

    Raises
    ------
    StructurallySingular
        Non-square matrix, or no finite transversal.
    """
    n, m, i, j, val = _entries(sigma)
    if n != m:
        raise StructurallySingular(f"signature matrix is not square: {n} x {m}")
    if n == 0:
        return SigmaResult([], [], [], 0, 0, 0)
    cols = _certified(n, i, j, val, start) if start is not None else None
    if cols is None:
        cols = _transversal(n, i, j, val)
    c, d, value = _offsets(n, i, j, val, cols)
    index = int(c.max()) + (1 if (d == 0).any() else 0)
    return SigmaResult([int(x) for x in cols], c.tolist(), d.tolist(), index,
                       int(d.sum() - c.sum()), value)
