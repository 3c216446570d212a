"""The dense LU of a small system when neither scipy.linalg nor the compiled step loop's
library is loaded (the first run of a model on the numpy backend): numpy row operations
judge the pivots as LAPACK's factors are judged, and ``numpy.linalg.solve`` solves.
Checked against LAPACK (numpy's solve on the unfactored matrix) and Higham's backward
error bound, on the same cases as the compiled LU."""
import numpy as np
import pytest
import scipy.linalg

from acausal.solvers import linalg
from acausal.solvers.linalg import NUMPY_LU_MAX, LinearSolver, SingularMatrixError

_EPS = np.finfo(float).eps


class _NoScipy:
    """``sys`` as seen by linalg in a process that has not imported scipy.linalg."""
    import sys as _sys
    modules = {k: v for k, v in _sys.modules.items() if k != "scipy.linalg"}


@pytest.fixture
def numpy_lu(monkeypatch):
    monkeypatch.setattr(linalg, "sys", _NoScipy())
    monkeypatch.setattr(linalg, "_compiled_lu", lambda: None)


def test_pivots_are_lapacks(numpy_lu):
    rng = np.random.default_rng(1)
    for n in (1, 2, 5, NUMPY_LU_MAX):
        A = rng.standard_normal((n, n))
        lu, _ = scipy.linalg.lu_factor(A)
        ref = np.diagonal(lu)
        # the same partial pivoting: the same pivots up to the rounding of the updates
        assert np.abs(linalg._numpy_lu(A) - ref).max() < 1e3 * n * _EPS * np.abs(A).max()


def test_solutions_agree_with_lapack_within_the_backward_error_bound(numpy_lu):
    rng = np.random.default_rng(0)
    for n in (1, 3, 12, NUMPY_LU_MAX):
        A = rng.standard_normal((n, n)) + n * np.eye(n)
        b = rng.standard_normal(n)
        lin = LinearSolver(n)
        lin.factor(A)
        assert lin._numpy and lin._getrf is None and not lin._in_c
        x = lin.solve(b)
        x_ref = scipy.linalg.solve(A, b)
        assert np.abs(x - x_ref).max() < 1e-12 * np.abs(x_ref).max()
        # |b - A x| <= gamma_3n |L||U||x| (Higham 2002, thm. 9.4); growth factor <= 2
        scale = (np.abs(A) @ np.abs(x) + np.abs(b)).max()
        assert np.abs(A @ x - b).max() < 20 * n * _EPS * scale


def test_a_larger_system_keeps_lapack(numpy_lu):
    n = NUMPY_LU_MAX + 1
    lin = LinearSolver(n)
    lin.factor(np.eye(n) * 2.0)
    assert not lin._numpy and lin._getrf is not None
    np.testing.assert_allclose(lin.solve(np.ones(n)), 0.5 * np.ones(n), rtol=1e-15)


def test_a_badly_scaled_matrix_is_equilibrated(numpy_lu):
    # a hydraulic chamber's (V/beta) p' = q: a pivot of 1.4e-13 that only reflects units
    lin = LinearSolver(2)
    lin.factor(np.array([[1e6, 0.0], [3e-12, 1.4e-13]]))
    assert lin._r is not None
    np.testing.assert_allclose(lin.solve(np.array([1.0, 1.0])),
                               [1e-6, (1.0 - 3e-18) / 1.4e-13], rtol=1e-14)


def test_a_singular_matrix_is_named_as_with_lapack(numpy_lu):
    A = np.array([[1.0, 0.0, 2.0], [5.0, 3.0, 1.0], [2.0, 0.0, 4.0]])
    with pytest.raises(SingularMatrixError) as info:
        LinearSolver(3).factor(A)
    assert sorted(info.value.rows) == [0, 2]
    with pytest.raises(SingularMatrixError, match="non-finite"):
        LinearSolver(2).factor(np.array([[1.0, np.nan], [0.0, 1.0]]))
    with pytest.raises(SingularMatrixError):       # an exactly zero column
        LinearSolver(2).factor(np.array([[1.0, 0.0], [2.0, 0.0]]))
