"""Checks every dense LU of ``LinearSolver`` must pass (LAPACK's, the compiled step
loop's, numpy's): the same cases, each LU's tests call them with that LU selected."""
import numpy as np
import pytest

from acausal.solvers.linalg import LinearSolver, SingularMatrixError

EPS = np.finfo(float).eps


def assert_solves(lin, A, b, x_ref):
    """x = lin.solve(b) against a reference solve, and its backward error: LU with
    partial pivoting gives |b - A x| <= gamma_3n |L||U||x| (Higham 2002, thm. 9.4),
    gamma_3n ~ 3n eps, and |L||U| stays within a small factor of |A| for diagonally
    dominant matrices (growth factor <= 2)."""
    n = len(b)
    x = lin.solve(b)
    assert np.abs(x - x_ref).max() < 1e-12 * np.abs(x_ref).max()
    scale = (np.abs(A) @ np.abs(x) + np.abs(b)).max()
    assert np.abs(A @ x - b).max() < 20 * n * EPS * scale
    return x


def assert_badly_scaled_matrix_is_solved() -> LinearSolver:
    """A hydraulic chamber's (V/beta) p' = q: a pivot of 1.4e-13 that only reflects
    units, solved exactly by hand."""
    lin = LinearSolver(2)
    lin.factor(np.array([[1e6, 0.0], [3e-12, 1.4e-13]]))
    np.testing.assert_allclose(lin.solve(np.array([1.0, 1.0])),
                               [1e-6, (1.0 - 3e-18) / 1.4e-13], rtol=1e-12)
    return lin


def assert_singular_matrices_are_named():
    """Rows 0 and 2 are proportional; a NaN entry; an exactly zero column."""
    A = np.array([[1.0, 0.0, 2.0], [5.0, 3.0, 1.0], [2.0, 0.0, 4.0]])
    with pytest.raises(SingularMatrixError) as info:
        LinearSolver(3).factor(A)
    assert sorted(info.value.rows) == [0, 2]
    with pytest.raises(SingularMatrixError, match="non-finite"):
        LinearSolver(2).factor(np.array([[1.0, np.nan], [0.0, 1.0]]))
    with pytest.raises(SingularMatrixError):
        LinearSolver(2).factor(np.array([[1.0, 0.0], [2.0, 0.0]]))
