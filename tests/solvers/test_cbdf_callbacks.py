"""A numpy-backend model in the compiled step loop (solvers/cbdf_callbacks.py): its
generated functions are called back through the pointers the C backend's functions
take.  The two backends on the same loop agree to rounding
(tests/compiler/test_cbackend.py); here: the loop is chosen, a point outside a
function's domain is reported as the Python loop reports it, another exception is
raised.  A large numpy model (sparse LU, array code) in the compiled loop, against its
exact solution: tests/compiler/test_arraycode.py."""
import warnings

import numpy as np
import pytest
import sympy as sp

import acausal as ac
from acausal.solvers import cbdf

needs_loop = pytest.mark.skipif(cbdf.library() is None, reason="no C compiler on this machine")


class Runout(ac.Component):
    """der(x) = sqrt(1 - t): undefined after t = 1, where the run must stop."""

    x = ac.Variable(start=0.0)

    def equations(self):
        return [ac.Eq(ac.der(self.x), sp.sqrt(1.0 - ac.time))]


@needs_loop
def test_a_domain_error_is_reported_as_in_the_python_loop():
    model = ac.compile(Runout(), backend="numpy")
    runs = {}
    for loop in ("python", "c"):
        model.evaluation_errors.clear()
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)
            res = ac.simulate(model, t_end=2.0, rtol=1e-8, step_loop=loop)
        assert res.stats["step_loop"] == loop and not res.success
        runs[loop] = (res, list(model.evaluation_errors))
    (a, errors_a), (b, errors_b) = runs["python"], runs["c"]
    # x = (2/3)(1 - (1 - t)^1.5) up to t = 1, where both stop
    for res in (a, b):
        early = res.t <= 0.9           # away from the infinite slope at t = 1
        exact = 2.0 / 3.0 * (1.0 - (1.0 - res.t[early]) ** 1.5)
        assert np.max(np.abs(res["x"][early] - exact)) < 1e-6 * 2.0 / 3.0
        assert abs(res.t[-1] - 1.0) < 1e-9
    for errors in (errors_a, errors_b):     # in the same words in both loops
        assert errors and all(e.startswith("computing der(x) failed at t = ") and
                              e.endswith("ValueError: math domain error") for e in errors)


@needs_loop
def test_another_exception_in_a_callback_is_raised_when_the_loop_returns():
    model = ac.compile(Runout(), backend="numpy")
    good = model.code.residual
    calls = []

    def failing(*args):
        calls.append(args[0])
        if len(calls) > 20:
            raise RuntimeError("a bug in a user function")
        return good(*args)

    model.code.residual = failing
    with pytest.raises(RuntimeError, match="a bug in a user function"):
        ac.simulate(model, t_end=0.5, step_loop="c")


@needs_loop
def test_the_sparse_analysis_is_made_once_per_model_and_pattern(monkeypatch):
    """The compiled loop's sparse LU keeps SuperLU's orderings with the model: the
    second run makes no analysis of its own and, from the same start, computes the
    same numbers."""
    from acausal.solvers import cbdf_sparse
    from acausal.tests.models.test_large_ladder import Ladder, _exact
    made = []
    analysis = cbdf_sparse.analysis

    def recorded(A, perms=None):
        made.append(perms is None)
        return analysis(A, perms)

    monkeypatch.setattr(cbdf_sparse, "analysis", recorded)
    model = ac.compile(Ladder(110), backend="numpy")
    assert model.n > cbdf.MAX_DENSE
    first = ac.simulate(model, t_end=2e-3)
    second = ac.simulate(model, t_end=2e-3)
    assert first.stats["step_loop"] == second.stats["step_loop"] == "c"
    assert made == [True, False]
    np.testing.assert_array_equal(first.t, second.t)
    np.testing.assert_array_equal(first["C[109].v"], second["C[109].v"])
    # and the run is the ladder's solution (matrix exponential)
    t = np.linspace(0.0, 2e-3, 5)
    res = ac.simulate(model, t_end=t[-1], rtol=1e-8, t_eval=t)
    x = _exact(110, t)
    for k in (0, 109):
        assert np.max(np.abs(res[f"L[{k}].i"] - x[:, k])) <= 1e-5 * np.max(np.abs(x[:, 0]))
        assert np.max(np.abs(res[f"C[{k}].v"] - x[:, 110 + k])) <= 1e-5 * np.max(np.abs(x[:, 110]))
