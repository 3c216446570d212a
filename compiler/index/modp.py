"""Full row rank of a sparse rational matrix, certified modulo a prime.

Reducing rationals (with denominators prime to p) mod p is a ring homomorphism, so
every minor of the reduced matrix is the reduction of the rational minor: full row rank
mod p proves full row rank over the rationals (the converse fails only when p divides
every maximal minor, which a caller settles by exact elimination).

The elimination pivots as :mod:`acausal.compiler.algebra.exact` does (the column with the
fewest non-zeros, then its shortest row), first on rows kept as dictionaries.  On the
constant blocks of a network that order keeps the fill small until a few hundred rows
are left, which then fill in: on a random R/L/C network of 100k equations (one block of
29 438 rows, 87 399 non-zeros) 97 % of the 5.5 million row updates fell on the last
600 pivots, where the active rows are 2-30 % full.  So once the active part is small
and no longer sparse (:data:`DENSE_ROWS`, :data:`DENSE_FILL`), it is moved into a
numpy array and eliminated there with the same pivot rule, a pivot's updates one
array operation.  The rank does not depend on the pivot order; the order only decides
how much fills in.
"""
from __future__ import annotations

import heapq

import numpy as np

__all__ = ["PRIME", "full_row_rank_mod_p"]

# the largest prime below 2**30: residues are one CPython digit and their products two
# (with 2**61 - 1 the products were five-digit integers, a third of the elimination);
# a product of two residues also fits numpy's int64 (< 2**60)
PRIME = 1073741789

DENSE_ROWS = 3000       # active rows at most, for the array (72 MB at 3000 x 3000)
DENSE_FILL = 0.005      # and non-zeros at least this share of active rows x rows
_CHECK_EVERY = 64       # pivots between two looks at the active part's size


def full_row_rank_mod_p(rows: dict, p: int = PRIME) -> bool:
    """Whether ``rows`` ({row: {column: Fraction}}) have full row rank modulo ``p``
    (False also when a denominator is divisible by ``p``)."""
    a, col_rows = {}, {}
    nnz = 0
    for r, vals in rows.items():
        row = {}
        for c, q in vals.items():
            if q:
                if q.denominator % p == 0:
                    return False
                v = q.numerator * pow(q.denominator, -1, p) % p
                if v:
                    row[c] = v
                    col_rows.setdefault(c, set()).add(r)
        a[r] = row
        nnz += len(row)
    heap = [(len(rs), c) for c, rs in col_rows.items()]
    heapq.heapify(heap)
    done, rank, since = set(), 0, 0
    while heap:
        if since >= _CHECK_EVERY:
            since = 0
            if len(a) <= DENSE_ROWS and nnz >= DENSE_FILL * len(a) * len(a):
                return rank + _dense_rank(a, col_rows, done, p) == len(rows)
        count, c = heapq.heappop(heap)
        rows_c = col_rows[c]
        if c in done or count != len(rows_c):
            continue                    # stale entry: the count changed since
        done.add(c)
        if count == 0:
            continue
        piv = min(rows_c, key=lambda r: (len(a[r]), r))
        pivot_row = a.pop(piv)
        nnz -= len(pivot_row)
        inv = pow(pivot_row[c], -1, p)
        prow = list(pivot_row.items())
        for q in sorted(rows_c - {piv}):
            qrow = a[q]
            get = qrow.get
            f = qrow[c] * inv % p
            for k, v in prow:            # row_q -= f row_p: zero at c
                x = (get(k, 0) - f * v) % p
                if x:
                    if k not in qrow:
                        col_rows[k].add(q)
                        nnz += 1
                    qrow[k] = x
                elif k in qrow:
                    del qrow[k]
                    col_rows[k].discard(q)
                    nnz -= 1
        for k, _ in prow:
            col_rows[k].discard(piv)
            if k not in done:
                heapq.heappush(heap, (len(col_rows[k]), k))
        rank += 1
        since += 1
    return rank == len(rows)


def _dense_rank(a: dict, col_rows: dict, done: set, p: int) -> int:
    """The rank mod p of the active rows ``a`` (their columns not in ``done``), by
    elimination in an int64 array with the sparse phase's pivot rule."""
    rows = sorted(a)
    cols = sorted(c for c, rs in col_rows.items() if rs and c not in done)
    if not rows or not cols:
        return 0
    where = {c: k for k, c in enumerate(cols)}
    A = np.zeros((len(rows), len(cols)), dtype=np.int64)
    for i, r in enumerate(rows):
        row = a[r]
        A[i, [where[c] for c in row]] = list(row.values())
    nz = A != 0
    col_count = nz.sum(axis=0)
    row_len = nz.sum(axis=1)
    big = len(rows) + 1
    free = np.ones(len(cols), dtype=bool)      # columns not yet pivoted on
    rank = 0
    while True:
        candidates = np.where(free & (col_count > 0), col_count, big)
        c = int(np.argmin(candidates))
        if candidates[c] == big:
            return rank
        free[c] = False
        hit = np.flatnonzero(A[:, c])
        piv = int(hit[np.argmin(row_len[hit])])     # the first of the shortest rows
        others = hit[hit != piv]
        pcols = np.flatnonzero(A[piv])
        pvals = A[piv, pcols]
        if len(others):
            inv = pow(int(A[piv, c]), -1, p)
            f = A[others, c] * inv % p
            block = np.ix_(others, pcols)
            old = A[block]
            new = (old - f[:, None] * pvals[None, :]) % p
            change = (new != 0).astype(np.int64) - (old != 0)
            col_count[pcols] += change.sum(axis=0)
            row_len[others] += change.sum(axis=1)
            A[block] = new
        col_count[pcols] -= 1
        A[piv, pcols] = 0
        row_len[piv] = 0
        rank += 1
