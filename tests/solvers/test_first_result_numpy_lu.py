"""The dense LU of a small system where the compiled step loop is not installed: numpy
row operations judge the pivots as LAPACK's factors are judged, and
``numpy.linalg.solve`` solves.
Checked against LAPACK (numpy's solve on the unfactored matrix) and Higham's backward
error bound, on the same cases as the compiled LU, and whole integrations on it against
Radau and closed forms."""
import numpy as np
import pytest
import scipy.linalg
from scipy.integrate import solve_ivp

from acausal.solvers import linalg
from acausal.solvers.driver import integrate
from acausal.solvers.linalg import NUMPY_LU_MAX, LinearSolver

from .lu_cases import (assert_badly_scaled_matrix_is_solved,
                       assert_singular_matrices_are_named, assert_solves)
from .problems import DampedOscillator, LinearIndex1, Robertson, VanDerPol

_EPS = np.finfo(float).eps


@pytest.fixture
def numpy_lu(monkeypatch):
    """Counts the factorizations judged by the numpy LU (the compiled LU not installed)."""
    monkeypatch.setattr(linalg, "library", lambda: None)
    calls = []
    judge = linalg._numpy_lu
    monkeypatch.setattr(linalg, "_numpy_lu", lambda A: (calls.append(1), judge(A))[1])
    return calls


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
        assert lin._numpy and lin._getrf is None and not lin._in_c and lin.kind == "numpy"
        assert_solves(lin, A, b, scipy.linalg.solve(A, b))


def test_a_larger_system_keeps_lapack(numpy_lu):
    n = NUMPY_LU_MAX + 1
    lin = LinearSolver(n)
    lin.factor(np.eye(n) * 2.0)
    assert not lin._numpy and lin._getrf is not None and lin.kind == "lapack"
    np.testing.assert_allclose(lin.solve(np.ones(n)), 0.5 * np.ones(n), rtol=1e-12)


def test_a_badly_scaled_matrix_is_equilibrated(numpy_lu):
    lin = assert_badly_scaled_matrix_is_solved()
    assert lin._r is not None           # it was equilibrated


def test_a_singular_matrix_is_named_as_with_lapack(numpy_lu):
    assert_singular_matrices_are_named()


@pytest.mark.parametrize("make, y0, t_end", [(lambda: VanDerPol(10.0), [2.0, 0.0], 3.0),
                                             (Robertson, [1.0, 0.0, 0.0], 40.0)],
                         ids=["vanderpol", "robertson"])
def test_the_python_loop_on_the_numpy_lu_matches_radau(numpy_lu, make, y0, t_end):
    # stiff problems: the iteration matrix is refactored often, and Robertson's rows
    # span 10 orders of magnitude (its algebraic row is the conservation law)
    p = make()
    ref = solve_ivp(p.ode, (0, t_end), y0, method="Radau", rtol=1e-12, atol=1e-14,
                    jac=p.ode_jac).y[:, -1]
    out = integrate(make(), (0, t_end), y0, rtol=1e-10, atol=1e-12, step_loop="python")
    assert out.success and len(numpy_lu) >= out.stats.lu_factorizations > 10
    assert np.max(np.abs(out.y[-1] - ref)) / np.max(np.abs(ref)) < 1e-8


def test_the_python_loop_on_the_numpy_lu_matches_closed_forms(numpy_lu):
    t = np.linspace(0, 10, 201)
    p = DampedOscillator()
    out = integrate(p, (0, 10), [1.0, 0.0], rtol=1e-10, atol=1e-12, t_eval=t,
                    step_loop="python")
    x, v = p.exact(t)
    assert np.max(np.abs(out.y[:, 0] - x)) < 1e-8 * np.max(np.abs(x))
    assert np.max(np.abs(out.y[:, 1] - v)) < 1e-8 * np.max(np.abs(v))
    q = LinearIndex1()
    out = integrate(q, (0, 10), [1.0, 1.5], rtol=1e-10, atol=1e-12, t_eval=t,
                    step_loop="python")
    x, z = q.exact(t, 1.0)
    assert np.max(np.abs(out.y[:, 0] - x)) < 1e-8 * np.max(np.abs(x))
    assert np.max(np.abs(out.y[:, 1] - z)) < 1e-8 * np.max(np.abs(z))
    assert numpy_lu
