"""Electrical circuits against their closed-form solutions (relative error < 1e-5)."""
import numpy as np
import pytest

import acausal as ac
from acausal.library.electrical import (Capacitor, ConstantVoltage, Ground, Inductor,
                                        Resistor, StepVoltage)


class RCCharging(ac.Component):
    """V source, series R, capacitor to ground: v_C = V (1 - exp(-t / (R C)))."""

    src = ConstantVoltage(V=10.0)
    R1 = Resistor(R=100.0)
    C1 = Capacitor(C=1e-3)
    gnd = Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.R1.p), ac.connect(self.R1.n, self.C1.p),
                ac.connect(self.C1.n, self.src.n, self.gnd.p)]


class SeriesRLC(ac.Component):
    """Step source, R, L and C in series."""

    src = StepVoltage(V=1.0)
    R1 = Resistor(R=10.0)
    L1 = Inductor(L=1e-2)
    C1 = Capacitor(C=1e-4)
    gnd = Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.R1.p), ac.connect(self.R1.n, self.L1.p),
                ac.connect(self.L1.n, self.C1.p), ac.connect(self.C1.n, self.src.n, self.gnd.p)]


def test_rc_charging_matches_exponential():
    t = np.linspace(0, 0.5, 101)
    res = ac.simulate(RCCharging(), t_end=0.5, rtol=1e-8, t_eval=t)
    exact = 10.0 * (1 - np.exp(-t / 0.1))
    assert np.allclose(res.t, t)
    err = np.max(np.abs(res["C1.v"] - exact)) / 10.0
    assert err < 1e-5
    # every variable is in the result under its own name, aliases included
    assert np.allclose(res["R1.n.v"], res["C1.v"]) and np.allclose(res["src.i"], -res["R1.i"])


def _rlc_underdamped(t, V, R, L, C):
    """v_C(t) for a unit step on a series RLC, underdamped: alpha < w0."""
    alpha, w0 = R / (2 * L), 1 / np.sqrt(L * C)
    wd = np.sqrt(w0**2 - alpha**2)
    return V * (1 - np.exp(-alpha * t) * (np.cos(wd * t) + alpha / wd * np.sin(wd * t)))


def test_series_rlc_step_response_underdamped():
    t = np.linspace(0, 0.02, 401)
    res = ac.simulate(SeriesRLC(), t_end=0.02, rtol=1e-8, t_eval=t)
    exact = _rlc_underdamped(t, 1.0, 10.0, 1e-2, 1e-4)
    assert np.max(np.abs(res["C1.v"] - exact)) / np.max(np.abs(exact)) < 1e-5
    alpha, w0 = 10.0 / (2 * 1e-2), 1 / np.sqrt(1e-2 * 1e-4)
    wd = np.sqrt(w0**2 - alpha**2)
    i_exact = 1e-4 * np.exp(-alpha * t) * w0**2 / wd * np.sin(wd * t)   # i = C dv/dt
    assert np.max(np.abs(res["L1.i"] - i_exact)) / np.max(np.abs(i_exact)) < 1e-5


def test_modification_at_instantiation_changes_the_time_constant():
    t = np.linspace(0, 0.2, 41)
    res = ac.simulate(RCCharging(R1={"R": 50.0}), t_end=0.2, rtol=1e-8, t_eval=t)
    assert np.max(np.abs(res["C1.v"] - 10.0 * (1 - np.exp(-t / 0.05)))) < 1e-4


def test_parameters_change_without_recompiling():
    compiled = ac.compile(RCCharging())
    t = np.linspace(0, 0.2, 41)
    res = ac.simulate(compiled, t_end=0.2, rtol=1e-8, t_eval=t, parameters={"C1.C": 2e-3})
    assert np.max(np.abs(res["C1.v"] - 10.0 * (1 - np.exp(-t / 0.2)))) < 1e-4


def test_result_csv_and_names(tmp_path):
    res = ac.simulate(RCCharging(), t_end=0.1, rtol=1e-6, n_points=11)
    assert "C1.v" in res.names and "R1.p.v" in res.names
    path = tmp_path / "rc.csv"
    res.to_csv(path, names=["C1.v"])
    data = np.loadtxt(path, delimiter=",", skiprows=1)
    assert data.shape == (11, 2) and np.allclose(data[:, 1], res["C1.v"])
    assert res.stats["steps"] > 0            # the statistics are reported (any run steps)
    with pytest.raises(KeyError, match="C1.vv"):
        res["C1.vv"]
