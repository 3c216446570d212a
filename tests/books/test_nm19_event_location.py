"""NM-19: event detection on dense output (Egeland & Gravdahl, 001 §14.8.2-14.8.3).

A sign change of g(y, t) over a step [t_n, t_n + h] is followed by solving

    g(y_n(alpha), t_n + alpha h) = 0                                          (14.221)

on the method's dense output y_n(alpha), not on the step end points.  acausal locates
roots with the Illinois iteration on the BDF interpolant (``acausal.solvers.driver``).

Checked on y' = -y, y(0) = 1 with g_1 = y - 0.5 and g_2 = y - 0.1 (exact crossings ln 2
and ln 10):
* at rtol 1e-3 the steps over the crossings are 0.13 and 0.19 long; the dense output of
  the same run *without* the event functions, evaluated at the first located time, is 0.5
  to 1e-10 (measured 8e-15 relative), and the solution recorded at each event is on its
  level (4e-15, 6e-14): the root is that of (14.221) on the interpolant, not of a chord
  between step ends (which would be off by ~h^2 y''/8 ~ 2e-3);
* the located times approach ln 2 and ln 10 with the tolerance, within 20 rtol relative
  (measured 4.3e-6 and 5.4e-7 at rtol 1e-5, 5.8e-8 and 4.4e-9 at rtol 1e-8).
"""
import numpy as np
import pytest

from acausal.solvers import EventAction, integrate

from ..solvers.problems import Decay

LEVELS = np.array([0.5, 0.1])


class DecayCrossings(Decay):
    """y' = -y reporting y = 0.5 and y = 0.1 as events that change nothing."""

    n_roots = 2

    def roots(self, t, y, yp):
        return y[0] - LEVELS

    def handle_event(self, t, y, yp, crossed):
        return EventAction(changed=False)


def test_roots_are_those_of_the_dense_output():
    out = integrate(DecayCrossings(), (0.0, 5.0), [1.0], rtol=1e-3, atol=1e-12)
    assert out.success
    t_e = np.array(out.event_times)
    assert t_e.size == 2
    # the steps over the crossings are long enough for a chord to be visibly wrong
    plain = integrate(Decay(), (0.0, 5.0), [1.0], rtol=1e-3, atol=1e-12)
    for t in t_e:
        k = np.searchsorted(plain.t, t)
        assert plain.t[k] - plain.t[k - 1] > 0.05
    # the same step sequence up to the first event: its dense output at t_e is the level
    first = integrate(Decay(), (0.0, 5.0), [1.0], rtol=1e-3, atol=1e-12, t_eval=t_e[:1])
    assert abs(first.y[0, 0] - LEVELS[0]) < 1e-10 * LEVELS[0]
    # and at each event the solution recorded is on the level
    for t, level in zip(t_e, LEVELS):
        k = np.flatnonzero(out.t == t)
        assert k.size >= 1
        assert np.all(np.abs(out.y[k, 0] - level) < 1e-10 * level)


@pytest.mark.parametrize("rtol", [1e-5, 1e-8])
def test_located_times_converge_to_the_exact_crossings(rtol):
    out = integrate(DecayCrossings(), (0.0, 5.0), [1.0], rtol=rtol, atol=1e-14)
    t_exact = -np.log(LEVELS)
    t_e = np.array(out.event_times)
    assert t_e.size == 2
    assert np.all(np.abs(t_e - t_exact) < 20 * rtol * t_exact)
