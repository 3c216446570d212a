"""Boolean and Integer variables: discrete by nature, evaluated at events, Modelica's event
iteration; each case against a closed form."""
import math

import numpy as np
import pytest
import sympy as sp

import acausal as ac
from acausal.ports import BooleanInput, BooleanOutput, IntegerOutput, RealInput, RealOutput


class BooleanStep(ac.Component):
    y = BooleanOutput()
    startTime = ac.Parameter(0.5, unit="s")

    def equations(self):
        return [ac.Eq(self.y, ac.time >= self.startTime)]


class Gate(ac.Component):
    u = BooleanInput()
    x = ac.Variable(start=0.0, fixed=True)

    def equations(self):
        return [ac.Eq(ac.der(self.x), ac.if_else(self.u, 1.0, 0.0))]


class StepIntoIntegrator(ac.Component):
    step = BooleanStep()
    gate = Gate()

    def equations(self):
        return [ac.connect(self.step.y, self.gate.u)]


def test_a_boolean_step_switches_an_integrator_at_its_exact_time():
    t = np.linspace(0.0, 1.0, 11)
    res = ac.simulate(StepIntoIntegrator(), t_end=1.0, t_eval=t, rtol=1e-9)
    assert res["step.y"].dtype == bool and res["gate.u"].dtype == bool
    assert list(res["step.y"]) == list(t >= 0.5)
    assert np.max(np.abs(res["gate.x"] - np.maximum(0.0, t - 0.5))) < 1e-9
    assert [float(e) for e in res.events] == [0.5]


class Thermostat(ac.Component):
    """der(T) = P on - k (T - Ta), on = Hysteresis(T: below Tlow on, above Thigh off):
    between switches T relaxes exponentially, so each switching time is a closed form."""

    T = ac.Variable(start=20.0, fixed=True)
    on = ac.Variable(type=bool, start=True)
    P = ac.Parameter(4.0)
    k = ac.Parameter(0.1)
    Ta = ac.Parameter(10.0)
    Tlow = ac.Parameter(20.0)
    Thigh = ac.Parameter(25.0)

    def equations(self):
        was = ac.pre(self.on)
        return [ac.Eq(ac.der(self.T), ac.if_else(self.on, self.P, 0.0) - self.k * (self.T - self.Ta)),
                ac.Eq(self.on, (was & (self.T < self.Thigh)) | (~was & (self.T <= self.Tlow)))]


def test_a_thermostat_switches_where_the_exponentials_reach_its_thresholds():
    P, k, Ta, lo, hi = 4.0, 0.1, 10.0, 20.0, 25.0
    heat_end = Ta + P / k                      # heating: T -> 50, from 20 to 25
    t_on = math.log((lo - heat_end) / (hi - heat_end)) / k
    t_off = math.log((hi - Ta) / (lo - Ta)) / k     # cooling: 25 -> 20
    res = ac.simulate(Thermostat(), t_end=2 * (t_on + t_off) + 1.0, rtol=1e-10)
    # the instants where on switches (a relation that sits at its threshold when the
    # heating stops crosses back just after: a second event at the same time)
    times = np.unique([float(e) for e in res.events
                       if any(c[0] == "on" for c in e.changes)])
    expected = np.array([t_on, t_on + t_off, 2 * t_on + t_off, 2 * (t_on + t_off)])
    assert times.shape == expected.shape
    assert np.max(np.abs(times - expected)) < 1e-6 * expected[-1]
    assert res["on"].dtype == bool
    assert res["on"][0] and not res["on"][np.searchsorted(res.t, t_on + 0.5 * t_off)]


class Counter(ac.Component):
    """Counts the rising edges of a Boolean that says whether sin(w t) > 1/2."""

    high = ac.Variable(type=bool)
    n = ac.Variable(type=int, start=0)
    w = ac.Parameter(2.0, unit="rad/s")

    def equations(self):
        return [ac.Eq(self.high, ac.sin(self.w * ac.time) > 0.5),
                ac.when(ac.edge(self.high), ac.assign(self.n, ac.pre(self.n) + 1))]


