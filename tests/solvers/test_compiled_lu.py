"""The dense LU of the compiled step loop's library, used by the linear solver when
scipy.linalg is not loaded: the same answers as LAPACK's, the same singularity test."""
import numpy as np
import pytest

from acausal.solvers import cbdf, linalg
from acausal.solvers.linalg import LinearSolver

from .lu_cases import (assert_badly_scaled_matrix_is_solved,
                       assert_singular_matrices_are_named, assert_solves)



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
        assert_solves(lin, A, b, np.linalg.solve(A, b))


def test_compiled_lu_equilibrates_a_badly_scaled_matrix(compiled):
    assert_badly_scaled_matrix_is_solved()


def test_singular_matrix_is_named_as_with_lapack(compiled):
    assert_singular_matrices_are_named()
