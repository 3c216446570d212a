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
    # SuperLU and LAPACK order their operations differently: the solutions agree to
    # rounding relative to the solution's size, not component by component
    xs, xd = sparse.solve(b), dense.solve(b)
    assert np.abs(xs - xd).max() < 1e-12 * np.abs(xd).max()
    for x in (xs, xd):           # backward error, on the scale of |A| |x| + |b|
        scale = (abs(A) @ np.abs(x) + np.abs(b)).max()
        assert np.abs(A @ x - b).max() < 1e-12 * scale


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


def _scaled(A, rng, decades=13):
    """Row factors 10^-decades .. 10^decades (the units of the equations) and column
    factors that keep each row's largest entry where it is (the units of the variables
    of a diagonally dominant matrix: 10^-3 .. 10^3 here)."""
    r = 10.0 ** rng.uniform(-decades, decades, A.shape[0])
    c = 10.0 ** rng.uniform(-3, 3, A.shape[1])
    return r, c


def test_badly_scaled_regular_matrices_are_factored_accurately():
    rng = np.random.default_rng(3)
    # the iteration matrix of a hydraulic chamber (V/beta) p' = q: a pivot ~1e-13
    lin = LinearSolver(2)
    lin.factor(np.array([[1e6, 0.0], [3e-12, 1.4e-13]]))
    np.testing.assert_allclose(lin.solve(np.array([1.0, 1.0])),
                               [1e-6, (1.0 - 3e-18) / 1.4e-13], rtol=1e-14)
    for n, sparse in [(8, False), (90, True)]:
        A = (sp.random(n, n, density=0.05, random_state=n, format="csc")
             + 4e3 * sp.eye(n)).toarray()
        r, c = _scaled(A, rng)
        B = A * r[:, None] * c
        x0 = rng.standard_normal(n)
        x, b = x0 / c, r * (A @ x0)     # B x = b without cancellation in forming b
        lin = LinearSolver(n, pattern=np.nonzero(B) if sparse else None)
        lin.factor(sp.csc_matrix(B) if sparse else B)
        assert lin.sparse == sparse
        np.testing.assert_allclose(lin.solve(b), x, rtol=1e-9)


def test_badly_scaled_singular_matrix_is_still_named():
    rng = np.random.default_rng(4)
    A = np.array([[1.0, 0.0, 2.0], [5.0, 3.0, 1.0], [2.0, 0.0, 4.0]])
    r, c = _scaled(A, rng)
    with pytest.raises(SingularMatrixError) as info:
        LinearSolver(3).factor(A * r[:, None] * c)
    assert sorted(info.value.rows) == [0, 2]
    assert 1 not in info.value.cols or len(info.value.cols) == 3


def test_a_consistent_rank_deficient_matrix_gives_minimum_norm_solutions_with_weights():
    """x1 + x2 = b1 twice (dependent rows) and x3 = b3: without weights the matrix is
    refused as singular; with them (the integrator's error weights) a consistent right
    side gets the minimum-norm solution, x1 = x2 = b1/2, and an inconsistent one (the
    dependent rows disagree by more than the variables' tolerance) is still refused."""
    A = np.array([[1.0, 1.0, 0.0], [2.0, 2.0, 0.0], [0.0, 0.0, 1.0]])
    with pytest.raises(SingularMatrixError):
        LinearSolver(3).factor(A)
    for kind in (False, True):
        lin = LinearSolver(3, sparse=kind)
        lin.factor(sp.csc_matrix(A) if kind else A, np.full(3, 1e6))
        assert lin.deficient
        assert np.allclose(lin.solve(np.array([3.0, 6.0, 1.0])), [1.5, 1.5, 1.0],
                           rtol=1e-13)
        # a mismatch of 1e-9 in units of x (below the tolerance 1e-6): round-off
        assert np.allclose(lin.solve(np.array([3.0, 6.0 + 2e-9, 1.0])),
                           [1.5, 1.5, 1.0], rtol=1e-8)
        with pytest.raises(SingularMatrixError):
            lin.solve(np.array([3.0, 8.0, 1.0]))
    # a regular matrix is factored as before
    lin = LinearSolver(3)
    lin.factor(np.eye(3), np.ones(3))
    assert not lin.deficient