class HeldCounter(ac.Component):
    counter = Counter()
    x = ac.Variable(start=0.0, fixed=True)

    def equations(self):
        return [ac.Eq(ac.der(self.x), 1.0)]


def test_an_integer_counts_rising_edges_located_as_state_events():
    res = ac.simulate(HeldCounter(), t_end=10.0, t_eval=np.linspace(0, 10, 201), rtol=1e-9)
    n = res["counter.n"]
    assert n.dtype == np.int64
    # rising edges of sin(2 t) > 1/2 at 2 t = pi/6 + 2 pi j
    rises = (np.pi / 6 + 2 * np.pi * np.arange(10)) / 2
    expected = np.searchsorted(rises, res.t, side="right")
    assert list(n) == list(expected)


class Rounder(ac.Component):
    """RealToInteger's rounding, halves away from zero, of 3 sin(t) (no states)."""

    y = IntegerOutput()

    def equations(self):
        u = 3 * ac.sin(ac.time)
        return [ac.Eq(self.y, ac.if_else(u > 0, ac.integer(u + 0.5), -ac.integer(0.5 - u)))]


def test_integer_rounding_without_states_locates_its_crossings():
    t = np.linspace(0.0, 10.0, 1001)
    res = ac.simulate(Rounder(), t_end=10.0, t_eval=t, check_units="off")
    u = 3 * np.sin(t)
    exact = np.where(u > 0, np.floor(u + 0.5), np.ceil(u - 0.5)).astype(np.int64)
    # the points within 1e-9 of a switching time may fall either side of it
    near = np.abs(np.abs(u) - (np.floor(np.abs(u)) + 0.5)) < 1e-8
    assert np.array_equal(res["y"][~near], exact[~near])
    # y switches where 3 sin(t) crosses +-0.5, +-1.5, +-2.5: at t = asin(h/3) + 2 pi j
    # and pi - asin(h/3) + 2 pi j, each located as an event
    roots = []
    for h in np.arange(-2.5, 3.0, 1.0):
        a = math.asin(h / 3)
        for base in (a, math.pi - a):
            roots += [base + 2 * math.pi * j for j in range(-1, 3)]
    roots = np.sort([r for r in roots if 0 < r < 10.0])
    switched = np.unique([float(e) for e in res.events
                          if any(c[0] == "y.signal" for c in e.changes)])
    assert switched.shape == roots.shape
    assert np.max(np.abs(switched - roots)) < 1e-9


class Toggle(ac.Component):
    y = ac.Variable(type=bool)
    x = ac.Variable(start=0.0, fixed=True)

    def equations(self):
        return [ac.Eq(self.y, ~ac.pre(self.y) & (ac.time > 0.5)),
                ac.Eq(ac.der(self.x), 1.0)]


def test_a_boolean_that_reads_its_own_pre_and_never_settles_is_named():
    with pytest.raises(ac.SimulationError, match=r"y: (True|False) -> (True|False)"):
        ac.simulate(Toggle(), t_end=1.0, raise_on_failure=True)


class Latch(ac.Component):
    """set at 0.3, reset at 0.6: an RS latch written with pre, event iteration settles it
    in two rounds at each instant."""

    q = ac.Variable(type=bool)
    s = ac.Variable(type=bool)
    r = ac.Variable(type=bool)
    x = ac.Variable(start=0.0, fixed=True)

    def equations(self):
        t = ac.time
        return [ac.Eq(self.s, (t >= 0.3) & (t < 0.4)),
                ac.Eq(self.r, t >= 0.6),
                ac.Eq(self.q, (self.s | ac.pre(self.q)) & ~self.r),
                ac.Eq(ac.der(self.x), ac.if_else(self.q, 1.0, 0.0))]


