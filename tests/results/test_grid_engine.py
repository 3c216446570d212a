"""Linearization over a parameter grid and estimation on the ensemble engine.

A mass on a spring-damper, m s'' + d s' + c s = 0: its poles are
(-d +- sqrt(d^2 - 4 m c)) / (2 m) at every point of the grid; the engine's results on
local processes equal the serial ones, and an estimate whose Jacobian simulations run on
processes finds the same parameters as the serial estimate.
"""
import numpy as np
import pytest

import acausal as ac
from acausal.library.translational import Fixed, Mass, SpringDamper

from ..analysis.test_estimate import A_TRUE, Tank


class Oscillator(ac.Component):
    mass = Mass(m=1.0, s={"start": 0.1, "fixed": True})
    spring = SpringDamper(c=4.0, d=0.5)
    wall = Fixed()

    def equations(self):
        return [ac.connect(self.mass.flange_a, self.spring.flange_b),
                ac.connect(self.spring.flange_a, self.wall.flange)]


def _poles(m, c, d):
    return np.sort_complex(np.roots([m, d, c]).astype(complex))


def test_poles_over_a_grid_match_the_closed_form_serial_and_on_processes():
    grid = {"mass.m": [0.5, 1.0, 2.0], "spring.c": [1.0, 4.0, 9.0]}
    compiled = ac.compile(Oscillator())
    serial = ac.linearize_grid(compiled, grid, inputs=[], outputs=["mass.s"])
    assert serial["A"].shape == (9, 2, 2) and bool(serial["success"].all())
    for i in range(9):
        m, c = float(serial["mass.m"][i]), float(serial["spring.c"][i])
        exact = _poles(m, c, 0.5)
        assert np.max(np.abs(serial["poles"].values[i] - exact)) <= 1e-8 * np.max(np.abs(exact))
    on_processes = ac.linearize_grid(compiled, grid, outputs=["mass.s"],
                                     executor="processes", max_workers=2)
    for k in ("A", "C", "poles"):
        a, b = serial[k].values, on_processes[k].values
        assert np.max(np.abs(a - b)) <= 1e-12 * np.max(np.abs(a))
    # the compiled model keeps its own values
    assert compiled.p[compiled.param_names.index("mass.m")] == 1.0


def test_a_point_that_cannot_be_linearized_keeps_its_reason_and_loses_no_other():
    ds = ac.linearize_grid(Oscillator(), {"mass.m": [1.0, -1.0, 2.0]}, grid="zip")
    assert ds["success"].values.tolist() == [True, False, True]
    assert "mass.m" in str(ds["message"].values[1]) and np.isnan(ds["A"].values[1]).all()
    assert np.max(np.abs(ds["poles"].values[2] - _poles(2.0, 4.0, 0.5))) <= 1e-8
    with pytest.raises(ValueError, match="one set of parameters"):
        res = ac.simulate(Oscillator(), t_end=1.0)
        ac.linearize_grid(Oscillator(), {"mass.m": [1.0]}, at=(res, 0.5))


def test_estimate_with_its_jacobian_on_processes_equals_the_serial_estimate():
    from acausal.analysis import estimate
    compiled = ac.compile(Tank(a=A_TRUE))
    t = np.linspace(0.0, 10.0, 101)
    q = ac.simulate(compiled, t_end=10.0, t_eval=t, rtol=1e-10)["q"]
    noisy = q + 0.001 * np.random.default_rng(2).standard_normal(len(t))
    serial = estimate(compiled, {"t": t, "q": noisy}, {"a": 0.5})
    spread = estimate(compiled, {"t": t, "q": noisy}, {"a": 0.5}, executor="processes")
    assert spread["a"] == pytest.approx(serial["a"], rel=1e-9)
    assert abs(serial["a"] - A_TRUE) < 3 * serial.std_errors["a"]
