"""The dense LU of the compiled step loop's library, used by the linear solver when
scipy.linalg is not loaded: the same answers as LAPACK's, the same singularity test."""
import numpy as np
import pytest

from acausal.solvers import cbdf, linalg
from acausal.solvers.linalg import LinearSolver, SingularMatrixError

_EPS = np.finfo(float).eps


@pytest.fixture
def compiled(monkeypatch):
    lib = cbdf.library()
    if lib is None:
        pytest.skip("no C compiler")
    monkeypatch.setattr(linalg, "sys", _NoScipy())
    assert linalg._compiled_lu() is lib
    return lib


class _NoScipy:
    """``sys`` as seen by linalg in a process that has not imported scipy.linalg."""
    import sys as _sys
    modules = {k: v for k, v in _sys.modules.items() if k != "scipy.linalg"}


def test_compiled_and_lapack_lu_agree(compiled):
    rng = np.random.default_rng(0)
    for n in (1, 3, 12, 40):
        A = rng.standard_normal((n, n)) + n * np.eye(n)
        b = rng.standard_normal(n)
        lin = LinearSolver(n)
        lin.factor(A)
        assert lin._in_c
        x = lin.solve(b)
        x_ref = np.linalg.solve(A, b)
        assert np.abs(x - x_ref).max() < 1e-12 * np.abs(x_ref).max()
        # backward error of LU with partial pivoting: |b - A x| <= gamma_3n |L||U||x|
        # (Higham 2002, thm. 9.4), gamma_3n ~ 3n eps, and |L||U| stays within a small
        # factor of |A| for these diagonally dominant matrices (growth factor <= 2)
        scale = (np.abs(A) @ np.abs(x) + np.abs(b)).max()
        assert np.abs(A @ x - b).max() < 20 * n * _EPS * scale


def test_compiled_lu_equilibrates_a_badly_scaled_matrix(compiled):
    # a hydraulic chamber's (V/beta) p' = q: a pivot of 1.4e-13 that only reflects units
    lin = LinearSolver(2)
    lin.factor(np.array([[1e6, 0.0], [3e-12, 1.4e-13]]))
    np.testing.assert_allclose(lin.solve(np.array([1.0, 1.0])),
                               [1e-6, (1.0 - 3e-18) / 1.4e-13], rtol=1e-14)


def test_singular_matrix_is_named_as_with_lapack(compiled):
    A = np.array([[1.0, 0.0, 2.0], [5.0, 3.0, 1.0], [2.0, 0.0, 4.0]])
    with pytest.raises(SingularMatrixError) as info:
        LinearSolver(3).factor(A)
    assert sorted(info.value.rows) == [0, 2]
    with pytest.raises(SingularMatrixError):
        LinearSolver(2).factor(np.array([[1.0, np.nan], [0.0, 1.0]]))
