"""Reported outputs must agree with the integration they come from, events included.

In a switching model every output that is the time derivative of a state (or a
combination that the model's equations make one) must match the slope of the
integrated state, in the mode that was integrated, also at the output points just
before and just after an event.  The check needs no model knowledge beyond the one
equation: for consecutive output points k, k+1 in the same mode,

    (x_{k+1} - x_k) / (t_{k+1} - t_k)  =  (a_k + a_{k+1}) / 2  + O(h^2 a'')

(the trapezoidal rule), compared relative to the size of a over the run.  The outputs
are taken at the solver's own steps plus the points just before and after each event
(``t_eval=None``).

Models:

* an inertia J = 0.02 kg m2 coasting on Karnopp friction F_s = F_c = 0.2 N m from
  -1 rad/s: a = der(w) and J a = -tau_friction; it stops at 0.1 s and stays;
* the heater of ``test_steady_state_modes`` (C = 5 kJ/K, G = 10 W/K, P controller
  K_p = 100 W/K through a 0..1 kW Limiter) heating from ambient: C T' = Q - G (T - T_amb),
  the limiter leaving saturation at t = 111.57 s;
* a half-wave rectifier: 10 V, 50 Hz sine (phase 0.3 rad) - 10 Ohm - IdealDiode -
  100 uF || 1 kOhm:  i_diode = C v' + v/R.
"""
import numpy as np

import acausal as ac
from acausal.library import electrical as el
from acausal.library import rotational as rot
from acausal.library.friction.rotational import KarnoppFriction

from ..heater import C_TH, G, K_P, Q_MAX, T_AMB, LimitedHeater

TOL = 5e-3          # of max |a|: far below any sign or branch error, above O(h^2 a'')


def _mode_pairs(res):
    """Index pairs (k, k+1) of consecutive outputs in the same mode, h not vanishing."""
    t, ev = res.t, np.sort(np.asarray(res.events, dtype=float))
    span = t[-1] - t[0]
    pairs = []
    for k in range(len(t) - 1):
        h = t[k + 1] - t[k]
        across = np.any((ev > t[k]) & (ev < t[k + 1]))
        if h > 1e-7 * span and not across:
            pairs.append(k)
    return np.array(pairs, dtype=int)


def _slope_mismatch(res, x, a):
    """max |secant slope - trapezoidal mean of a| / max |a| over same-mode pairs."""
    k = _mode_pairs(res)
    t = res.t
    slope = (x[k + 1] - x[k]) / (t[k + 1] - t[k])
    mean = 0.5 * (a[k] + a[k + 1])
    worst = int(np.argmax(np.abs(slope - mean)))
    return (np.max(np.abs(slope - mean)) / np.max(np.abs(a)),
            f"at t = {t[k[worst]]:.10g}: slope {slope[worst]:.6g}, reported {mean[worst]:.6g}")


class CoastingOnFriction(ac.Component):
    """Inertia from -1 rad/s on Karnopp friction, nothing else."""

    friction = KarnoppFriction(F_c=0.2, F_s=0.2, dv=1e-9)
    load = rot.Inertia(J=0.02, phi={"start": 0.0, "fixed": True},
                       w={"start": -1.0, "fixed": True})
    housing = rot.Fixed()

    def equations(self):
        return [ac.connect(self.load.flange_b, self.friction.flange_b),
                ac.connect(self.friction.flange_a, self.housing.flange)]


def test_friction_outputs_follow_the_integrated_speed():
    res = ac.simulate(CoastingOnFriction(), t_end=0.2, rtol=1e-8)
    assert res.success, res.message
    w = res["load.w"]
    err, where = _slope_mismatch(res, w, res["load.a"])
    assert err < TOL, "load.a " + where
    err, where = _slope_mismatch(res, w, -res["friction.tau"] / 0.02)
    assert err < TOL, "-friction.tau/J " + where


def HeaterWithLimiter():
    """P temperature control through a 0..1 kW Limiter, starting at ambient (fixed)."""
    return LimitedHeater(body={"T": {"start": T_AMB, "fixed": True}})


def test_limiter_outputs_follow_the_integrated_temperature():
    res = ac.simulate(HeaterWithLimiter(), t_end=2000.0, rtol=1e-8)
    assert res.success, res.message
    t_release = -C_TH / G * np.log(1 - (323.15 - Q_MAX / K_P - T_AMB) * G / Q_MAX)
    assert np.min(np.abs(np.asarray(res.events) - t_release)) < 1e-6 * t_release
    T = res["body.T"]
    err, where = _slope_mismatch(res, T, res["der(body.T)"])
    assert err < TOL, "der(body.T) " + where
    heat = (res["limit.y.signal"] - G * (T - T_AMB)) / C_TH
    err, where = _slope_mismatch(res, T, heat)
    assert err < TOL, "(Q - G (T - T_amb))/C " + where


class HalfWaveRectifier(ac.Component):
    """Sine source - series resistor - ideal diode - capacitor parallel to a load."""

    src = el.SineVoltage(V=10.0, f=50.0, phase=0.3)
    Rs = el.Resistor(R=10.0)
    diode = el.IdealDiode()
    C1 = el.Capacitor(C=1e-4, v={"start": 0.0, "fixed": True})
    load = el.Resistor(R=1e3)
    gnd = el.Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.Rs.p),
                ac.connect(self.Rs.n, self.diode.p),
                ac.connect(self.diode.n, self.C1.p, self.load.p),
                ac.connect(self.src.n, self.C1.n, self.load.n, self.gnd.p)]


def test_diode_outputs_follow_the_integrated_capacitor_voltage():
    res = ac.simulate(HalfWaveRectifier(), t_end=0.1, rtol=1e-8)
    assert res.success, res.message
    assert len(res.events) >= 8                # on and off in each of 5 periods
    v = res["C1.v"]
    err, where = _slope_mismatch(res, v, res["C1.i"] / 1e-4)
    assert err < TOL, "C1.i/C " + where
    charge = (res["diode.i"] - v / 1e3) / 1e-4
    err, where = _slope_mismatch(res, v, charge)
    assert err < TOL, "(i_diode - v/R)/C " + where
