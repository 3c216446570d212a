"""Exact linear algebra over the rationals (``fractions.Fraction``), for the reference
solver of the random-network tests.

Matrices are lists of rows; vectors are lists.  Everything is plain Gauss-Jordan
elimination with exact pivots, so a rank, a null space or a regularity decision is a
fact about the numbers, not a judgement against a round-off threshold.  The matrices
are small (tens of rows) and sparse, so rows are eliminated only where they have a
non-zero entry.
"""
from __future__ import annotations

from fractions import Fraction
from typing import List, Sequence, Tuple

Matrix = List[List[Fraction]]

__all__ = ["zeros", "identity", "matmul", "transpose", "rref", "rank", "nullspace",
           "basis", "preimage", "inverse", "columns", "from_columns", "is_zero",
           "to_float"]


def zeros(m: int, n: int) -> Matrix:
    return [[Fraction(0)] * n for _ in range(m)]


def identity(n: int) -> Matrix:
    out = zeros(n, n)
    for i in range(n):
        out[i][i] = Fraction(1)
    return out


def matmul(a: Matrix, b: Matrix) -> Matrix:
    """a b; ``b`` may have zero columns (an empty basis)."""
    ncols = len(b[0]) if b else 0
    out = zeros(len(a), ncols)
    for i, row in enumerate(a):
        acc = out[i]
        for k, aik in enumerate(row):
            if aik:
                for j, bkj in enumerate(b[k]):
                    if bkj:
                        acc[j] += aik * bkj
    return out


def transpose(a: Matrix, ncols: int | None = None) -> Matrix:
    n = len(a[0]) if a else (ncols or 0)
    return [[a[i][j] for i in range(len(a))] for j in range(n)]


def columns(a: Matrix, n_rows: int) -> List[List[Fraction]]:
    """The columns of ``a`` as vectors (``n_rows`` fixes the length of an empty matrix)."""
    if not a:
        return []
    return [[a[i][j] for i in range(n_rows)] for j in range(len(a[0]))]


def from_columns(cols: Sequence[Sequence[Fraction]], n_rows: int) -> Matrix:
    return [[Fraction(c[i]) for c in cols] for i in range(n_rows)]


def rref(a: Matrix, ncols: int | None = None) -> Tuple[Matrix, List[int]]:
    """Reduced row echelon form and the pivot columns (a new matrix; ``a`` is kept)."""
    m = [list(map(Fraction, row)) for row in a]
    n = len(m[0]) if m else (ncols or 0)
    pivots, r = [], 0
    for c in range(n):
        if r == len(m):
            break
        p = next((i for i in range(r, len(m)) if m[i][c]), None)
        if p is None:
            continue
        m[r], m[p] = m[p], m[r]
        piv = m[r][c]
        if piv != 1:
            m[r] = [x / piv for x in m[r]]
        prow = m[r]
        nz = [j for j in range(c, n) if prow[j]]
        for i in range(len(m)):
            f = m[i][c] if i != r else 0
            if f:
                row = m[i]
                for j in nz:
                    row[j] -= f * prow[j]
        pivots.append(c)
        r += 1
    return m, pivots


def rank(a: Matrix) -> int:
    return len(rref(a)[1]) if a and a[0] else 0


def nullspace(a: Matrix, ncols: int) -> List[List[Fraction]]:
    """A basis of {x : a x = 0} (vectors of length ``ncols``)."""
    if not a:
        return [[Fraction(int(i == j)) for i in range(ncols)] for j in range(ncols)]
    r, pivots = rref(a, ncols)
    free = [j for j in range(ncols) if j not in set(pivots)]
    out = []
    for f in free:
        x = [Fraction(0)] * ncols
        x[f] = Fraction(1)
        for row, pc in zip(r, pivots):
            x[pc] = -row[f]
        out.append(x)
    return out


def basis(vectors: Sequence[Sequence[Fraction]], n: int) -> List[List[Fraction]]:
    """A basis of the span of ``vectors`` (length-n vectors), in reduced form."""
    if not vectors:
        return []
    r, pivots = rref([list(v) for v in vectors], n)
    return [r[i] for i in range(len(pivots))]


def preimage(m: Matrix, image_basis: Sequence[Sequence[Fraction]], n: int,
             n_rows: int) -> List[List[Fraction]]:
    """A basis of {x in Q^n : m x in span(image_basis)}.

    With L a basis of the left null space of the image (L K = 0), the condition is
    L m x = 0, so the preimage is the null space of L m.
    """
    if image_basis:
        left = nullspace([list(v) for v in image_basis], n_rows)   # rows y with y K = 0
    else:
        left = [[Fraction(int(i == j)) for i in range(n_rows)] for j in range(n_rows)]
    if not left:
        return nullspace([], n)
    return nullspace(matmul(left, m), n)


def inverse(a: Matrix) -> Matrix:
    """a^-1; raises ZeroDivisionError if a is singular."""
    n = len(a)
    r, pivots = rref([list(row) + [Fraction(int(i == j)) for j in range(n)]
                      for i, row in enumerate(a)], 2 * n)
    if pivots[:n] != list(range(n)):
        raise ZeroDivisionError("singular matrix")
    return [row[n:] for row in r]


def is_zero(a: Matrix) -> bool:
    return not any(x for row in a for x in row)


def to_float(a: Matrix, ncols: int | None = None):
    import numpy as np
    n = len(a[0]) if a else (ncols or 0)
    return np.array([[float(x) for x in row] for row in a], dtype=float).reshape(len(a), n)
