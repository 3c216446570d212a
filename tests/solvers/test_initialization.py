"""Consistent initialization and the linear index-1 DAE with a closed form."""
import numpy as np
import pytest

from acausal.solvers import DAEProblem, InitializationFailed, integrate
from acausal.solvers.initialization import consistent_initial, reinitialize
from acausal.solvers.newton import damped_newton, homotopy

from .problems import LinearIndex1, Robertson


def test_linear_index1_dae_corrects_inconsistent_start():
    p = LinearIndex1()
    ts = np.linspace(0.0, 10.0, 51)
    out = integrate(p, (0.0, 10.0), [1.0, 5.0], [0.0, 7.0], rtol=1e-8, atol=1e-10,
                    t_eval=ts)
    # x(0) is trusted; z(0) and x'(0) are made consistent, z' of the algebraic is 0
    np.testing.assert_allclose(out.y[0], [1.0, 1.5], atol=1e-12)
    np.testing.assert_allclose(out.yp[0], [0.5, 0.0], atol=1e-12)
    x, z = LinearIndex1.exact(ts, 1.0)
    np.testing.assert_allclose(out.y[:, 0], x, atol=1e-6)
    np.testing.assert_allclose(out.y[:, 1], z, atol=1e-6)


def test_suppress_alg_gives_same_solution():
    p = LinearIndex1()
    out = integrate(p, (0.0, 10.0), [1.0, 0.0], rtol=1e-8, atol=1e-10, suppress_alg=True)
    x, z = LinearIndex1.exact(out.t, 1.0)
    np.testing.assert_allclose(out.y[:, 0], x, atol=1e-6)
    np.testing.assert_allclose(out.y[:, 1], z, atol=1e-6)


def test_robertson_initial_derivatives():
    y, yp = reinitialize(Robertson(), 0.0, [1.0, 0.0, 0.5], None)
    # y3 = 1 - y1 - y2 to rounding on the concentrations' scale, their sum 1
    np.testing.assert_allclose(y, [1.0, 0.0, 0.0], atol=1e-14 * 1.0)
    np.testing.assert_allclose(yp, [-0.04, 0.04, 0.0], rtol=1e-12)


class FixedAlgebraic(LinearIndex1):
    """The algebraic z(0) = 2 is fixed instead of x(0): x(0) = 2(z - cos 0) = 2."""

    def init_residual(self, t, y, yp):
        return np.array([y[1] - 2.0])


class SteadyStart(LinearIndex1):
    """Start in steady state x'(0) = 0 (with init_jacobian given)."""

    def init_residual(self, t, y, yp):
        return np.array([yp[0]])

    def init_jacobian(self, t, y, yp):
        return np.zeros((1, 2)), np.array([[1.0, 0.0]])


def test_initial_equations_fix_other_unknowns():
    y, yp = consistent_initial(FixedAlgebraic(), 0.0, [0.0, 0.0], None)
    np.testing.assert_allclose(y, [2.0, 2.0], atol=1e-10)
    np.testing.assert_allclose(yp, [0.0, 0.0], atol=1e-10)
    y, yp = consistent_initial(SteadyStart(), 0.0, [5.0, 0.0], None)
    # steady state: x = z, z = 1 + x/2  ->  x = z = 2
    np.testing.assert_allclose(y, [2.0, 2.0], atol=1e-10)
    out = integrate(FixedAlgebraic(), (0.0, 5.0), [0.0, 0.0], rtol=1e-8, atol=1e-10)
    x, _ = LinearIndex1.exact(out.t, 2.0)
    np.testing.assert_allclose(out.y[:, 0], x, atol=1e-6)


class NoSolution(DAEProblem):
    """0 = z^2 + 1 has no real solution."""

    def __init__(self):
        super().__init__(2, ["x", "z"])
        self.algebraic[1] = True
        self.equation_names = ["der(x) = -x", "z^2 + 1 = 0"]

    def residual(self, t, y, yp):
        return np.array([yp[0] + y[0], y[1] ** 2 + 1.0])

    def jacobian(self, t, y, yp, cj):
        return np.array([[cj + 1.0, 0.0], [0.0, 2.0 * y[1]]])


