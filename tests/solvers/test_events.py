"""Events, chattering detection and failure reports of the driver."""
import re

import numpy as np
import pytest

from acausal.solvers import DAEProblem, EventAction, SimulationError, integrate

from .problems import BlowUp, BouncingBall


def test_bounce_times_match_closed_form():
    ball = BouncingBall(e=0.8)
    out = integrate(ball, (0.0, 8.0), [10.0, 0.0], rtol=1e-10, atol=1e-10)
    assert out.success
    t_exact = ball.bounce_times(10.0, 4)
    assert len(out.event_times) == 4
    np.testing.assert_allclose(out.event_times, t_exact, rtol=0, atol=1e-8)
    # each event appears before and after: same time (the located time, stored twice,
    # so == is exact), velocity reversed and damped
    for te in out.event_times:
        k = np.flatnonzero(out.t == te)
        assert k.size == 2
        v_before, v_after = out.y[k[0], 1], out.y[k[1], 1]
        assert v_before < 0 and v_after == pytest.approx(-0.8 * v_before, rel=1e-12)
    assert out.y[:, 0].min() > -1e-8        # the ball never goes through the floor
    assert out.stats.events == 4            # the bounces in [0, 8]: fixed by the physics


def test_bouncing_ball_t_eval_output():
    ball = BouncingBall(e=0.8)
    ts = np.linspace(0.0, 4.0, 41)
    out = integrate(ball, (0.0, 4.0), [10.0, 0.0], rtol=1e-10, atol=1e-10, t_eval=ts)
    np.testing.assert_array_equal(out.t, ts)
    t1 = ball.bounce_times(10.0, 1)[0]
    before = ts <= t1
    np.testing.assert_allclose(out.y[before, 0], 10.0 - 0.5 * 9.81 * ts[before] ** 2,
                               atol=1e-8)
    v1 = 0.8 * 9.81 * t1
    after = (ts > t1) & (ts < ball.bounce_times(10.0, 2)[1])
    dt = ts[after] - t1
    np.testing.assert_allclose(out.y[after, 0], v1 * dt - 0.5 * 9.81 * dt ** 2, atol=1e-8)


def test_zeno_ball_stops_with_chattering_error():
    ball = BouncingBall(e=0.8)
    t_zeno = ball.bounce_times(10.0, 1)[0] + 2 * 0.8 * np.sqrt(2 * 9.81 * 10.0) / 9.81 / 0.2
    with pytest.raises(SimulationError) as info:
        integrate(ball, (0.0, 20.0), [10.0, 0.0], rtol=1e-8, atol=1e-8)
    err = info.value
    assert "chattering" in str(err) and "Zeno" in str(err)
    assert err.t < t_zeno
    predicted = float(re.search(r"accumulate at t≈([0-9.]+)", str(err)).group(1))
    assert predicted == pytest.approx(t_zeno, rel=1e-4)
    partial = err.partial
    assert partial is not None and not partial.success
    assert partial.t[-1] == pytest.approx(err.t)
    assert len(partial.event_times) >= 10
    np.testing.assert_allclose(partial.event_times,
                               ball.bounce_times(10.0, len(partial.event_times)),
                               atol=1e-6)


def test_blow_up_reports_time_and_partial_output():
    with pytest.raises(SimulationError) as info:
        integrate(BlowUp(), (0.0, 2.0), [1.0])
    err = info.value
    assert abs(err.t - 1.0) < 1e-3
    assert err.variables == ["y"]
    assert "step size" in err.reason or "error test" in err.reason
    partial = err.partial
    assert partial.t.size > 10 and partial.t[-1] <= 1.0
    # the partial output is the solution 1/(1-t) where it is resolvable
    ok = partial.t < 0.9
    np.testing.assert_allclose(partial.y[ok, 0], 1.0 / (1.0 - partial.t[ok]), rtol=1e-3)


class StepInput(DAEProblem):
    """y' = u with u switching 0 -> 1 at the time event t = 1 (frozen discrete state)."""

    time_events = (1.0,)

    def __init__(self):
        super().__init__(1, ["y"])
        self.u = 0.0

    def residual(self, t, y, yp):
        return yp - self.u

    def jacobian(self, t, y, yp, cj):
        return np.array([[cj]])

    def handle_event(self, t, y, yp, crossed):
        self.u = 1.0 if t >= 1.0 else 0.0
        return EventAction()


def test_time_event_stops_exactly_and_restarts():
    out = integrate(StepInput(), (0.0, 3.0), [0.0], rtol=1e-8, atol=1e-10)
    assert out.event_times == [1.0]         # a listed time is hit exactly, not located
    k = np.flatnonzero(out.t == 1.0)
    # before the edge y and y' are sums of zeros, hence exactly 0; after it y' = u comes
    # out of the re-initialization's linear solve: 1 to rounding
    assert k.size == 2 and out.yp[k[0], 0] == 0.0
    assert out.yp[k[1], 0] == pytest.approx(1.0, rel=1e-12)
    np.testing.assert_allclose(out.y[:, 0], np.maximum(out.t - 1.0, 0.0), atol=1e-9)


class Terminating(BouncingBall):
    def handle_event(self, t, y, yp, crossed):
        return EventAction(stop=True, message="ball reached the floor")


def test_event_can_stop_the_simulation():
    out = integrate(Terminating(), (0.0, 5.0), [10.0, 0.0], rtol=1e-10, atol=1e-10)
    assert not out.success and out.message == "ball reached the floor"
    assert out.t[-1] == pytest.approx(np.sqrt(2 * 10.0 / 9.81), abs=1e-8)


