"""Linear solves with the BDF iteration matrix  J = dF/dy + cj dF/dy'.

The corrector of a BDF step solves ``J delta = -F`` with a factorization that is kept
across steps as long as the simplified Newton iteration converges (Brenan, Campbell &
Petzold 1996, sec. 5.2; Hindmarsh et al. 2005).  Two back ends are
chosen automatically from what the problem supplies:

* dense LU (LAPACK ``getrf``/``getrs`` through :mod:`scipy.linalg`) for small systems,
  called directly so that a solve costs a few microseconds of Python overhead; when
  scipy.linalg is not loaded yet and the compiled step loop's library is already built
  (:mod:`.cbdf`), its LU (``cbdf_lu.c``, partial pivoting, the same pivot test and
  equilibration) instead, since importing scipy.linalg takes 0.2-0.4 s, longer than a
  small model's whole run from a warm cache; when neither is there (the numpy backend,
  or the step loop's library still being built) and the system has at most
  :data:`NUMPY_LU_MAX` unknowns, a factorization is judged by an LU of numpy row
  operations (the same partial pivoting and pivot test) and solves call
  ``numpy.linalg.solve`` (LAPACK's ``gesv``) on the matrix judged, so that the first
  run of a small model never waits for scipy.linalg;
* sparse LU (SuperLU through :func:`scipy.sparse.linalg.splu`) when the problem gives a
  ``jac_pattern`` or returns a scipy.sparse matrix and ``n`` exceeds
  :data:`SPARSE_THRESHOLD`.  The iteration matrix keeps its pattern from one
  factorization to the next, so SuperLU's column order and pivot rows of the first are
  kept, and the next ones of that pattern are numeric refactorizations by the compiled
  step loop's sparse LU (:mod:`~acausal.solvers.cbdf_sparse`; when a C compiler is
  there), which pivots afresh where a kept pivot has become small.

A factorization whose pivots look singular is judged again on the *equilibrated*
matrix ``B = D_r J D_c`` (``D_r``, ``D_c`` diagonal): first every row, then every
column is scaled to a largest entry of one, as
LAPACK's ``xGEEQU`` (Anderson et al., *LAPACK Users' Guide*, 3rd ed. 1999, sec.
4.4.1; van der Sluis 1969 for why equilibration nearly minimizes the condition
number).  The units of a model set the scales of its rows (equations) and columns
(variables) arbitrarily -- a hydraulic chamber ``(V/beta) p' = q`` has a coefficient
~1e-13 in a row of its own -- so only pivots of the equilibrated matrix say anything
about singularity: a pivot of ``B`` below :data:`_PIVOT_RTOL` times its largest pivot
means ``J`` is singular to working precision.  Scaling the rows of ``J`` (the units of
the equations) leaves ``B`` unchanged up to rounding.  Scaling its columns (the units
of the variables) changes ``B`` only by a diagonal similarity, which leaves the pivots
alone, while every row's and column's largest entry stays on the diagonal (the usual
case of an iteration matrix); beyond that, one pass of equilibration removes most but
not all of it (an exactly invariant scaling needs a maximum-product matching, Duff &
Koster 2001 (MC64), not done here).  If ``B`` passes, its factorization is used and
solves use ``x = D_c B^{-1} D_r b``.  Equilibrating only then leaves the arithmetic of
the common, well-scaled case untouched (and costs nothing there).

An integrator may allow a *consistent* rank-deficient iteration matrix (``factor(J,
weights)``): two friction elements locked on one motion impose the same constraint twice,
so the force balance fixes only the sum of their locking forces (the MSL's
Rotational.Examples.LossyGearDemo2: "If both friction models are stuck, there is no
unique solution.  Still a reliable Modelica simulator should be able to handle this
situation").  Where the LU finds the matrix singular, the equilibrated matrix ``B`` is
then factored by its singular value decomposition (rank-revealing; singular values below
:data:`_RANK_RTOL` times the largest are zero) and each solve returns the minimum-norm
least-squares solution ``x = D_c B^+ D_r b``: no correction along the indeterminate
directions, which keep the split the last consistent solve chose.  The safeguards: the
matrix must be structurally regular (the problem's Jacobian pattern, else the entries of
a sparse matrix, else the nonzeros, admit a perfect matching: an unknown that no equation
reads, or an equation that reads none, is a modelling error, not an indeterminate split),
and the part
of ``D_r b`` that no ``x`` can produce (its component along the left null vectors, in the
units of the variables those rows constrain, weighted by ``weights``) must be within one
unit of the error test; otherwise the equations are inconsistent and the solve raises
:class:`SingularMatrixError`, as a singular matrix always did.

A singular iteration matrix raises :class:`SingularMatrixError`, which carries the
equations (rows) and variables (columns) involved, found first structurally (maximum
bipartite matching: unmatched rows/columns) and, for a structurally regular matrix,
numerically (the singular vectors of the smallest singular value of the equilibrated
matrix).
"""
from __future__ import annotations

