"""The sparse LU of the compiled BDF step loop (``cbdf_sparse.c``), for systems with more
than :data:`~acausal.solvers.cbdf.MAX_DENSE` unknowns.

The C side factors ``dF/dy + cj dF/dy'`` on the problem's fixed CSC pattern
(``jac_pattern``, one slot per position: :meth:`CompiledModel.jacobian`), assembling the
values in place from the generated Jacobian's entries.  The column order and the
preferred pivot rows come from one SuperLU factorization (:func:`scipy.sparse.linalg.splu`,
COLAMD) of the first iteration matrix, made here: :func:`analysis`.  Each later
factorization keeps them while the preferred pivot passes a threshold test and pivots
on the largest entry of its column otherwise (``cbdf_sparse.c``), so a matrix whose
values drift far from the analysed one is still factored stably, at most with more fill.
"""
from __future__ import annotations

import weakref

import numpy as np

__all__ = ["SparseLU", "analysis"]


def analysis(A, perms=None):
    """(column order q, preferred pivot row of every step, a guess of nnz(L + U),
    SuperLU's ``(perm_c, perm_r)``) of the CSC matrix ``A`` (``perms``: those of its
    factorization, if made already): step k factors column ``q[k]`` and prefers row
    ``pref[k]``.  A matrix SuperLU cannot factor gives the natural order and no
    preference (the C factorization then pivots on its own), and perms None."""
    from scipy.sparse.linalg import splu
    n = A.shape[0]
    if perms is None:
        try:
            if not np.all(np.isfinite(A.data)):
                raise RuntimeError("not finite")
            lu = splu(A, permc_spec="COLAMD")
        except RuntimeError:
            return np.arange(n), np.full(n, -1), 2 * A.nnz, None
        perms = (lu.perm_c, lu.perm_r)
    perm_c, perm_r = perms
    q = np.empty(n, dtype=np.int64)
    q[perm_c] = np.arange(n)
    pref = np.empty(n, dtype=np.int64)
    pref[perm_r] = np.arange(n)
    return q, pref, 2 * A.nnz, perms


def _ptr(a: np.ndarray) -> int:
    return a.__array_interface__["data"][0]


class SparseLU:
    """A factorization object of ``cbdf_sparse.c`` on the CSC pattern ``(indptr,
    indices)`` of an n x n matrix; ``slot[e]`` is the position of the e-th entry of the
    problem's ``jac_pattern`` (entries at one position add up); ``A``: a matrix of that
    pattern to analyse, ``perms`` SuperLU's permutations of it if known
    (:func:`analysis`).  ``handle`` is what the step loop gets; ``perms`` SuperLU's
    permutations it was made with (None when SuperLU could not factor ``A``)."""

    def __init__(self, lib, n, indptr, indices, slot, A, perms=None):
        q, pref, cap, self.perms = analysis(A, perms)
        arrays = [np.ascontiguousarray(a, dtype=np.int64) for a in
                  (indptr, indices, slot, q, pref)]
        h = lib.sparse_new(int(n), *map(_ptr, arrays[:2]), len(arrays[2]), _ptr(arrays[2]),
                           _ptr(arrays[3]), _ptr(arrays[4]), int(cap))
        if not h:
            raise MemoryError("no memory for the sparse LU")
        self.lib, self.n, self.handle = lib, int(n), h
        self.nnz = int(arrays[0][-1])
        self._finalizer = weakref.finalize(self, lib.sparse_free, h)
        # views and pointers made once: a solve is a few microseconds of C
        self._values = np.ctypeslib.as_array(lib.sparse_values(h), (max(self.nnz, 1),))
        self._values = self._values[:self.nnz]
        self._x = np.zeros(self.n)
        self._xp = _ptr(self._x)

    def factor(self, data) -> int:
        """Factor the matrix with CSC values ``data``: 0, or 4 (singular) / 5 (not
        finite) as the step loop's failure kinds."""
        self._values[:] = data
        return int(self.lib.sparse_factor(self.handle))

    def solve(self, b) -> np.ndarray:
        """``A^{-1} b`` with the last factorization."""
        self._x[:] = b
        self.lib.sparse_solve(self.handle, self._xp)
        return self._x.copy()

    def fill(self) -> int:
        """nnz(L) + nnz(U) of the last factorization, diagonals included."""
        return int(self.lib.sparse_nnz(self.handle))
