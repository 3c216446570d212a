"""Dense/sparse LU selection and the location of singular blocks."""
import numpy as np
import pytest
import scipy.sparse as sp

from acausal.solvers.linalg import LinearSolver, SingularMatrixError, singular_block


def test_dense_and_sparse_solve_agree():
    rng = np.random.default_rng(0)
    n = 100
    A = sp.random(n, n, density=0.05, random_state=1, format="csc") + 10 * sp.eye(n)
    b = rng.standard_normal(n)
    sparse = LinearSolver(n, pattern=A.nonzero())
    sparse.factor(A)
    dense = LinearSolver(n)
    dense.factor(A.toarray())
    assert sparse.sparse and not dense.sparse
    np.testing.assert_allclose(sparse.solve(b), dense.solve(b), rtol=1e-12)
    np.testing.assert_allclose(A @ dense.solve(b), b, rtol=1e-12)


def test_structurally_singular_block_is_named():
    # rows 1 and 2 both involve only column 1: column 2 is unmatched
    A = np.array([[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 3.0, 0.0]])
    rows, cols = singular_block(A)
    assert list(cols) == [2] and len(rows) == 1 and rows[0] in (1, 2)
    big = sp.block_diag([sp.eye(70), sp.csr_matrix(A)], format="csc")
    lin = LinearSolver(73, pattern=big.nonzero())
    with pytest.raises(SingularMatrixError) as info:
        lin.factor(big)
    assert lin.sparse and info.value.cols == [72]


def test_numerically_singular_block_is_named():
    # full structure, but rows 0 and 2 are proportional in columns 0 and 2
    A = np.array([[1.0, 0.0, 2.0], [5.0, 3.0, 1.0], [2.0, 0.0, 4.0]])
    with pytest.raises(SingularMatrixError) as info:
        LinearSolver(3).factor(A)
    assert sorted(info.value.rows) == [0, 2]
    assert {0, 2} <= set(info.value.cols)   # null vector (-2, 3, 1)