import ctypes
import sys

import numpy as np

from .cbdf_library import library
from .cbdf_sparse import SparseLU

__all__ = ["SPARSE_THRESHOLD", "DENSE_MAX", "NUMPY_LU_MAX", "LinearSolver", "SingularMatrixError",
           "singular_block", "make_linear_solver", "equilibrate"]

#: Systems larger than this use sparse LU when the problem offers sparsity.
SPARSE_THRESHOLD = 60
#: Dense systems up to this size are factored by numpy row operations when the compiled
#: LU is not installed, rather than by LAPACK through scipy.linalg: a factorization
#: costs about n numpy calls, a few microseconds each, against 0.2-0.4 s for the import.
#: (Which LU runs depends on the size and the installation only, never on what a process
#: has imported: the same run gives the same numbers.)
NUMPY_LU_MAX = 16
#: Systems up to this size are built and factored dense where the caller chooses the
#: form: the compiled step loop's iteration matrix, and the Newton systems of
#: initialization and of the values at output times.  A dense LU of 200 unknowns takes
#: well under a millisecond, and a dense system needs no scipy.sparse (whose import,
#: with the SuperLU it brings, takes 0.3-0.5 s: more than a mid-size model's run, and
#: what every new worker process of a sweep would pay).
DENSE_MAX = 200

#: Largest system whose singular iteration matrix may be factored by its SVD (dense:
#: ``n^3`` work per factorization) when the integrator allows a consistent rank deficiency.
RANK_DEFICIENT_MAX = 400
# Singular values of the equilibrated matrix below this times the largest are zero.
_RANK_RTOL = 1e-10

# A pivot of the equilibrated matrix this small relative to the largest one is treated
# as zero: below it, LU solutions carry no correct digits and a Newton step built on
# them cannot converge.
_PIVOT_RTOL = 64 * np.finfo(float).eps


def issparse(J) -> bool:
    """Whether ``J`` is a scipy.sparse matrix.  None can exist before scipy.sparse is
    imported, so a dense problem never imports it (0.2-0.4 s)."""
    sparse = sys.modules.get("scipy.sparse")
    return sparse is not None and sparse.issparse(J)


def assemble(vals, rows, cols, shape, dense: bool = False):
    """The matrix with entries ``vals`` at ``(rows, cols)``, repeated positions summed in
    their order: CSR, or with ``dense`` an ndarray of the same values (what the dense LU
    of a small system factors, without importing scipy.sparse)."""
    if dense:
        A = np.zeros(shape)
        np.add.at(A, (rows, cols), vals)
        return A
    import scipy.sparse as sp
    return sp.csr_matrix((vals, (rows, cols)), shape=shape)


def iteration_matrix(problem, lin, t, y, yp, cj):
    """``problem.jacobian(t, y, yp, cj)`` for the solver ``lin``: an ndarray when ``lin``
    factors densely and the problem can build one (``offers_dense_jacobian``), so a small
    system never builds a sparse matrix only to expand it."""
    if getattr(problem, "offers_dense_jacobian", False) and lin.dense_decided():
        return problem.jacobian(t, y, yp, cj, dense=True)
    return problem.jacobian(t, y, yp, cj)


def _inverse(scale: np.ndarray) -> np.ndarray:
    """1/scale; an empty row or column stays empty (and shows as a zero pivot)."""
    return 1.0 / np.maximum(scale, 1e-300)


def equilibrate(J):
    """Row and column scalings ``(r, c)`` of a finite ``J`` (dense or sparse): the rows
    of ``diag(r) J`` and then the columns of ``diag(r) J diag(c)`` have largest
    magnitude 1 (xGEEQU; not rounded to powers of two as xGEEQUB does, which would
    cost more than the O(eps) relative change it avoids in each entry)."""
    if issparse(J):
        import scipy.sparse as sp
        A = abs(sp.csr_matrix(J))
        r = _inverse(A.max(axis=1).toarray().ravel())
        c = _inverse((sp.diags(r) @ A).max(axis=0).toarray().ravel())
    else:
        A = np.abs(J)
        r = _inverse(A.max(axis=1))
        A *= r[:, None]
        c = _inverse(A.max(axis=0))
    return r, c


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