def test_a_latch_holds_through_the_end_of_its_set_pulse():
    t = np.array([0.1, 0.35, 0.45, 0.55, 0.65, 0.9])
    res = ac.simulate(Latch(), t_end=1.0, t_eval=t, rtol=1e-9)
    assert list(res["q"]) == [False, True, True, True, False, False]
    assert abs(res["x"][-1] - 0.3) < 1e-9


class SampleTriggered(ac.Component):
    tick = ac.Variable(type=bool)
    count = ac.Variable(type=int)

    def equations(self):
        return [ac.Eq(self.tick, ac.sample(0.0, 0.25)),
                ac.when(self.tick, ac.assign(self.count, ac.pre(self.count) + 1))]


def test_sample_as_a_value_is_true_only_at_its_ticks():
    t = np.array([0.1, 0.3, 0.6, 0.9])
    res = ac.simulate(SampleTriggered(), t_end=1.0, t_eval=t)
    assert not res["tick"].any()
    # ticks at 0, 0.25, 0.5, 0.75: the one at t0 fires once the initial values are found
    assert list(res["count"]) == [1, 2, 3, 4]


# -- the language's checks -------------------------------------------------------------------
class RealFromCondition(ac.Component):
    x = ac.Variable()

    def equations(self):
        return [ac.Eq(self.x, ac.time > 1)]


class Mixed(ac.Component):
    src = BooleanStep()
    sink = Gate()
    real = RealOutput()
    inp = RealInput()

    def equations(self):
        return [ac.connect(self.src.y, self.inp)]


class ConditionOnReal(ac.Component):
    x = ac.Variable()

    def equations(self):
        return [ac.Eq(self.x, ac.if_else(self.x, 1, 0))]


def test_a_condition_given_to_a_real_variable_is_refused():
    with pytest.raises(ac.InvalidEquation, match="x is a Real variable"):
        ac.compile(RealFromCondition())


def test_a_boolean_output_does_not_connect_to_a_real_input():
    with pytest.raises(ac.InvalidConnection, match="different types"):
        ac.compile(Mixed())


def test_a_real_variable_is_not_a_condition():
    with pytest.raises(ac.InvalidEquation, match=r"x is a Real variable; compare it"):
        ac.compile(ConditionOnReal())


def test_values_of_the_wrong_type_are_refused_where_they_are_given():
    with pytest.raises(ac.InvalidValue, match="not an Integer"):
        class Bad(ac.Component):
            n = ac.Parameter(2.5, type=int)
    with pytest.raises(ac.InvalidValue, match="not a Boolean"):
        Thermostat(on={"start": 1})
    with pytest.raises(ac.InvalidValue, match="no nominal"):
        class Bad2(ac.Component):
            b = ac.Variable(type=bool, nominal=2.0)
    with pytest.raises(ac.InvalidValue, match="is a bool, not a real number"):
        Thermostat(P=True)


class _NonZeroCount(ac.Component):
    """b = (n <> 0) of an Integer parameter n; x' = 1 while b, else 0."""

    n = ac.Parameter(-1, type=int)
    b = ac.Variable(type=bool)
    x = ac.Variable(start=0.0, fixed=True)

    def equations(self):
        return [ac.Eq(self.b, sp.Ne(self.n, 0)),
                ac.Eq(ac.der(self.x), ac.if_else(self.b, 1.0, 0.0))]


def test_an_equality_of_parameters_alone_is_a_value_not_an_event():
    # (the MSL writes nperiod <> 0 in its digital pulse): x(1) = 1 while n <> 0, and 0
    # once n is tuned to 0
    compiled = ac.compile(_NonZeroCount())
    res = ac.simulate(compiled, 1.0, rtol=1e-9)
    assert res["b"].all() and abs(res["x"][-1] - 1.0) <= 1e-9
    res = ac.simulate(compiled, 1.0, rtol=1e-9, parameters={"n": 0})
    assert not res["b"].any() and res["x"][-1] == 0.0
