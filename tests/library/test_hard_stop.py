"""Hard stops (MassWithStop) against closed forms: a mass pushed into a stop by
F0 sin(omega t) rests with v = 0 exactly and leaves when the force reverses; Newton's
restitution reverses the velocity exactly; rebounds end in rest below v_rest."""
import math

import numpy as np
from scipy.optimize import brentq

import acausal as ac
from acausal.library.translational import ConstantForce, MassWithStop
from acausal.library.translational.examples.mass_with_stop import MassAgainstStop

OMEGA, F0, M, S_MAX = math.pi, 1.0, 1.0, 0.1


def test_mass_rests_at_the_stop_and_leaves_when_the_force_reverses():
    res = ac.simulate(MassAgainstStop(), t_end=2.0, rtol=1e-10)
    assert res.success
    t, s, v = res.t, res["mass.s"], res["mass.v"]
    events = np.array(res.events)
    # from rest: v = F0/(m w) (1 - cos wt), s = F0/(m w) (t - sin(wt)/w), up to s_max
    s1 = lambda tt: F0 / (M * OMEGA) * (tt - np.sin(OMEGA * tt) / OMEGA)
    t_hit = brentq(lambda tt: s1(tt) - S_MAX, 0.1, 1.0, xtol=1e-15)
    assert np.min(np.abs(events - t_hit)) < 1e-8
    before = t < t_hit - 1e-6
    assert np.max(np.abs(s[before] - s1(t[before]))) < 1e-8
    # resting: the force pushes in until t = pi/w = 1 s, where the release is located
    # (to the event tolerance, on either side of 1); v = 0 and s = s_max exactly
    t_release = events[np.argmin(np.abs(events - 1.0))]
    rest = (t > t_hit + 1e-9) & (t < t_release)
    assert rest.sum() > 3
    # exact on every machine: the hit's reinit sets v = 0 and s = s_max (e = 0: s_max
    # - 0 * 2 eps), and resting der(v) = (f_app + f_stop)/m = (f - f)/m = 0 exactly
    assert np.all(v[rest] == 0.0) and np.all(s[rest] == S_MAX)
    stop_force = res["mass.f_stop"][rest]
    assert np.max(np.abs(stop_force + F0 * np.sin(OMEGA * t[rest]))) < 1e-12 * F0
    # released at the reversal: an event at 1 s, moving from then on, on the closed form
    # v = F0/(m w) (cos(w) - cos(wt)), s = s_max - F0/(m w) ((t - 1) + sin(wt)/w)
    assert abs(t_release - 1.0) < 1e-11 * 1.0          # of the release time
    after = t > t_release
    assert np.all(v[after] < 0.0)
    ta = t[after]
    assert np.max(np.abs(v[after] - F0 / (M * OMEGA) * (-1 - np.cos(OMEGA * ta)))) < 1e-8
    s2 = S_MAX - F0 / (M * OMEGA) * ((ta - 1) + np.sin(OMEGA * ta) / OMEGA)
    assert np.max(np.abs(s[after] - s2)) < 1e-8


def test_example_stays_between_the_stops():
    res = ac.simulate(MassAgainstStop(), t_end=MassAgainstStop.stop_time, rtol=1e-8)
    assert res.success
    s = res["mass.s"]
    travel = 0.1 - (-0.3)
    assert s.min() >= -0.3 - 2.5e-12 * travel and s.max() <= 0.1 + 2.5e-12 * travel
    # resting at a stop (put there exactly by a reinit, pushed into it: a stop force),
    # v = 0 exactly; just after a release s can still equal the stop to the last bit
    # while v is already a few ulps, so the stop force, not s, tells who rests
    resting = ((s == 0.1) | (s == -0.3)) & (res["mass.f_stop"] != 0.0)
    assert resting.any() and np.all(res["mass.v"][resting] == 0.0)


class FreeFlight(ac.Component):
    """No force: v0 = 1 m/s from s = 0 between stops at -0.5 and 0.5 m, e = 0.5."""

    mass = MassWithStop(m=2.0, s_min=-0.5, s_max=0.5, e=0.5,
                        s={"start": 0.0, "fixed": True}, v={"start": 1.0, "fixed": True})


def test_restitution_reverses_the_velocity_exactly():
    res = ac.simulate(FreeFlight(), t_end=7.0, rtol=1e-10)
    assert res.success
    t, v = res.t, res["mass.v"]
    # hits at 0.5 (s_max), 0.5 + 1/0.5 = 2.5 (s_min), 2.5 + 1/0.25 = 6.5 (s_max)
    hits = [0.5, 2.5, 6.5]
    assert len(res.events) == 3
    # each hit is taken in a band eps = 1e-10 m before the stop, and a rebound starts
    # 2 eps inside: the times drift by a few eps/v
    assert np.max(np.abs(np.array(res.events) - hits)) < 1e-8
    for lo, hi, expected in [(0, 0.5, 1.0), (0.5, 2.5, -0.5), (2.5, 6.5, 0.25),
                             (6.5, 7.0, -0.125)]:
        inside = (t > lo + 1e-6) & (t < hi - 1e-6)
        # exact: e = 0.5 and v0 = 1 make each reinit -e v a power of two, and with no
        # force der(v) = 0 exactly between the hits
        assert inside.any() and np.all(v[inside] == expected)


class PushedWithRebound(ac.Component):
    """1 N pushes a 1 kg mass from rest into the stop at 0.5 m: hits at 1 m/s,
    e = 0.5, rebounds until e v < v_rest = 0.01 m/s."""

    mass = MassWithStop(m=1.0, s_min=-1.0, s_max=0.5, e=0.5, v_rest=0.01,
                        s={"start": 0.0, "fixed": True}, v={"start": 0.0, "fixed": True})
    push = ConstantForce(f_constant=1.0)

    def equations(self):
        return [ac.connect(self.push.flange, self.mass.flange_b)]


def test_rebounds_end_at_rest_on_the_stop():
    res = ac.simulate(PushedWithRebound(), t_end=4.0, rtol=1e-10)
    assert res.success
    # the k-th hit at v_k = 0.5^k m/s; the flight between hits takes 2 v_k (a = 1 m/s2)
    v_hits = 0.5 ** np.arange(7)                     # 0.5 * 0.5^6 < 0.01: plastic
    t_hits = 1.0 + np.concatenate([[0.0], np.cumsum(2 * 0.5 * v_hits[:-1])])
    assert len(res.events) == 7
    # a hit is taken eps = 1e-10 m early and a rebound starts 2 eps inside: the hit
    # times drift by about 3 eps/v_k each, 4e-8 s over these seven
    assert np.max(np.abs(np.array(res.events) - t_hits)) < 5e-8
    t, s, v = res.t, res["mass.s"], res["mass.v"]
    rest = t > t_hits[-1] + 1e-9
    assert np.all(v[rest] == 0.0) and np.all(s[rest] == 0.5)    # the plastic hit's reinit
    # the stop's reaction to the push: computed, so judged to rounding of the push's 1 N
    assert np.max(np.abs(res["mass.f_stop"][rest] + 1.0)) < 1e-12 * 1.0