def _structural_defect(S):
    """Rows and columns left unmatched by a maximum bipartite matching of ``S != 0``
    (``S`` a scipy.sparse CSR matrix)."""
    import scipy.sparse as sp
    pattern = sp.csr_matrix((np.ones(S.nnz), S.indices, S.indptr), shape=S.shape)
    pattern.eliminate_zeros()
    from scipy.sparse.csgraph import maximum_bipartite_matching   # diagnostics only
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
        smallest singular value of the equilibrated matrix (so that the answer does
        not depend on the units of the equations and variables).  Empty when nothing
        can be said.
    """
    import scipy.sparse as sp
    S = sp.csr_matrix(J)
    S.eliminate_zeros()
    rows, cols = _structural_defect(S)
    if rows.size or cols.size:
        return rows, cols
    if S.shape[0] > max_dense:
        return np.empty(0, int), np.empty(0, int)
    A = S.toarray()
    r, c = equilibrate(A)
    u, _, vt = np.linalg.svd(A * r[:, None] * c)
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
        self._r = self._c = None     # row and column equilibration of the factored matrix
        self._getrf = self._getrs = None
        self._kept = None            # (indptr, indices, SuperLU's permutations), or False
        self._clu = None             # the compiled refactorization on that analysis
        self._dlu = None             # the compiled step loop's library, for a dense LU
        self._in_c = False           # whether the last factorization is the compiled one
        self._numpy = False          # dense, judged by _numpy_lu and solved by numpy
        self._deficient = None       # the SVD of a consistent rank-deficient matrix

    def dense_decided(self) -> bool:
        """Whether the factorization is dense whatever form the matrix comes in."""
        return self.sparse is False or (self.sparse is None and self.pattern is not None
                                        and self.n <= SPARSE_THRESHOLD)

    def _decide(self, J) -> None:
        if self.sparse is None:
            offered = issparse(J) or self.pattern is not None
            self.sparse = bool(offered and self.n > SPARSE_THRESHOLD)
        if not self.sparse:
            self._dlu = library()
            if self._dlu is None:
                self._numpy = self.n <= NUMPY_LU_MAX
                if not self._numpy:
                    self._lapack()

    @property
    def kind(self) -> str:
        """Which LU factors: "compiled" (the step loop's, ``cbdf_lu.c``), "numpy" or
        "lapack" when dense; "superlu" when sparse (its numeric refactorizations by the
        compiled sparse LU where installed); "" before the first factorization."""
        if self.sparse is None:
            return ""
        if self.sparse:
            return "superlu"
        return "compiled" if self._dlu is not None else "numpy" if self._numpy else "lapack"

    def _lapack(self) -> None:
        from scipy.linalg import get_lapack_funcs    # only a dense factorization needs it
        self._getrf, self._getrs = get_lapack_funcs(("getrf", "getrs"), (np.empty((1, 1)),))

    def factor(self, J, weights=None) -> None:
        """LU-factor ``J``; raise :class:`SingularMatrixError` if it is singular.  With
        ``weights`` (of the error test, per variable) a singular ``J`` of at most
        :data:`RANK_DEFICIENT_MAX` unknowns is factored by its SVD instead, and solves
        are minimum-norm while the right-hand sides are consistent (module docstring)."""
        self._deficient = None
        if self.sparse is None or (not self.sparse and self._getrf is None
                                   and self._dlu is None and not self._numpy):
            self._decide(J)
        try:
            if self.sparse:
                self._factor_sparse(J)
            else:
                self._factor_dense(J)
        except SingularMatrixError:
            if weights is None or self.n > RANK_DEFICIENT_MAX or \
                    not self._factor_deficient(J, weights):
                raise

    @property
    def deficient(self) -> bool:
        """Whether the last factorization is of a rank-deficient matrix (its SVD)."""
        return self._deficient is not None

    def _factor_deficient(self, J, weights) -> bool:
        """The SVD of the equilibrated ``J`` for minimum-norm solves, and per left null
        vector the weight of its mismatch (module docstring); False if ``J`` is not
        finite."""
        A = J.toarray() if issparse(J) else np.array(J, dtype=float)
        if not np.all(np.isfinite(A)):
            return False
        import scipy.sparse as sp
        if self.pattern is not None:      # the structure: the problem's pattern, ...
            rows, cols = self.pattern
            S = sp.csr_matrix((np.ones(len(rows)), (rows, cols)), shape=A.shape)
        else:                             # ... a sparse matrix's entries, or the nonzeros
            S = sp.csr_matrix(J) if issparse(J) else sp.csr_matrix(A)
        rows, cols = _structural_defect(S)
        if rows.size or cols.size:     # an unknown no equation determines: an error
            return False
        r, c = equilibrate(A)
        B = A * r[:, None] * c
        u, sv, vt = np.linalg.svd(B)
        rank = int(np.count_nonzero(sv > _RANK_RTOL * sv[0])) if sv.size else 0
        null = u[:, rank:]
        # a left null vector's mismatch is in the units (over D_c) of the variables its
        # rows constrain: the most sensitive of them judges it
        w = np.asarray(weights, dtype=float) * c
        sens = np.empty(null.shape[1])
        for k in range(null.shape[1]):
            rows = np.abs(null[:, k]) > 0.1 * np.abs(null[:, k]).max()
            cols = np.any(np.abs(B[rows]) > 0.1, axis=0)
            sens[k] = w[cols].max() if cols.any() else w.max()
        self._deficient = (u[:, :rank], sv[:rank], vt[:rank], null, sens, r, c, A)
        return True

    def _solve_deficient(self, b: np.ndarray) -> np.ndarray:
        ur, sv, vr, null, sens, r, c, A = self._deficient
        rb = r * np.asarray(b, dtype=float)
        mismatch = np.abs(null.T @ rb) * sens
        if not np.all(mismatch <= 1.0):      # NaN too
            raise SingularMatrixError("iteration matrix is singular and the equations "
                                      "it makes dependent are inconsistent", matrix=A)
        return c * (vr.T @ ((ur.T @ rb) / sv))

    def _factor_dense(self, J) -> None:
        A = J.toarray() if issparse(J) else np.asarray(J, dtype=float)
        if not np.all(np.isfinite(A)):
            raise SingularMatrixError("iteration matrix has non-finite entries",
                                      *self._nonfinite(A))
        if self._dlu is not None:
            if self._factor_compiled(A):
                return
            self._lapack()        # singular: LAPACK's path, for its diagnostics
        self._in_c = False
        if self._numpy:
            self._factor_numpy(A, J)
            return
        lu, piv, info = self._getrf(np.array(A, order="F"), overwrite_a=True)
        if info == 0 and _pivots_ok(np.diagonal(lu)):
            self._lu, self._piv, self._r = lu, piv, None
            return
        # a small pivot may only reflect the units: judge the equilibrated matrix
        r, c = equilibrate(A)
        B = np.multiply(A, r[:, None], order="F")
        B *= c
        lu, piv, info = self._getrf(B, overwrite_a=True)
        if info > 0 or not _pivots_ok(np.diagonal(lu)):
            raise SingularMatrixError("iteration matrix is singular", matrix=J)
        self._lu, self._piv, self._r, self._c = lu, piv, r, c

    def _factor_compiled(self, A: np.ndarray) -> bool:
        n = self.n
        A = np.ascontiguousarray(A, dtype=float)
        lu, piv = np.empty((n, n)), np.empty(n, dtype=np.int64)
        r, c, equil = np.empty(n), np.empty(n), ctypes.c_int(0)
        code = self._dlu.dense_factor(A.ctypes.data, lu.ctypes.data, piv.ctypes.data,
                                      r.ctypes.data, c.ctypes.data, n, ctypes.byref(equil))
        if code != 0:
            return False
        self._lu, self._piv, self._in_c = lu, piv, True
        self._r, self._c = (r, c) if equil.value else (None, None)
        return True

    def _factor_numpy(self, A: np.ndarray, J) -> None:
        """Judge ``A`` by :func:`_numpy_lu` as :meth:`_factor_dense` judges LAPACK's
        factors, and keep the matrix judged (``A`` or its equilibrated form) for
        ``numpy.linalg.solve``."""
        self._c = None
        if _pivots_ok(_numpy_lu(A)):
            self._lu, self._r = np.array(A), None
            return
        r, c = equilibrate(A)
        B = A * r[:, None] * c
        if not _pivots_ok(_numpy_lu(B)):
            raise SingularMatrixError("iteration matrix is singular", matrix=J)
        self._lu, self._r, self._c = B, r, c

    def _factor_sparse(self, J) -> None:
        import scipy.sparse as sp
        A = sp.csc_matrix(J, dtype=float)
        if not np.all(np.isfinite(A.data)):
            raise SingularMatrixError("iteration matrix has non-finite entries",
                                      *self._nonfinite(A.toarray()))
        if self._refactored(A):
            return
        lu = _splu(A)
        if lu is not None and _pivots_ok(lu.U.diagonal()):
            self._lu, self._r = lu, None
            self._keep_analysis(A, lu)
            return
        r, c = equilibrate(A)
        lu = _splu(sp.csc_matrix(sp.diags(r) @ A @ sp.diags(c)))
        if lu is None or not _pivots_ok(lu.U.diagonal()):
            raise SingularMatrixError("iteration matrix is singular", matrix=A)
        self._lu, self._r, self._c = lu, r, c

    def _refactored(self, A) -> bool:
        """Factor ``A`` numerically with the column order and pivot rows of an earlier
        SuperLU factorization of the same pattern, by the compiled sparse LU of the
        step loop (:mod:`~acausal.solvers.cbdf_sparse`: no ordering and no SuperLU
        set-up per factorization, the idea of KLU's refactorization).  False where
        there is none (the first factorization of a pattern, no C compiler), or where
        its pivots look singular even equilibrated: SuperLU then factors afresh and
        decides."""
        kept = self._kept
        if kept is None or kept is False or not _same_pattern(A, kept[0], kept[1]):
            return False
        if self._clu is None:
            lib = library()
            if lib is None:
                self._kept = False
                return False
            self._clu = SparseLU(lib, self.n, kept[0], kept[1], np.arange(A.nnz), A,
                                 kept[2])
        if self._clu.factor(A.data) != 0:
            return False
        self._lu, self._r = self._clu, None
        return True

    def _keep_analysis(self, A, lu) -> None:
        """SuperLU's column order and pivot rows of ``A``, kept for the next
        factorizations of its pattern (a solver factoring only once never builds the
        compiled one)."""
        kept = self._kept
        if kept is False or (kept is not None and _same_pattern(A, kept[0], kept[1])):
            return
        self._kept = (A.indptr.copy(), A.indices.copy(), (lu.perm_c, lu.perm_r))
        self._clu = None

    @staticmethod
    def _nonfinite(A: np.ndarray):
        bad = ~np.isfinite(A)
        return np.flatnonzero(bad.any(axis=1)), np.flatnonzero(bad.any(axis=0))

    def solve(self, b: np.ndarray) -> np.ndarray:
        """Return ``J^{-1} b`` with the last factorization (the minimum-norm solution
        where it is rank-deficient)."""
        if self._deficient is not None:
            return self._solve_deficient(b)
        r = self._r
        if self.sparse:
            return self._lu.solve(b) if r is None else self._c * self._lu.solve(r * b)
        if self._in_c:
            x = np.array(b, dtype=float)
            self._dlu.dense_solve(self._lu.ctypes.data, self._piv.ctypes.data,
                                  None if r is None else r.ctypes.data,
                                  None if r is None else self._c.ctypes.data, self.n,
                                  x.ctypes.data)
            return x
        if self._numpy:
            if r is None:
                return np.linalg.solve(self._lu, b)
            return self._c * np.linalg.solve(self._lu, r * b)
        if r is None:
            return self._getrs(self._lu, self._piv, b)[0]
        x, _ = self._getrs(self._lu, self._piv, r * b, overwrite_b=True)
        x *= self._c
        return x


def _same_pattern(A, indptr, indices) -> bool:
    return A.indptr.shape == indptr.shape and A.indices.shape == indices.shape and \
        np.array_equal(A.indptr, indptr) and np.array_equal(A.indices, indices)


def _pivots_ok(diag) -> bool:
    d = np.abs(diag)
    return bool(d.size) and d.min() > _PIVOT_RTOL * d.max()


def _numpy_lu(A: np.ndarray) -> np.ndarray:
    """The pivots (diagonal of U) of the LU of ``A`` with partial pivoting, by numpy
    row operations (the algorithm of LAPACK's ``getf2`` and of ``cbdf_lu.c``, for small
    matrices); zeros from the first exactly zero pivot on."""
    U = np.array(A, dtype=float)
    n = len(U)
    pivots = np.zeros(n)
    for k in range(n):
        p = k + int(np.argmax(np.abs(U[k:, k])))
        if p != k:
            U[[k, p], k:] = U[[p, k], k:]
        d = pivots[k] = U[k, k]
        if d == 0.0:
            break
        m = U[k + 1:, k] * (1.0 / d)
        U[k + 1:, k + 1:] -= np.outer(m, U[k, k + 1:])
    return pivots


def _splu(A):
    # scipy.sparse.linalg is imported by the first sparse factorization: small systems,
    # factored densely by LAPACK, never need it
    from scipy.sparse.linalg import splu
    try:
        return splu(A)
    except RuntimeError:     # exactly singular
        return None


def make_linear_solver(problem) -> LinearSolver:
    """The linear solver suited to ``problem`` (back end decided at the first factor)."""
    return LinearSolver(problem.n, None, getattr(problem, "jac_pattern", None))
