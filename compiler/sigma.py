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

from dataclasses import dataclass

import numpy as np

from .graph import Structure
from .structure import StructurallySingular, base_variables

__all__ = ["SigmaResult", "signature_matrix", "sigma_method"]

_DENSE_LIMIT = 1000    # above this, the sparse assignment solver is used
# Up to this size the assignment is solved here (Hungarian method) rather than by
# scipy.optimize, whose import (0.3-0.4 s, with scipy.sparse and scipy.linalg) is longer
# than the whole compile of a small model; the pure-numpy method costs O(n^2) vector
# operations, under 20 ms at this size.
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
    entries = {}
    for e, vs in enumerate(s.graph):
        for v in vs:
            key = (e, col[base[v]])
            entries[key] = max(entries.get(key, 0), s.order(v))
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


def _transversal(n: int, i, j, val) -> np.ndarray:
    """Step 1: column of each row in a maximum-value transversal."""
    top = val.max(initial=0.0)
    if n <= _DENSE_LIMIT:
        finite = np.zeros((n, n), bool)
        finite[i, j] = True
        big = (n + 1) * (top - val.min(initial=0.0) + 1)
        a = np.full((n, n), -big)
        a[i, j] = val
        if n <= _OWN_LIMIT:
            cols = _hungarian(-a)
        else:
            from scipy.optimize import linear_sum_assignment
            _, cols = linear_sum_assignment(a, maximize=True)
        ok = finite[np.arange(n), cols].all()
    else:       # weights top+1-sigma are all >= 1: no entry is an implicit zero
        from scipy.sparse import csr_matrix
        from scipy.sparse.csgraph import min_weight_full_bipartite_matching
        w = csr_matrix((top + 1 - val, (i, j)), shape=(n, n))
        try:
            _, cols = min_weight_full_bipartite_matching(w)
            ok = True
        except ValueError:
            ok = False
    if not ok:
        raise StructurallySingular("signature matrix has no finite transversal")
    return np.asarray(cols)


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


def sigma_method(sigma) -> SigmaResult:
    """Pryce's structural analysis of a square signature matrix.

    Parameters
    ----------
    sigma : array_like of shape (n, n), or dict
        ``sigma[i][j]``: order of variable j in equation i; ``None`` or ``-inf`` where
        absent.  Or a dict ``{(i, j): order}`` of the present entries.

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
    cols = _transversal(n, i, j, val)
    c, d, value = _offsets(n, i, j, val, cols)
    index = int(c.max()) + (1 if (d == 0).any() else 0)
    return SigmaResult([int(x) for x in cols], c.tolist(), d.tolist(), index,
                       int(d.sum() - c.sum()), value)
