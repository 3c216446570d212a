"""The dense LU of the compiled step loop's library, used by the linear solver wherever it
is installed: the same answers as LAPACK's, the same singularity test."""
import numpy as np
import pytest

from acausal.solvers import cbdf, linalg
from acausal.solvers.linalg import LinearSolver

from .lu_cases import (assert_badly_scaled_matrix_is_solved,
                       assert_singular_matrices_are_named, assert_solves)



@pytest.fixture
def compiled():
    lib = cbdf.library()
    if lib is None:
        pytest.skip("the compiled step loop is not installed")
    assert linalg.library() is lib
    return lib


def test_compiled_and_lapack_lu_agree(compiled):
    rng = np.random.default_rng(0)
    for n in (1, 3, 12, 40):
        A = rng.standard_normal((n, n)) + n * np.eye(n)
        b = rng.standard_normal(n)
        lin = LinearSolver(n)
        lin.factor(A)
        assert lin._in_c and lin.kind == "compiled"
        assert_solves(lin, A, b, np.linalg.solve(A, b))


def test_compiled_lu_equilibrates_a_badly_scaled_matrix(compiled):
    assert_badly_scaled_matrix_is_solved()


def test_singular_matrix_is_named_as_with_lapack(compiled):
    assert_singular_matrices_are_named()
