"""The compiled BDF step loop (solvers/cbdf.c) against closed forms, an independent
solver and the Python loop.

The compiled loop runs the Python loop's method statement for statement, but with its
own LU, so the two agree to the integration tolerance, not bitwise.  Each run is
judged against something independent (a closed form, solve_ivp at rtol 1e-12, or the
Python loop at a tolerance 100 times tighter), relative to the signal.
"""
import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

import acausal as ac
from acausal.solvers import DAEProblem, cbdf, cbdf_library
from acausal.library.examples.motor_drive import MotorDrive
from acausal.library.examples.pendulum import Pendulum
from acausal.solvers.cbdf import CAPACITY, library
from acausal.solvers.driver import integrate
from acausal.tests.library.test_electrical import IdealRectifier, _ideal_rectifier_reference
from acausal.tests.models.test_events import BouncingBall as Ball, _bounce_times

from .problems import (BlowUp, BouncingBall, DampedOscillator, LinearIndex1, Robertson,
                       VanDerPol)
from acausal.errors import BackendError, SimulationError

pytestmark = pytest.mark.skipif(library() is None, reason="no C compiler on this machine")


def _rel(a, b):
    return np.max(np.abs(a - b)) / np.max(np.abs(b))


# ---------------------------------------------------------------- hand-written problems
def test_damped_oscillator_and_an_index_1_dae_match_their_closed_forms():
    t = np.linspace(0, 10, 201)
    p = DampedOscillator()
    out = integrate(p, (0, 10), [1.0, 0.0], rtol=1e-10, atol=1e-12, t_eval=t, step_loop="c")
    x, v = p.exact(t)
    assert out.stats.step_loop == "c" and out.stats.steps > 0
    assert _rel(out.y[:, 0], x) < 1e-8 and _rel(out.y[:, 1], v) < 1e-8
    q = LinearIndex1()
    out = integrate(q, (0, 10), [1.0, 1.5], rtol=1e-10, atol=1e-12, t_eval=t, step_loop="c")
    x, z = q.exact(t, 1.0)
    assert _rel(out.y[:, 0], x) < 1e-8 and _rel(out.y[:, 1], z) < 1e-8


def test_options_suppress_alg_max_step_and_max_steps_act_as_in_the_python_loop():
    t = np.linspace(0, 5, 51)
    q = LinearIndex1()
    out = integrate(q, (0, 5), [1.0, 1.5], rtol=1e-9, atol=1e-11, t_eval=t,
                    suppress_alg=True, max_step=0.05, step_loop="c")
    x, z = q.exact(t, 1.0)
    assert _rel(out.y[:, 0], x) < 1e-7 and _rel(out.y[:, 1], z) < 1e-7
    assert out.stats.steps >= 100                     # 5 s in steps of at most 0.05 s
    for loop in ("python", "c"):
        with pytest.raises(SimulationError, match="maximum number of steps") as info:
            integrate(LinearIndex1(), (0, 5), [1.0, 1.5], max_steps=20, step_loop=loop)
        assert info.value.partial.stats.steps == 20


@pytest.mark.parametrize("make, y0, t_end", [(lambda: VanDerPol(10.0), [2.0, 0.0], 3.0),
                                             (Robertson, [1.0, 0.0, 0.0], 40.0)],
                         ids=["vanderpol", "robertson"])
def test_stiff_problems_match_radau_as_the_python_loop_does(make, y0, t_end):
    p = make()
    ref = solve_ivp(p.ode, (0, t_end), y0, method="Radau", rtol=1e-12, atol=1e-14,
                    jac=p.ode_jac).y[:, -1]
    ends = {}
    for loop in ("python", "c"):
        out = integrate(make(), (0, t_end), y0, rtol=1e-10, atol=1e-12, step_loop=loop)
        assert out.stats.step_loop == loop
        ends[loop] = out.y[-1]
    err_py = np.max(np.abs(ends["python"] - ref)) / np.max(np.abs(ref))
    err_c = np.max(np.abs(ends["c"] - ref)) / np.max(np.abs(ref))
    assert err_c < 1e-8
    assert err_c < 3 * err_py + 1e-9      # as accurate as the Python loop