class Singular(DAEProblem):
    """x' = -x and x = 1 - z^0 ... : z appears nowhere, the iteration matrix is singular."""

    def __init__(self):
        super().__init__(2, ["x", "z"])
        self.algebraic[1] = True

    def residual(self, t, y, yp):
        return np.array([yp[0] + y[0], y[0] - np.exp(-t)])

    def jacobian(self, t, y, yp, cj):
        return np.array([[cj + 1.0, 0.0], [1.0, 0.0]])


def test_singular_iteration_matrix_names_variable():
    with pytest.raises(SimulationError) as info:
        integrate(Singular(), (0.0, 1.0), [1.0, 0.0], [-1.0, 0.0], initialize=False)
    err = info.value
    assert "singular" in err.reason and err.variables == ["z"]
    assert err.t == 0.0 and err.partial.t.size == 1


class Thermostat(DAEProblem):
    """T' = -(T - Ta)/tau + u P with a two-point controller switching u.

    The switching functions are algebraic variables (d_lo = T - 18, d_hi = T - 22),
    so the event logic must cope with roots whose y' is not available.
    """

    n_roots = 2

    def __init__(self):
        super().__init__(3, ["T", "d_lo", "d_hi"])
        self.algebraic[1:] = True
        self.u = 0.0

    def residual(self, t, y, yp):
        return np.array([yp[0] + (y[0] - 10.0) - 20.0 * self.u,
                         y[1] - (y[0] - 18.0), y[2] - (y[0] - 22.0)])

    def jacobian(self, t, y, yp, cj):
        return np.array([[cj + 1.0, 0.0, 0.0], [-1.0, 1.0, 0.0], [-1.0, 0.0, 1.0]])

    def roots(self, t, y, yp):
        return y[1:]

    def handle_event(self, t, y, yp, crossed):
        new = 1.0 if (crossed[0] and self.u == 0.0) else \
            0.0 if (crossed[1] and self.u == 1.0) else self.u
        changed = new != self.u
        self.u = new
        return EventAction(changed=changed)


def test_thermostat_switching_times_on_algebraic_roots():
    out = integrate(Thermostat(), (0.0, 3.0), [20.0, 0.0, 0.0], rtol=1e-10, atol=1e-10)
    first = np.log(10.0 / 8.0)            # cool 20 -> 18
    period = np.log(1.5)                  # heat 18 -> 22, cool 22 -> 18
    expected = first + period * np.arange(7)
    np.testing.assert_allclose(out.event_times, expected, atol=1e-8)
    assert out.y[:, 0].min() > 18.0 - 1e-7 and out.y[-1, 0] < 22.0 + 1e-7


class Relay(DAEProblem):
    """x' = u, u = -sign(x) as a frozen mode: an ideal relay slides at x = 0."""

    n_roots = 1

    def __init__(self):
        super().__init__(1, ["x"])
        self.u = -1.0

    def residual(self, t, y, yp):
        return yp - self.u

    def jacobian(self, t, y, yp, cj):
        return np.array([[cj]])

    def roots(self, t, y, yp):
        return y.copy()

    def handle_event(self, t, y, yp, crossed):
        new = -self.u if crossed[0] else self.u
        changed = new != self.u
        self.u = new
        return EventAction(changed=changed)


def test_sliding_mode_chattering_is_reported():
    with pytest.raises(SimulationError) as info:
        integrate(Relay(), (0.0, 3.0), [1.0], rtol=1e-8, atol=1e-10)
    err = info.value
    assert "chattering" in err.reason and "sliding" in err.reason
    assert err.t == pytest.approx(1.0, abs=1e-6)
    assert len(err.partial.event_times) >= 40


class PulseIntegral(DAEProblem):
    """y' = u with u a pulse train; its edges come from ``next_time_event``.

    The solution is piecewise linear, so steps grow past whole pulses: without time
    events the edges could not be seen from the signs of a zero-crossing function.
    """

    start, period, width, high = 0.1, 0.25, 0.3, 2.0

    def __init__(self):
        super().__init__(1, ["y"])
        self.u = 0.0

    def residual(self, t, y, yp):
        return yp - self.u

    def jacobian(self, t, y, yp, cj):
        return np.array([[cj]])

    def next_time_event(self, t):
        k = np.floor((t - self.start) / self.period)
        edges = [self.start + (j + e) * self.period
                 for j in (k - 1, k, k + 1) for e in (0.0, self.width)]
        later = [te for te in edges if te > t + 1e-12 * max(1.0, abs(t))]
        return min(later) if later else None

    def handle_event(self, t, y, yp, crossed):
        phase = ((t - self.start) / self.period + 1e-9) % 1.0
        self.u = self.high if t >= self.start - 1e-12 and phase < self.width else 0.0
        return EventAction()


def test_next_time_event_drives_periodic_edges():
    out = integrate(PulseIntegral(), (0.0, 1.0), [0.0], rtol=1e-10, atol=1e-12)
    edges = [0.1, 0.175, 0.35, 0.425, 0.6, 0.675, 0.85, 0.925]
    # the driver stops at the times next_time_event computes, which differ from these
    # literals by the rounding of start + (j + e) period
    np.testing.assert_allclose(out.event_times, edges, rtol=1e-12, atol=0)
    assert out.y[-1, 0] == pytest.approx(2.0 * 4 * 0.075, abs=1e-10)
