"""Over-specified initial problems: consistent redundant conditions are checked and
dropped (with a warning naming them), inconsistent ones are refused naming the
conditions and their residuals (OpenModelica's rule; ``acausal/runtime/redundant.py``).

The models:

* a pendulum in Cartesian coordinates, x^2 + y^2 = L^2 (index 3), with both x and y
  fixed: on the circle the second is redundant, off it the two contradict the rod;
* two capacitors in parallel charged through a resistor: one state, and both capacitor
  voltages fixed -- redundant exactly when they are equal.

References: the run with only the necessary conditions (the redundant ones dropped by
hand) is the same run, to the last bit; the closed form of the RC circuit.
"""
import numpy as np
import pytest

import acausal as ac
from acausal import InitializationFailed
from acausal import InitialConditionWarning

L, G = 1.0, 9.81
X0 = 0.6


class Pendulum(ac.Component):
    """x'' = -lam x, y'' = -lam y - g, x^2 + y^2 = L^2 (unit mass)."""

    x = ac.Variable(start=X0, fixed=True)
    y = ac.Variable(start=-np.sqrt(L**2 - X0**2))
    vx = ac.Variable(start=0.0, fixed=True)
    vy = ac.Variable(start=0.0)
    lam = ac.Variable(start=1.0)

    def equations(self):
        return [ac.Eq(ac.der(self.x), self.vx), ac.Eq(ac.der(self.y), self.vy),
                ac.Eq(ac.der(self.vx), -self.lam * self.x),
                ac.Eq(ac.der(self.vy), -self.lam * self.y - G),
                ac.Eq(self.x**2 + self.y**2, L**2)]


def _run(model, **kw):
    return ac.simulate(model, t_end=1.0, rtol=1e-8, n_points=11, check_units="off", **kw)


def test_consistent_redundant_position_is_dropped_with_a_warning():
    reference = _run(Pendulum())
    over = Pendulum(y={"start": -np.sqrt(L**2 - X0**2), "fixed": True},
                    vy={"start": 0.0, "fixed": True})
    compiled = ac.compile(over, check_units="off")
    assert any("redundant" in n for n in compiled.report.notes)
    with pytest.warns(InitialConditionWarning, match=r"y = -0\.8.*fixed start value"):
        res = ac.simulate(compiled, t_end=1.0, rtol=1e-8, n_points=11)
    assert res.success
    for name in ("x", "y", "vx", "vy", "lam"):
        np.testing.assert_array_equal(res[name], reference[name])
    assert any("were dropped" in n for n in compiled.report.notes)


def test_inconsistent_positions_are_refused_naming_the_conditions_and_residuals():
    over = Pendulum(y={"start": -0.7, "fixed": True})      # 0.6^2 + 0.7^2 != 1
    with pytest.raises(InitializationFailed) as err:
        _run(over)
    text = str(err.value)
    assert "over-specified and inconsistent" in text
    assert "y = -0.7 (fixed start value)" in text and "residual" in text
    assert "x = 0.6" in text              # the kept condition it conflicts with


class ParallelCapacitors(ac.Component):
    """A 10 V source and R = 1 kOhm charging C1 = 1 uF and C2 = 2 uF in parallel."""

    from acausal.library.electrical import Capacitor, ConstantVoltage, Ground, Resistor
    src = ConstantVoltage(V=10.0)
    R = Resistor(R=1000.0)
    C1 = Capacitor(C=1e-6)
    C2 = Capacitor(C=2e-6)
    gnd = Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.R.p), ac.connect(self.R.n, self.C1.p, self.C2.p),
                ac.connect(self.C1.n, self.C2.n, self.src.n, self.gnd.p)]


def test_parallel_capacitor_voltages_both_fixed_follow_the_closed_form():
    # one state: the common voltage; fixing it on both capacitors says it twice
    model = ParallelCapacitors(C1={"v": {"start": 2.0, "fixed": True}},
                               C2={"v": {"start": 2.0, "fixed": True}})
    with pytest.warns(InitialConditionWarning, match=r"C\d\.v = 2\.0 \(fixed start"):
        res = ac.simulate(model, t_end=5e-3, rtol=1e-9, n_points=21)
    tau = 1000.0 * 3e-6
    v = 10.0 + (2.0 - 10.0) * np.exp(-res.t / tau)
    np.testing.assert_allclose(res["C1.v"], v, rtol=1e-7, atol=1e-7 * 10)
    np.testing.assert_allclose(res["C2.v"], v, rtol=1e-7, atol=1e-7 * 10)


def test_parallel_capacitor_voltages_that_disagree_are_refused():
    model = ParallelCapacitors(C1={"v": {"start": 2.0, "fixed": True}},
                               C2={"v": {"start": 3.0, "fixed": True}})
    with pytest.raises(InitializationFailed) as err:
        ac.simulate(model, t_end=1e-3)
    text = str(err.value)
    assert "C1.v = 2.0 (fixed start value" in text and "C2.v = 3.0" in text
    assert "residual 1," in text and "conflicts with" in text


class _RestingRate(ac.Component):
    """x' = c (1 - x), c' = 0: the rate a = x' held at 0 at the start fixes c."""

    x = ac.Variable(start=0.5, fixed=True)
    c = ac.Variable(start=100.0)
    a = ac.Variable(fixed=True)           # fixed, no start: Modelica's default start 0

    def equations(self):
        return [ac.Eq(ac.der(self.x), self.c * (1 - self.x)), ac.Eq(ac.der(self.c), 0),
                ac.Eq(self.a, ac.der(self.x))]


def test_fixed_without_a_start_holds_the_default_start():
    # a(0) = 0 with x(0) = 0.5 forces c = 0: x stays 0.5 (with c at its start, 100, x
    # would rise to 1 within 0.05 s)
    res = ac.simulate(_RestingRate(), t_end=1.0, rtol=1e-9, n_points=11)
    assert abs(res["c"][0]) <= 1e-12 and np.max(np.abs(res["x"] - 0.5)) <= 1e-12
