"""Time events of periodic sources: every edge of a ``PulseVoltage`` is an event.

An RC low-pass (R = 1 kOhm) driven by a 1 V ``PulseVoltage``, the capacitor uncharged
at t = 0.  Between edges the capacitor voltage is an exponential with tau = R C towards
the source level, so the exact solution is a chain of exponentials through the edges:

    high:  v(t) = 1 - (1 - v_k) exp(-(t - t_k)/tau),   low:  v(t) = v_k exp(-(t - t_k)/tau)

* Narrow pulses: width 5e-4 of a 1 s period (0.05 %) (0.5 ms high from every whole second),
  C = 1 uF (tau = 1 ms), 20 s.  Edges in (0, 20): rising at 1, ..., 19 s (the one at
  t = 0 is the start, not an event) and falling at k + 5e-4 s, k = 0, ..., 19: 39 in
  all (the rising edge at t = 20 s itself, the 40th of (0, 20], ends the run and is not
  counted).  Each pulse charges the capacitor to 1 - exp(-0.5) = 0.3935 V, which then
  decays to nothing before the next one.
* A 20 kHz PWM: period 50 us, width 0.5, C = 0.1 uF (tau = 100 us), 5 ms (100 periods,
  199 edges in (0, 5 ms)); it settles into the periodic steady state
  v_high = 1/(1 + a), v_low = a/(1 + a), a = exp(-P/(2 tau)).
"""
import numpy as np
import pytest

import acausal as ac
from acausal.library.electrical import Capacitor, Ground, PulseVoltage, Resistor

R_OHM = 1e3


class PulsedRC(ac.Component):
    """PulseVoltage - R - C to ground."""

    src = PulseVoltage(V=1.0)
    R1 = Resistor(R=R_OHM)
    C1 = Capacitor(v={"start": 0.0, "fixed": True})
    gnd = Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.R1.p), ac.connect(self.R1.n, self.C1.p),
                ac.connect(self.C1.n, self.src.n, self.gnd.p)]


def _edges(width, period, t_end):
    """(time, level after it) of every edge in the open interval (0, t_end)."""
    out = []
    for k in range(int(np.ceil(t_end / period)) + 1):
        for t, level in ((k * period, 1.0), ((k + width) * period, 0.0)):
            if 0.0 < t < t_end * (1 - 1e-12):
                out.append((t, level))
    return sorted(out)


def _exact(t, width, period, tau, t_end):
    """Capacitor voltage at the times t (sorted), exponential from edge to edge."""
    edges = [(0.0, 1.0)] + _edges(width, period, t_end)
    v_at, out, j = 0.0, np.empty(len(t)), 0
    for (t0, level), t1 in zip(edges, [e[0] for e in edges[1:]] + [np.inf]):
        while j < len(t) and t[j] <= t1:
            out[j] = level - (level - v_at) * np.exp(-(t[j] - t0) / tau)
            j += 1
        if np.isfinite(t1):
            v_at = level - (level - v_at) * np.exp(-(t1 - t0) / tau)
    return out


def _event_times(res, t_end):
    """Distinct event times in (0, t_end) (an event may be listed once per iteration;
    an edge that falls on t_end itself may or may not be reported)."""
    ev = np.sort(np.asarray(res.events, dtype=float))
    ev = ev[(ev > 0.0) & (ev < t_end * (1 - 1e-12))]
    return ev[np.concatenate([[True], np.diff(ev) > 1e-9 * t_end])] if ev.size else ev


NARROW = dict(width=5e-4, period=1.0, tau=1e-3, t_end=20.0)


@pytest.fixture(scope="module")
def narrow():
    p = NARROW
    w, tau = p["width"], p["tau"]
    # output at the ends of some pulses, inside them and on the decays after them
    t = sorted({0.0, p["t_end"]} | {k + x for k in (0, 1, 7, 13, 19)
                                    for x in (0.5 * w, w, w + tau, w + 3 * tau, 0.5)})
    model = PulsedRC(src={"width": 100 * w, "period": p["period"]}, C1={"C": tau / R_OHM})
    return ac.simulate(model, t_end=p["t_end"], rtol=1e-8, t_eval=np.array(t))


def test_narrow_pulses_every_edge_is_an_event(narrow):
    assert narrow.success, narrow.message
    edges = np.array([e for e, _ in _edges(NARROW["width"], NARROW["period"],
                                            NARROW["t_end"])])
    assert len(edges) == 39
    found = _event_times(narrow, NARROW["t_end"])
    assert len(found) == len(edges)
    assert np.max(np.abs(found - edges)) < 1e-9 * NARROW["period"]


def test_narrow_pulses_charge_the_capacitor_as_the_closed_form(narrow):
    p = NARROW
    exact = _exact(narrow.t, p["width"], p["period"], p["tau"], p["t_end"])
    assert np.max(exact) == pytest.approx(1.0 - np.exp(-0.5), rel=1e-12)
    assert np.max(np.abs(narrow["C1.v"] - exact)) < 1e-6 * 1.0        # of the 1 V source


PWM = dict(width=0.5, period=5e-5, tau=1e-4, t_end=5e-3)


@pytest.fixture(scope="module")
def pwm():
    p = PWM
    t = np.linspace(0.0, p["t_end"], 1001)     # ten points a period, the edges included
    model = PulsedRC(src={"width": 100 * p["width"], "period": p["period"]},
                     C1={"C": p["tau"] / R_OHM})
    return ac.simulate(model, t_end=p["t_end"], rtol=1e-7, t_eval=t)


def test_pwm_every_edge_is_an_event(pwm):
    assert pwm.success, pwm.message
    edges = np.array([e for e, _ in _edges(PWM["width"], PWM["period"], PWM["t_end"])])
    assert len(edges) == 199
    found = _event_times(pwm, PWM["t_end"])
    assert len(found) == len(edges)
    assert np.max(np.abs(found - edges)) < 1e-9 * PWM["period"]


def test_pwm_follows_the_piecewise_exponentials_into_the_periodic_steady_state(pwm):
    p = PWM
    exact = _exact(pwm.t, p["width"], p["period"], p["tau"], p["t_end"])
    assert np.max(np.abs(pwm["C1.v"] - exact)) < 1e-5 * 1.0           # of the 1 V source
    a = np.exp(-p["period"] * p["width"] / p["tau"])
    last = pwm.t > p["t_end"] - 2 * p["period"]
    assert np.max(pwm["C1.v"][last]) == pytest.approx(1.0 / (1.0 + a), rel=1e-5)
    assert np.min(pwm["C1.v"][last]) == pytest.approx(a / (1.0 + a), rel=1e-5)