def test_initialization_failure_names_culprits():
    with pytest.raises(InitializationFailed) as info:
        integrate(NoSolution(), (0.0, 1.0), [1.0, 0.3])
    err = info.value
    assert isinstance(err, RuntimeError)
    assert "z" in err.variables or "z^2 + 1 = 0" in err.equations
    assert "z^2 + 1 = 0" in str(err) or "'z'" in str(err)


def test_homotopy_solves_what_newton_cannot():
    # arctan: plain Newton from x0 = 3 diverges; damping or continuation must rescue
    fun = lambda x: np.arctan(x - 1.0)                      # noqa: E731
    jac = lambda x: np.array([[1.0 / (1.0 + (x[0] - 1.0) ** 2)]])  # noqa: E731
    res = homotopy(fun, jac, [6.0], tol=1e-10)
    assert res.converged and res.x[0] == pytest.approx(1.0, abs=1e-9)
    res = damped_newton(fun, jac, [6.0], tol=1e-10)
    assert res.converged and res.x[0] == pytest.approx(1.0, abs=1e-9)



def test_a_consistent_singular_system_gets_its_minimum_norm_solution_and_an_inconsistent_none():
    """x1 + x2 = 3 twice (dependent rows) with x3 = 1: the solutions are a line, the
    minimum-norm one from zero is x1 = x2 = 1.5; with 3 and 4 on the right there is none."""
    from acausal.runtime.indeterminate import minimum_norm_newton, null_variables
    A = np.array([[1.0, 1.0, 0.0], [2.0, 2.0, 0.0], [0.0, 0.0, 1.0]])
    for b, expect in (([3.0, 6.0, 1.0], [1.5, 1.5, 1.0]), ([3.0, 8.0, 1.0], None)):
        found = minimum_norm_newton(lambda x: A @ x - b, lambda x: A, np.zeros(3),
                                    np.full(3, 1e6), np.ones(3))
        if expect is None:
            assert found is None
            continue
        x, null = found
        assert np.allclose(x, expect, rtol=1e-12)
        assert null_variables(null, ["x1", "x2", "x3"]) == ["x1", "x2"]


class DependentRows(DAEProblem):
    """x' = 1 with z1 + z2 = g1(t) and 2 (z1 + z2) = g2(t): the iteration matrix is
    singular for every step.  With g2 = 2 g1 the rows are consistent and z1 = z2 = t/2
    (the minimum-norm solution from z1 = z2 = 0); with g2 = 2 g1 + t they disagree as
    soon as t > 0, and the integration must stop as singular, not return a least-squares
    answer.  (The start is given consistent: the initialization's own treatment of a
    singular system is :mod:`acausal.runtime.indeterminate`'s.)"""

    def __init__(self, inconsistent):
        super().__init__(3, ["x", "z1", "z2"])
        self.algebraic[1:] = True
        self.bad = inconsistent

    def residual(self, t, y, yp):
        s = y[1] + y[2]
        return np.array([yp[0] - 1.0, s - t, 2 * s - 2 * t - (t if self.bad else 0.0)])

    def jacobian(self, t, y, yp, cj):
        return np.array([[cj, 0.0, 0.0], [0.0, 1.0, 1.0], [0.0, 2.0, 2.0]])


@pytest.mark.parametrize("bad", [False, True])
def test_integration_through_a_rank_deficient_iteration_matrix_only_when_consistent(bad):
    from acausal.solvers.base import SimulationError
    p = DependentRows(bad)
    ts = np.linspace(0.0, 1.0, 11)
    if bad:
        with pytest.raises(SimulationError, match="singular"):
            integrate(p, (0.0, 1.0), [0.0, 0.0, 0.0], [1.0, 0.0, 0.0], rtol=1e-8,
                      atol=1e-10, t_eval=ts, initialize=False)
        return
    out = integrate(p, (0.0, 1.0), [0.0, 0.0, 0.0], [1.0, 0.5, 0.5], rtol=1e-8,
                    atol=1e-10, t_eval=ts, initialize=False)
    assert out.success
    np.testing.assert_allclose(out.y[:, 0], ts, atol=1e-9)
    np.testing.assert_allclose(out.y[:, 1], ts / 2, atol=1e-9)
    np.testing.assert_allclose(out.y[:, 2], ts / 2, atol=1e-9)
