"""Dynamic state selection in the compiled step loop (solvers/cbdf_dyn.c), against the
pendulum in its angle and against the Python loop.

The Cartesian pendulum of library/examples/pendulum.py, swinging to 72 degrees and going
round, passes the band where x stops being a good state (and, going round, y too) many
times.  The compiled loop tests the current choice after every step in C and hands the
search back to Python only when that test fails, so both loops must take the same
decisions: the same choices, in the same order, at the same steps.  Each run is judged
against theta'' = -(g/L) sin(theta) by scipy's DOP853 at rtol 1e-12 (a different
formulation and method), relative to the pendulum's size L = 1.
"""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal as ac
from acausal.library.examples.pendulum import Pendulum
from acausal.solvers.cbdf import library

pytestmark = pytest.mark.skipif(library() is None, reason="no C compiler on this machine")

G = 9.81
RTOL = 1e-6
# (x0, vx0, t_end): a 72 degree swing (through the switching band twice per half
# period) and full turns (vx0 = 7 m/s at the bottom)
CASES = {"swing 72 deg": (0.95, 0.0, 10.0), "full turns": (0.0, 7.0, 3.0)}


@pytest.fixture(scope="module", params=list(CASES), ids=list(CASES))
def runs(request):
    x0, vx0, t_end = CASES[request.param]
    compiled = ac.compile(Pendulum(x={"start": x0}, y={"start": -np.sqrt(1.0 - x0**2)},
                                   vx={"start": vx0}), backend="c")
    out = {loop: ac.simulate(compiled, t_end=t_end, rtol=RTOL, step_loop=loop)
           for loop in ("c", "python")}
    theta0 = np.arcsin(x0)
    ref = solve_ivp(lambda _, s: [s[1], -G * np.sin(s[0])], (0.0, t_end),
                    [theta0, vx0 / np.cos(theta0)], method="DOP853", rtol=1e-12,
                    atol=1e-12, dense_output=True).sol
    return out, ref


def test_both_loops_match_the_angle_ode(runs):
    out, ref = runs
    assert out["c"].stats["step_loop"] == "c"
    assert out["python"].stats["step_loop"] == "python"
    for res in out.values():
        assert res.success, res.message
        theta = ref(res.t)[0]
        err = np.hypot(res["x"] - np.sin(theta), res["y"] + np.cos(theta))    # L = 1
        # a BDF's global error on an undamped swing grows with time (it damps a little
        # at every step): within 250 tolerances over 5 periods or 3 turns, as the Python
        # loop is held to in test_pendulum_steps.py
        assert err.max() < 250 * RTOL


def test_the_loops_switch_states_at_the_same_steps(runs):
    out, _ = runs
    c, py = out["c"].state_switches, out["python"].state_switches
    assert len(c) >= 4                      # x -> y -> x ... in every swing or turn
    assert [s.changes for s in c] == [s.changes for s in py]
    # a switch is taken after an accepted step: the same step in both loops, whose
    # ends differ only as far as the loops' step sizes have drifted apart (the LUs round
    # differently, and the error test feeds that back into h), far below the step
    t = out["python"].t
    for a, b in zip(c, py):
        k = np.searchsorted(t, float(b))
        assert abs(a - b) < 0.01 * (t[k] - t[k - 1]), (float(a), float(b))


def test_every_switch_keeps_the_better_conditioned_coordinate(runs):
    """After a switch the position state is the coordinate of smaller magnitude: the
    constraint x^2 + y^2 = L^2 then fixes the other one well (its sensitivity to the
    state, |state / other|, is below one), and the switch happens before the dropped
    state's pivot has fallen to a third of the kept one (runtime/dynamic.py)."""
    out, _ = runs
    res = out["c"]
    for s in res.state_switches:
        k = np.searchsorted(res.t, float(s))
        x, y = abs(res["x"][k]), abs(res["y"][k])
        new = s.changes[0][2].split(", ")
        state_x = "der(x)" not in new          # der(x) a dummy: x is no state
        assert state_x == ("der(y)" in new)     # exactly one of them is a state
        assert (x < y) if state_x else (y < x), (float(s), x, y, new)
        assert min(x, y) / max(x, y) > 1.0 / 3.0


