"""Linear solves with the BDF iteration matrix  J = dF/dy + cj dF/dy'.

The corrector of a BDF step solves ``J delta = -F`` with a factorization that is kept
across steps as long as the simplified Newton iteration converges (Brenan, Campbell &
Petzold 1996, sec. 5.2; Hindmarsh et al. 2005).  Two back ends are
chosen automatically from what the problem supplies:

* dense LU (LAPACK ``getrf``/``getrs`` through :mod:`scipy.linalg`) for small systems,
  called directly so that a solve costs a few microseconds of Python overhead;
* sparse LU (SuperLU through :func:`scipy.sparse.linalg.splu`) when the problem gives a
  ``jac_pattern`` or returns a scipy.sparse matrix and ``n`` exceeds
  :data:`SPARSE_THRESHOLD`.

A singular iteration matrix raises :class:`SingularMatrixError`, which carries the
equations (rows) and variables (columns) involved, found first structurally (maximum
bipartite matching: unmatched rows/columns) and, for a structurally regular matrix,
numerically (the singular vectors of the smallest singular value).
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp
from scipy.linalg import get_lapack_funcs
from scipy.sparse.csgraph import maximum_bipartite_matching
from scipy.sparse.linalg import splu

__all__ = ["SPARSE_THRESHOLD", "LinearSolver", "SingularMatrixError", "singular_block",
           "make_linear_solver"]

#: Systems larger than this use sparse LU when the problem offers sparsity.
SPARSE_THRESHOLD = 60

# A pivot this small relative to the largest one is treated as zero: below it, LU
# solutions carry no correct digits and a Newton step built on them cannot converge.
_PIVOT_RTOL = 64 * np.finfo(float).eps


class SingularMatrixError(np.linalg.LinAlgError):
    """The iteration matrix is (numerically) singular.

    Attributes
    ----------
    rows, cols : list of int
        Equations and variables of the singular block (a best guess when numerical).
    """

    def __init__(self, message: str, rows=(), cols=(), matrix=None):
        super().__init__(message)
        self._rows = [int(r) for r in rows]
        self._cols = [int(c) for c in cols]
        self._matrix = matrix    # analysed on first access: a caller may just retry

    def _analyse(self) -> None:
        if self._matrix is not None:
            rows, cols = singular_block(self._matrix)
            self._rows, self._cols = [int(r) for r in rows], [int(c) for c in cols]
            self._matrix = None

    @property
    def rows(self) -> list:
        self._analyse()
        return self._rows

    @property
    def cols(self) -> list:
        self._analyse()
        return self._cols


def _structural_defect(S: sp.csr_matrix):
    """Rows and columns left unmatched by a maximum bipartite matching of ``S != 0``."""
    pattern = sp.csr_matrix((np.ones(S.nnz), S.indices, S.indptr), shape=S.shape)
    pattern.eliminate_zeros()
    col_of_row = maximum_bipartite_matching(pattern, perm_type="column")
    row_of_col = maximum_bipartite_matching(pattern, perm_type="row")
    return np.flatnonzero(col_of_row < 0), np.flatnonzero(row_of_col < 0)


def singular_block(J, max_dense: int = 3000):
    """Locate the equations and variables responsible for the singularity of ``J``.

    Parameters
    ----------
    J : ndarray or scipy.sparse matrix
        A square matrix believed singular.
    max_dense : int
        Largest size for which the numerical (SVD) analysis is attempted.

    Returns
    -------
    rows, cols : ndarray of int
        Unmatched rows/columns if ``J`` is structurally singular; otherwise the
        components above 10 % of the largest in the left/right singular vectors of the
        smallest singular value.  Empty when nothing can be said.
    """
    S = sp.csr_matrix(J)
    S.eliminate_zeros()
    rows, cols = _structural_defect(S)
    if rows.size or cols.size:
        return rows, cols
    if S.shape[0] > max_dense:
        return np.empty(0, int), np.empty(0, int)
    A = S.toarray()
    A = A / np.maximum(np.abs(A).max(axis=1, keepdims=True), 1e-300)  # row equilibration
    u, _, vt = np.linalg.svd(A)
    left, right = np.abs(u[:, -1]), np.abs(vt[-1])
    return np.flatnonzero(left > 0.1 * left.max()), np.flatnonzero(right > 0.1 * right.max())


class LinearSolver:
    """Factor-once, solve-many LU of the iteration matrix.

    Parameters
    ----------
    n : int
        System size.
    sparse : bool or None
        Force the back end; None decides at the first :meth:`factor` call (sparse when
        the matrix is scipy.sparse or ``pattern`` is given, and ``n > SPARSE_THRESHOLD``).
    pattern : (rows, cols) or None
        Structural non-zeros, as in ``DAEProblem.jac_pattern``.
    """

    def __init__(self, n: int, sparse: bool | None = None, pattern=None):
        self.n = int(n)
        self.sparse = sparse
        self.pattern = pattern
        self._lu = None
        self._piv = None
        self._getrf = self._getrs = None

    def _decide(self, J) -> None:
        if self.sparse is None:
            offered = sp.issparse(J) or self.pattern is not None
            self.sparse = bool(offered and self.n > SPARSE_THRESHOLD)
        if not self.sparse:
            self._getrf, self._getrs = get_lapack_funcs(("getrf", "getrs"),
                                                        (np.empty((1, 1)),))

    def factor(self, J) -> None:
        """LU-factor ``J``; raise :class:`SingularMatrixError` if it is singular."""
        if self.sparse is None or (not self.sparse and self._getrf is None):
            self._decide(J)
        if self.sparse:
            self._factor_sparse(J)
        else:
            self._factor_dense(J)

    def _factor_dense(self, J) -> None:
        A = J.toarray() if sp.issparse(J) else np.array(J, dtype=float, order="F")
        if not np.all(np.isfinite(A)):
            raise SingularMatrixError("iteration matrix has non-finite entries",
                                      *self._nonfinite(A))
        lu, piv, info = self._getrf(A, overwrite_a=True)
        d = np.abs(np.diagonal(lu))
        if info > 0 or d.min() <= _PIVOT_RTOL * d.max():
            raise SingularMatrixError("iteration matrix is singular", matrix=J)
        self._lu, self._piv = lu, piv

    def _factor_sparse(self, J) -> None:
        A = sp.csc_matrix(J, dtype=float)
        if not np.all(np.isfinite(A.data)):
            raise SingularMatrixError("iteration matrix has non-finite entries",
                                      *self._nonfinite(A.toarray()))
        try:
            lu = splu(A)
        except RuntimeError:
            lu = None
        if lu is not None:
            d = np.abs(lu.U.diagonal())
            if d.size and d.min() > _PIVOT_RTOL * d.max():
                self._lu = lu
                return
        raise SingularMatrixError("iteration matrix is singular", matrix=A)

    @staticmethod
    def _nonfinite(A: np.ndarray):
        bad = ~np.isfinite(A)
        return np.flatnonzero(bad.any(axis=1)), np.flatnonzero(bad.any(axis=0))

    def solve(self, b: np.ndarray) -> np.ndarray:
        """Return ``J^{-1} b`` with the last factorization."""
        if self.sparse:
            return self._lu.solve(b)
        x, _ = self._getrs(self._lu, self._piv, b)
        return x


def make_linear_solver(problem) -> LinearSolver:
    """The linear solver suited to ``problem`` (back end decided at the first factor)."""
    return LinearSolver(problem.n, None, getattr(problem, "jac_pattern", None))