def test_bouncing_ball_with_unoriented_roots_bounces_on_time():
    p = BouncingBall()
    out = integrate(p, (0, 3), [1.0, 0.0], rtol=1e-10, atol=1e-12, step_loop="c")
    exact = p.bounce_times(1.0, len(out.event_times))
    assert len(out.event_times) >= 5
    assert np.max(np.abs(np.array(out.event_times) - exact)) < 1e-8


def test_a_blow_up_fails_as_in_the_python_loop():
    msgs = {}
    for loop in ("python", "c"):
        with pytest.raises(SimulationError) as info:
            integrate(BlowUp(), (0, 2), [1.0], rtol=1e-8, atol=1e-10, step_loop=loop)
        err = info.value
        assert err.partial is not None and 0.99 < err.partial.t[-1] < 1.0   # y = 1/(1-t)
        msgs[loop] = str(err).split(" at t=")[0]
    assert msgs["c"] == msgs["python"]


class _SingularRow(DAEProblem):
    """x' = -x and a row that does not involve z: the iteration matrix is singular."""

    def __init__(self):
        super().__init__(2, ["x", "z"])
        self.algebraic[1] = True

    def residual(self, t, y, yp):
        return np.array([yp[0] + y[0], 0.0 * y[1]])

    def jacobian(self, t, y, yp, cj):
        return np.array([[cj + 1.0, 0.0], [0.0, 0.0]])


def test_a_singular_iteration_matrix_is_reported_as_in_the_python_loop():
    msgs = {}
    for loop in ("python", "c"):
        with pytest.raises(SimulationError) as info:
            integrate(_SingularRow(), (0, 1), [1.0, 0.0], [-1.0, 0.0], initialize=False,
                      step_loop=loop)
        msgs[loop] = str(info.value)
        assert info.value.variables == ["z"]
    assert msgs["c"] == msgs["python"]


def test_single_steps_follow_the_closed_form():
    p = DampedOscillator()
    s = cbdf.CompiledBDF(p, 0.0, [1.0, 0.0], [0.0, -4.0], mode=1, rtol=1e-10, atol=1e-12)
    for _ in range(50):
        s.step()
    x, v = p.exact(s.t)
    assert s.stats.steps == 50 and s.t > 0
    assert abs(s.y[0] - x) < 1e-8 and abs(s.y[1] - v) < 1e-8


# ---------------------------------------------------------------- compiled models
def test_library_bouncing_ball_bounces_at_the_closed_form_times():
    c = ac.compile(Ball(), backend="c")
    res = ac.simulate(c, t_end=3.0, rtol=1e-10, atol=1e-12)
    assert res.stats["step_loop"] == "c"
    exact = _bounce_times(6)
    assert len(res.events) == 6
    assert np.max(np.abs(np.array(res.events) - exact)) < 1e-8


def test_ideal_rectifier_matches_solve_ivp_and_switches_with_the_python_loop():
    c = ac.compile(IdealRectifier(), backend="c")
    t = np.linspace(0, 0.04, 81)
    runs = {loop: ac.simulate(c, t_end=0.04, rtol=1e-10, t_eval=t, step_loop=loop,
                              raise_on_failure=True) for loop in ("python", "c")}
    assert runs["c"].stats["step_loop"] == "c"
    assert np.max(np.abs(runs["c"]["C.v"] - _ideal_rectifier_reference(t))) < 1e-7 * 5.0
    ta, tb = np.array(runs["python"].events), np.array(runs["c"].events)
    assert len(ta) == len(tb) >= 4
    assert np.max(np.abs(ta - tb)) < 1e-9 * 0.04


class _Staircase(ac.Component):
    """x' = 1 + x/10 from 0, so x = 10 (e^{t/10} - 1) reaches k at t_k = 10 ln(1 + k/10);
    z' = floor(x): a frozen floor value of a state, switched at those crossings."""

    x = ac.Variable(start=0.0, fixed=True)
    z = ac.Variable(start=0.0, fixed=True)

    def equations(self):
        return [ac.Eq(ac.der(self.x), 1 + self.x / 10),
                ac.Eq(ac.der(self.z), sp.floor(self.x))]