class PushedPendulum(ac.Component):
    """The Cartesian pendulum with a horizontal push F = +-F0 along the horizontal
    velocity (a relation on vx: zero crossings), m = L = 1."""

    L = ac.Parameter(1.0, unit="m")
    m = ac.Parameter(1.0, unit="kg")
    F0 = ac.Parameter(0.3, unit="N")
    g = ac.Parameter(G, unit="m/s2")
    x = ac.Variable(start=0.95, fixed=True, unit="m")
    y = ac.Variable(start=-np.sqrt(1.0 - 0.95**2), unit="m")
    vx = ac.Variable(start=0.0, fixed=True, unit="m/s")
    vy = ac.Variable(start=0.0, unit="m/s")
    lam = ac.Variable(start=10.0, unit="N/m")

    def equations(self):
        x, y, vx, vy, lam = self.x, self.y, self.vx, self.vy, self.lam
        push = ac.if_else(vx > 0, self.F0, -self.F0)
        return [ac.Eq(ac.der(x), vx), ac.Eq(ac.der(y), vy),
                ac.Eq(self.m * ac.der(vx), -lam * x + push),
                ac.Eq(self.m * ac.der(vy), -lam * y - self.m * self.g),
                ac.Eq(x**2 + y**2, self.L**2)]


def _pushed_angle(t_out, theta0, F0, t_end):
    """theta'' = -g sin(theta) + F0 sign(omega) cos(theta) (the push's tangential part;
    within |theta| < 90 degrees vx > 0 exactly when omega > 0), DOP853 restarted at each
    turning point omega = 0."""
    t, s, side, pieces = 0.0, [theta0, 0.0], -1.0, []   # from rest at x > 0: falls back
    while t < t_end:
        def turn(_, s, *a):
            return s[1]
        turn.terminal, turn.direction = True, -side     # omega leaves the sign `side`
        sol = solve_ivp(lambda _, s, d: [s[1], -G * np.sin(s[0]) + d * F0 * np.cos(s[0])],
                        (t, t_end), s, args=(side,), events=turn, method="DOP853",
                        rtol=1e-12, atol=1e-12, dense_output=True)
        pieces.append((t, sol.t[-1], sol.sol))
        t, s, side = sol.t[-1], sol.y[:, -1], -side
    return np.array([next(sol for _, b, sol in pieces if tk <= b)(tk)[0] for tk in t_out])


def test_state_switches_and_events_together_match_the_angle_ode():
    """Zero crossings (the push reverses at every turning point) and state switches in
    one run: both loops locate the same events and take the same choices, and both
    match the angle ODE restarted at its turning points."""
    compiled = ac.compile(PushedPendulum(), backend="c")
    t_out = np.linspace(0.0, 6.0, 241)
    out = {loop: ac.simulate(compiled, t_end=6.0, rtol=RTOL, t_eval=t_out, step_loop=loop)
           for loop in ("c", "python")}
    theta = _pushed_angle(t_out, np.arcsin(0.95), 0.3, 6.0)
    c, py = out["c"], out["python"]
    assert len(c.events) >= 4 and len(c.state_switches) >= 4
    assert np.allclose(np.asarray(c.events, float), np.asarray(py.events, float),
                       rtol=0, atol=1e-6)
    assert [s.changes for s in c.state_switches] == [s.changes for s in py.state_switches]
    for res in out.values():
        assert res.success, res.message
        err = np.hypot(res["x"] - np.sin(theta), res["y"] + np.cos(theta))
        assert err.max() < 100 * RTOL      # as for the free swing, over 3 periods, not 5


def test_a_full_output_buffer_loses_no_switch(monkeypatch):
    """With room for one output point per return and several requested points in every
    step, steps come back with a full buffer, their points still to be written by Python:
    a degraded choice found at such a step must still be re-examined there (after its
    points), as in the Python loop."""
    from acausal.solvers import cbdf
    x0, vx0, t_end = CASES["full turns"]
    compiled = ac.compile(Pendulum(x={"start": x0}, y={"start": -1.0}, vx={"start": vx0}),
                          backend="c")
    t_out = np.linspace(0.0, t_end, 3001)            # ~8 points per step
    py = ac.simulate(compiled, t_end=t_end, rtol=RTOL, t_eval=t_out, step_loop="python")
    monkeypatch.setattr(cbdf, "CAPACITY", 1)
    c = ac.simulate(compiled, t_end=t_end, rtol=RTOL, t_eval=t_out, step_loop="c")
    assert c.stats["step_loop"] == "c" and len(c.state_switches) >= 4
    assert [s.changes for s in c.state_switches] == [s.changes for s in py.state_switches]
    theta = solve_ivp(lambda _, s: [s[1], -G * np.sin(s[0])], (0.0, t_end), [0.0, vx0],
                      method="DOP853", rtol=1e-12, atol=1e-12, dense_output=True).sol(c.t)[0]
    err = np.hypot(c["x"] - np.sin(theta), c["y"] + np.cos(theta))
    assert err.max() < 250 * RTOL          # as test_both_loops_match_the_angle_ode
