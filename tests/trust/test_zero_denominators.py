"""Denominators that are exactly zero in one branch of an if-expression or of min/max.

A branch whose condition is false once the compile-time constants are in (a structural
zero parameter, a variable that its equations make a constant) is dropped, so a guarded
division ``if R > 0 then v/R else 0`` with R = 0 compiles and runs.  Where the condition
depends on the solution, a denominator the constants make identically zero is an error
naming the equation and the constants.  A zero that only one mode of a min/max gives
(-x/max(p, 0) with a tunable p <= 0) is compiled as an undefined value in that mode:
the run stops naming the equation if the mode is reached (through the iteration matrix
where the value multiplies a variable, through the residual where it stands alone), and
the same compiled model runs with p > 0.  On both backends, never a sympy traceback
(the C printer used to meet ``zoo``).  Results are checked against closed forms.
"""
import re

import numpy as np
import pytest

import acausal as ac
from acausal.errors import InvalidEquation

BACKENDS = ["numpy", "c"]
T = np.linspace(0.0, 2.0, 41)


class GuardedConductance(ac.Component):
    """i = if R > 0 then v/R else 0, v = sin(w t)."""

    R = ac.Parameter(0.0)
    w = ac.Parameter(1.0)
    v = ac.Variable()
    i = ac.Variable()

    def equations(self):
        return [ac.Eq(self.v, ac.sin(self.w * ac.time)),
                ac.Eq(self.i, ac.if_else(self.R > 0, self.v / self.R, 0.0))]


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("R", [0.0, 2.0])
def test_guarded_division_by_a_structural_zero(R, backend):
    res = ac.simulate(GuardedConductance(R=R), 2.0, t_eval=T, backend=backend)
    assert res.success
    expected = np.sin(T) / R if R > 0 else np.zeros_like(T)
    assert np.max(np.abs(res["i"] - expected)) < 1e-9 * max(1.0, np.max(np.abs(expected)))


class GuardedByAConstant(ac.Component):
    """g = 0 by its equation; der(x) = if g > 0 then -x/g else -x: the guard is false."""

    g = ac.Variable()
    x = ac.Variable(start=1.0, fixed=True)

    def equations(self):
        return [ac.Eq(self.g, 0.0),
                ac.Eq(ac.der(self.x), ac.if_else(self.g > 0, -self.x / self.g, -self.x))]


@pytest.mark.parametrize("backend", BACKENDS)
def test_guarded_division_by_a_constant_variable(backend):
    res = ac.simulate(GuardedByAConstant(), 2.0, t_eval=T, rtol=1e-9, backend=backend)
    assert res.success
    assert np.max(np.abs(res["x"] - np.exp(-T))) < 1e-7


class ConstantDifference(ac.Component):
    """x = p, and 1/(x - p) in a branch the solution decides."""

    p = ac.Parameter(1.0)
    x = ac.Variable()
    y = ac.Variable(start=1.0, fixed=True)

    def equations(self):
        return [ac.Eq(self.x, self.p),
                ac.Eq(ac.der(self.y),
                      ac.if_else(self.y > 10, 1 / (self.x - self.p), -self.y),
                      label="growth law")]


@pytest.mark.parametrize("backend", BACKENDS)
def test_division_by_a_difference_of_constants_is_named(backend):
    with pytest.raises(InvalidEquation) as info:
        ac.compile(ConstantDifference(), backend=backend)
    message = str(info.value)
    assert "growth law" in message and "ConstantDifference" in message
    assert "x = p" in message and "divides by zero" in message


class ClippedRate(ac.Component):
    """der(x) = -x/max(p, 0) while x < x_switch, else -x."""

    p = ac.Parameter(-1.0)
    x_switch = ac.Parameter(0.5)
    x = ac.Variable(start=1.0, fixed=True)

    def near(self):
        return self.x < self.x_switch

    def equations(self):
        return [ac.Eq(ac.der(self.x),
                      ac.if_else(self.near(), -self.x / ac.max(self.p, 0), -self.x))]


class ClippedAbove(ClippedRate):
    """The same with the clipped rate while x > x_switch."""

    def near(self):
        return self.x > self.x_switch


@pytest.mark.parametrize("backend", BACKENDS)
def test_zero_mode_of_max_never_reached(backend):
    # x = exp(-t) stays below 10: the branch that divides by max(p, 0) = 0 is not taken
    res = ac.simulate(ClippedAbove(x_switch=10.0), 2.0, t_eval=T, rtol=1e-9,
                      backend=backend)
    assert res.success
    assert np.max(np.abs(res["x"] - np.exp(-T))) < 1e-7


@pytest.mark.parametrize("backend", BACKENDS)
def test_zero_mode_of_max_reached_stops_the_run(backend):
    compiled = ac.compile(ClippedRate(), backend=backend)
    # p = -1: at t = ln 2 the branch -x/max(p, 0) = -x/0 is taken
    with pytest.warns(RuntimeWarning, match="stopped early"):
        res = ac.simulate(compiled, 2.0, t_eval=T)
    assert not res.success
    assert "der(x)" in res.message and "not finite" in res.message
    stopped = float(re.search(r"at t=([0-9.eE+-]+)", res.message).group(1))
    assert stopped == pytest.approx(np.log(2.0), rel=1e-6)
    # p = 2 with the same compiled model: x = exp(-t), then 0.5 exp(-(t - ln 2)/2)
    res = ac.simulate(compiled, 2.0, t_eval=T, rtol=1e-9, parameters={"p": 2.0})
    assert res.success
    t1 = np.log(2.0)
    expected = np.where(T < t1, np.exp(-T), 0.5 * np.exp(-(T - t1) / 2.0))
    assert np.max(np.abs(res["x"] - expected)) < 1e-6


class ClippedSource(ac.Component):
    """der(x) = 1/max(p, 0) while x < 0.5, else -x: the undefined value is the whole
    right-hand side, not a coefficient of x (the iteration matrix stays finite)."""

    p = ac.Parameter(-1.0)
    x = ac.Variable(start=1.0, fixed=True)

    def equations(self):
        return [ac.Eq(ac.der(self.x), ac.if_else(self.x < 0.5, 1 / ac.max(self.p, 0), -self.x))]


@pytest.mark.parametrize("backend", BACKENDS)
def test_undefined_right_hand_side_is_named(backend):
    with pytest.warns(RuntimeWarning, match="stopped early"):
        res = ac.simulate(ClippedSource(), 2.0, t_eval=T, backend=backend)
    assert not res.success
    assert "residuals of equations ['der(x)" in res.message and "not finite" in res.message
    stopped = float(re.search(r"at t=([0-9.eE+-]+)", res.message).group(1))
    assert stopped == pytest.approx(np.log(2.0), rel=1e-6)
