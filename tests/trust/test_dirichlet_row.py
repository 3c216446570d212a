"""A 200-node heat chain written directly as a ``DAEProblem``, with the Dirichlet
condition kept as an algebraic row of the residual.

Method of lines for u_t = kappa u_xx on [0, 1], kappa = 1e-2, n = 200 nodes:

    row 0:        u_0 - 1 = 0                         (Dirichlet, algebraic)
    rows 1..n-2:  u_i' - kappa/dx^2 (u_{i-1} - 2 u_i + u_{i+1}) = 0
    row n-1:      u_{n-1} - u_{n-2} = 0               (Neumann, algebraic)

from u = 0 inside and u_0 = 1.  The Dirichlet row is linear with a unit coefficient:
every Newton correction satisfies it to rounding and every interpolant through values
u_0 = 1 returns 1, so u_0 - 1 must vanish at round-off level (1e-14, relative to
u_0 = 1) at every output point; this is the one place where a round-off bound is the
physics.  The dense and the sparse LU solve the same problem: their trajectories must
agree, and each must match the exact semi-discrete solution (matrix exponential of the
interior system), both to a few rtol of the signal (u is of size 1).  Step counts are
not compared.
"""
import numpy as np
import pytest
import scipy.sparse as sps

from acausal.solvers import DAEProblem, integrate

N, KAPPA, T_END, RTOL, ATOL = 200, 1e-2, 1.0, 1e-8, 1e-10


class DirichletHeatChain(DAEProblem):
    """The residual of the module docstring; its iteration matrix dense or sparse."""

    def __init__(self, n=N, sparse=True):
        super().__init__(n, [f"u[{i}]" for i in range(n)])
        self.algebraic[0] = self.algebraic[-1] = True
        self.c = KAPPA * (n - 1) ** 2
        self.sparse = sparse
        self._dF_dy = self._matrix(0.0)
        self._dF_dyp = self._matrix(1.0) - self._dF_dy
        if sparse:
            coo = (self._dF_dy + self._dF_dyp).tocoo()
            self.jac_pattern = (coo.row, coo.col)

    def _matrix(self, cj):
        n, c = self.n, self.c
        main = np.full(n, cj + 2 * c)
        lower, upper = np.full(n - 1, -c), np.full(n - 1, -c)
        main[0], upper[0] = 1.0, 0.0                   # u_0 - 1
        main[-1], lower[-1] = 1.0, -1.0                # u_{n-1} - u_{n-2}
        return sps.diags([lower, main, upper], [-1, 0, 1], format="csc")

    def residual(self, t, y, yp):
        r = np.empty(self.n)
        r[0] = y[0] - 1.0
        r[1:-1] = yp[1:-1] - self.c * (y[:-2] - 2 * y[1:-1] + y[2:])
        r[-1] = y[-1] - y[-2]
        return r

    def jacobian(self, t, y, yp, cj):
        J = self._dF_dy + cj * self._dF_dyp
        return J if self.sparse else J.toarray()


def _exact(t, n=N):
    """Interior u' = A u + b with u_0 = 1 and u_{n-1} = u_{n-2}: the matrix exponential."""
    c, m = KAPPA * (n - 1) ** 2, n - 2
    A = c * (np.diag(np.full(m, -2.0)) + np.diag(np.ones(m - 1), 1)
             + np.diag(np.ones(m - 1), -1))
    A[-1, -1] += c
    b = np.zeros(m)
    b[0] = c
    u_ss = np.linalg.solve(A, -b)
    lam, V = np.linalg.eigh(A)             # A is symmetric: expm(A t) = V e^(lam t) V^T
    c0 = V.T @ u_ss
    inner = np.array([u_ss - V @ (np.exp(lam * tk) * c0) for tk in t])
    return np.column_stack([np.ones(len(t)), inner, inner[:, -1]])


def _start():
    u = np.zeros(N)
    u[0] = 1.0
    return u


@pytest.fixture(scope="module")
def runs():
    ts = np.linspace(0.0, T_END, 101)
    out = {}
    for sparse in (True, False):
        label = "sparse" if sparse else "dense"
        out[label] = integrate(DirichletHeatChain(sparse=sparse), (0.0, T_END), _start(),
                               rtol=RTOL, atol=ATOL, t_eval=ts)
    out["sparse, every step"] = integrate(DirichletHeatChain(sparse=True), (0.0, T_END),
                                          _start(), rtol=RTOL, atol=ATOL)
    return ts, out


@pytest.mark.parametrize("run", ["sparse", "dense", "sparse, every step"])
def test_dirichlet_row_holds_exactly_at_every_output(runs, run):
    _, out = runs
    assert out[run].success, out[run].message
    assert np.max(np.abs(out[run].y[:, 0] - 1.0)) <= 1e-14


def test_dense_and_sparse_lu_give_the_same_trajectory(runs):
    ts, out = runs
    assert out["sparse"].stats.linear_solver == "sparse"
    assert out["dense"].stats.linear_solver == "dense"
    assert np.max(np.abs(out["sparse"].y - out["dense"].y)) < 5 * RTOL


@pytest.mark.parametrize("run", ["sparse", "dense"])
def test_heat_chain_matches_the_matrix_exponential(runs, run):
    ts, out = runs
    assert np.max(np.abs(out[run].y - _exact(ts))) < 5 * RTOL