def test_a_floor_of_a_state_switches_at_the_closed_form_times():
    c = ac.compile(_Staircase(), backend="c")
    res = ac.simulate(c, t_end=3.0, rtol=1e-10, atol=1e-12)
    assert res.stats["step_loop"] == "c"
    tk = 10 * np.log(1 + np.arange(1, 4) / 10)
    assert len(res.events) == 3
    assert np.max(np.abs(np.array(res.events) - tk)) < 1e-8
    z_end = (tk[1] - tk[0]) + 2 * (tk[2] - tk[1]) + 3 * (3.0 - tk[2])
    assert abs(res["z"][-1] - z_end) < 1e-8 * z_end


def test_motor_drive_matches_the_python_loop_at_a_tighter_tolerance():
    """M3 of the benchmarks: a voltage step (a time event at 0.1 s)."""
    c = ac.compile(MotorDrive(), backend="c")
    t = np.linspace(0, 0.5, 2 * CAPACITY + 7)      # the output buffer refills mid-step
    ref = ac.simulate(c, t_end=0.5, rtol=1e-12, t_eval=t, step_loop="python")
    res = ac.simulate(c, t_end=0.5, rtol=1e-10, t_eval=t, step_loop="c")
    assert res.stats["step_loop"] == "c" and len(res.t) == len(t)
    np.testing.assert_array_equal(res.t, t)
    np.testing.assert_allclose(res.events, ref.events, rtol=1e-12)
    for name in c.states:
        assert _rel(res[name], ref[name]) < 1e-7, name
    # every accepted step as output (no t_eval): times increase, the event is in them
    steps = ac.simulate(c, t_end=0.5, rtol=1e-6)
    assert np.all(np.diff(steps.t) >= 0) and steps.stats["step_loop"] == "c"
    assert len(steps.t) > CAPACITY
    assert 0.1 in steps.t


# ---------------------------------------------------------------- which loop runs
def test_the_loop_is_chosen_by_backend_and_model():
    # both backends' models run in the compiled loop once its library is built (the
    # numpy code called back: solvers/cbdf_callbacks.py)
    built = cbdf.library() is not None
    assert ac.simulate(ac.compile(MotorDrive(), backend="numpy"), t_end=0.01) \
        .stats["step_loop"] == ("c" if built else "python")
    pend = ac.compile(Pendulum(), backend="c")      # dynamic state selection
    assert ac.simulate(pend, t_end=0.1).stats["step_loop"] == "c"
    assert ac.simulate(pend, t_end=0.1, step_loop="python").stats["step_loop"] == "python"
    with pytest.raises(ValueError, match="step_loop"):
        ac.simulate(pend, t_end=0.1, step_loop="fast")


def test_without_a_c_compiler_the_python_loop_runs(monkeypatch):
    c = ac.compile(MotorDrive(), backend="c")
    monkeypatch.setattr(cbdf_library, "_lib", False)  # as when installed without a compiler
    assert ac.simulate(c, t_end=0.01).stats["step_loop"] == "python"
    with pytest.raises(BackendError, match="C compiler"):
        ac.simulate(c, t_end=0.01, step_loop="c")


def test_dynamic_state_selection_above_max_dense_keeps_the_python_loop(monkeypatch):
    """The sparse LU keeps one Jacobian pattern and a new choice of states changes it:
    such a model stays in the Python loop, and "c" says why."""
    from types import SimpleNamespace
    monkeypatch.setattr(cbdf, "_loop_model", lambda problem: object())
    big = SimpleNamespace(n=cbdf.MAX_DENSE + 1, dynamic=object(), delays=None)
    assert cbdf.choose_step_loop(big, "auto", stald=False) is None
    with pytest.raises(ValueError, match="dynamic state selection"):
        cbdf.choose_step_loop(big, "c", stald=False)
    small = SimpleNamespace(n=cbdf.MAX_DENSE, dynamic=object(), delays=None)
    if cbdf.library() is not None:
        assert cbdf.choose_step_loop(small, "auto", stald=False) == 0


def test_a_model_with_a_delay_keeps_the_python_loop():
    """delay() records its history after every accepted step, in Python: "auto" keeps
    the Python loop there and "c" says why it cannot run."""
    from acausal.tests.library.test_delays import DelayedDecay
    c = ac.compile(DelayedDecay(a=1.0, T=1.0), backend="auto")
    res = ac.simulate(c, t_end=2.0)
    assert res.success and res.stats["step_loop"] == "python"
    with pytest.raises(ValueError, match="delay"):
        ac.simulate(c, t_end=2.0, step_loop="c")
