"""Non-finite values are failures, said in words.

x(t) = 1 - t (der(x) = -1, x(0) = 1) is integrated exactly; outputs computed only for
the results leave their domain at known times: y = sqrt(x) at t = 1, z = log(0.5 - t)
at t = 0.5, w = 1/(t - 0.5) at t = 0.5.  A run must end there with success=False,
naming the variable, its equation and a time at or just after the domain's edge, and
keep every point before it; a domain error inside the integration (der(x) = log(0.5 -
t)) must name what failed rather than only "step size too small".
"""
import warnings

import numpy as np
import pytest

import acausal as ac


class Root(ac.Component):
    """y = sqrt(x), x = 1 - t: undefined for t > 1."""

    x = ac.Variable(start=1.0, fixed=True)
    y = ac.Variable()

    def equations(self):
        return [ac.Eq(ac.der(self.x), -1.0), ac.Eq(self.y, ac.sqrt(self.x))]


class Logarithm(ac.Component):
    """z = log(0.5 - t): undefined for t >= 0.5."""

    x = ac.Variable(start=1.0, fixed=True)
    z = ac.Variable()

    def equations(self):
        return [ac.Eq(ac.der(self.x), -1.0), ac.Eq(self.z, ac.log(0.5 - ac.time))]


class Pole(ac.Component):
    """w = 1/(t - 0.5): infinite at t = 0.5, which a requested output time hits."""

    x = ac.Variable(start=1.0, fixed=True)
    w = ac.Variable()

    def equations(self):
        return [ac.Eq(ac.der(self.x), -1.0), ac.Eq(self.w, 1 / (ac.time - 0.5))]


class LogDerivative(ac.Component):
    """der(x) = log(0.5 - t): the integration itself leaves the domain at t = 0.5."""

    x = ac.Variable(start=1.0, fixed=True)

    def equations(self):
        return [ac.Eq(ac.der(self.x), ac.log(0.5 - ac.time))]


BACKENDS = ["numpy", "c"]


def _backend(backend):
    if backend == "c":
        from acausal.native import find_compiler
        if find_compiler() is None:
            pytest.skip("no C compiler")
    return backend


def _run(model, backend, **kw):
    with pytest.warns(RuntimeWarning, match="not finite"):
        return ac.simulate(model, 2.0, backend=_backend(backend), **kw)


@pytest.mark.parametrize("backend", BACKENDS)
def test_sqrt_of_a_negative_output_ends_the_run(backend):
    res = _run(Root(), backend)
    assert not res.success
    assert "y = nan" in res.message and "sqrt(x)" in res.message
    t_bad = float(res.message.split(" at t = ")[1].split()[0])
    assert 1.0 < t_bad <= 2.0
    assert res.t[-1] < t_bad and res.t[-1] <= 1.0 + 1e-12
    assert np.all(np.isfinite(res["y"]))                   # every point kept is whole
    # x = 1 - t exactly, and y = sqrt(x) where it is defined
    assert np.max(np.abs(res["y"] - np.sqrt(1.0 - res.t))) <= 1e-9


@pytest.mark.parametrize("backend", BACKENDS)
def test_log_past_its_domain_names_the_equation_and_the_time(backend):
    res = _run(Logarithm(), backend)
    assert not res.success
    assert "z = nan" in res.message and "log(0.5 - time)" in res.message
    t_bad = float(res.message.split(" at t = ")[1].split()[0])
    assert t_bad >= 0.5 and res.t[-1] < 0.5
    assert np.max(np.abs(res["z"] - np.log(0.5 - res.t))) <= 1e-12


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_pole_hit_by_an_output_time_ends_the_run(backend):
    res = _run(Pole(), backend, t_eval=np.linspace(0.0, 2.0, 9))   # 0.5 is one of them
    assert not res.success and "w = " in res.message and "t = 0.5 " in res.message
    assert res.t.tolist() == [0.0, 0.25]


@pytest.mark.parametrize("backend", BACKENDS)
def test_asked_to_continue_the_run_warns_and_goes_on(backend):
    res = _run(Root(), backend, nonfinite="warn")
    assert res.success and res.t[-1] == 2.0
    assert "nonfinite='warn'" in res.message and "y = nan" in res.message


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_domain_error_inside_the_integration_names_what_failed(backend):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = ac.simulate(LogDerivative(), 2.0, backend=_backend(backend))
    assert not res.success
    assert "computing der(x) failed" in res.message and "domain" in res.message
    assert abs(res.t[-1] - 0.5) <= 1e-6


def test_a_model_without_states_is_checked_at_every_point():
    class Explicit(ac.Component):
        z = ac.Variable()

        def equations(self):
            return [ac.Eq(self.z, ac.log(0.5 - ac.time))]

    with pytest.warns(RuntimeWarning, match="not finite"):
        res = ac.simulate(Explicit(), 1.0, n_points=11)
    assert not res.success and "log(0.5 - time)" in res.message
    assert res.t.tolist() == pytest.approx([0.0, 0.1, 0.2, 0.3, 0.4])


def test_outputs_that_need_no_check_cost_nothing():
    from acausal.library.examples.motor_drive import MotorDrive
    compiled = ac.compile(MotorDrive())
    assert compiled.meta["output_checks"] == []
    assert not compiled.check_point.every_point


class NoRealSolution(ac.Component):
    """x1 = sin(t) makes der(x1) = cos(t) a constraint on x2 alone, 1 = -c (a +
    exp(-x2^2)) at t = 0, which no real x2 satisfies (exp(-x2^2) would be negative):
    Newton's iterates run off until the Jacobian is no longer finite."""

    x1 = ac.Variable(start=-0.767, fixed=True)
    x2 = ac.Variable(start=-0.254)

    def equations(self):
        return [ac.Eq(ac.der(self.x1), -2.131 * self.x1
                      - 1.629 * (0.299 + ac.exp(-self.x2**2)) / 2),
                ac.Eq(self.x1, ac.sin(ac.time))]


def test_an_initial_problem_without_solution_is_refused_in_words():
    # before: numpy's LinAlgError ("SVD did not converge") from a least-squares step on
    # a Jacobian with NaN entries
    with pytest.raises(ac.InitializationFailed, match="x2"):
        ac.simulate(ac.compile(NoRealSolution()), t_end=1.0)


def test_a_least_squares_step_on_non_finite_numbers_is_a_singular_system():
    from acausal.solvers.linalg import SingularMatrixError
    from acausal.solvers.newton import _solve
    J = np.array([[1.0, np.nan], [0.0, 0.0]])
    with pytest.raises(SingularMatrixError, match="non-finite"):
        _solve(J, np.array([1.0, 0.0]), singular_ok=True)
