"""Damped Newton at a tight tolerance: a residual at its round-off floor is converged.

At rtol 1e-12 the weights of the re-initialization after an event ask for a Newton
step below the round-off of the unknowns themselves (1e-5 of 1e-12 |x|).  A start that
is already the solution to round-off then has a step of a few ulps that no point along
it improves: the line search fails although nothing is left to do.  Such a step, far
below the error scale (a tenth of it, as for a stalled iteration), is convergence;
a larger one is still a failure.
"""
import numpy as np

from acausal.solvers.newton import damped_newton

C = 0.0                # a root at 0: every trial point of the search moves x


def _floor(level):
    """A residual that no step lowers below ``level`` (its round-off at the root C),
    with the slope 1 its Jacobian gives."""
    return (lambda x: np.array([level + 1e6 * abs(x[0] - C)]),
            lambda x: np.array([[1.0]]))


def _weights(x, rtol=1e-12):
    return 1.0 / (rtol * np.abs(x) + rtol)


def test_step_at_round_off_level_is_converged():
    fun, jac = _floor(1e-15)
    x0 = np.array([C])
    res = damped_newton(fun, jac, x0, weights=_weights(x0), tol=1e-5)
    assert res.converged
    assert res.x[0] == C                      # the start, not a point the search rejected


def test_step_near_the_error_scale_still_fails():
    fun, jac = _floor(1e-12)                  # a step of 0.6 of the error scale
    x0 = np.array([C])
    res = damped_newton(fun, jac, x0, weights=_weights(x0), tol=1e-5)
    assert not res.converged
    assert res.message == "line search failed"
