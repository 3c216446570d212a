"""Bad input to ``simulate`` and to a compiled model: a typed error in the user's names,
nothing dropped silently (the model-building side is in test_bad_input.py).

Each case names what is wrong: the argument, the parameter, or the equation whose
evaluation fails at the start values.
"""
import math
import re

import numpy as np
import pytest
import sympy as sp

import acausal as ac

from .test_bad_input import RC      # 1 V charging C1 = 10 mF through R1 = 1 Ohm
from acausal.errors import InvalidValue, NotInModel



class Decay(ac.Component):
    """x' = -k x with k >= 0 declared."""

    k = ac.Parameter(1.0, min=0.0)
    x = ac.Variable(start=1.0)

    def equations(self):
        return [ac.Eq(ac.der(self.x), -self.k * self.x)]


class SqrtOfStart(ac.Component):
    """x' = -sqrt(x) started at x = -1: outside sqrt's domain at t = 0."""

    x = ac.Variable(start=-1.0)

    def equations(self):
        return [ac.Eq(ac.der(self.x), -sp.sqrt(self.x))]


def _raises(exc, text):
    return pytest.raises(exc, match=re.escape(text))


@pytest.mark.parametrize("kwargs, text", [
    (dict(n_points=0), "n_points must be an integer >= 2, got 0"),
    (dict(t_eval=[0.0, 2.0]), "t_eval has 1 time(s) outside [t_start, t_end]"),
    (dict(t_eval=[0.0, 0.06, 0.03]), "t_eval must be sorted"),
    (dict(t_eval=[0.0, math.nan, 0.1]), "t_eval has non-finite entries at positions [1]"),
    (dict(rtol=-1.0), "rtol is a relative error and must be in (0, 1), e.g. 1e-6; got -1.0"),
    (dict(rtol=1), "rtol is a relative error and must be in (0, 1), e.g. 1e-6; got 1"),
    (dict(rtol=5.0), "must be in (0, 1), e.g. 1e-6; got 5.0"),
    (dict(rtol=True), "rtol must be a number, got True"),
    (dict(atol=0.0), "atol must be > 0 and finite, got 0.0"),
    (dict(atol=-1e-8), "atol must be > 0 and finite, got -1e-08"),
    (dict(atol={"C1.vv": 1e-9}), "atol['C1.vv']: the model has no variable 'C1.vv' "
                                 "(did you mean 'C1.v'?)"),
    (dict(atol={"C1.v": 0.0}), "atol['C1.v'] must be > 0 and finite, got 0.0"),
    (dict(max_step=0.0), "max_step must be > 0, got 0.0"),
    (dict(max_order=6), "max_order must be an integer from 1 to 5, got 6"),
    (dict(n_points=1.5), "n_points must be an integer >= 2, got 1.5"),
    (dict(t_start=0.2), "t_end = 0.1 must be after t_start = 0.2"),
    (dict(t_start=math.inf), "t_start must be finite, got inf"),
    (dict(nonfinite="ignore"), "nonfinite must be one of 'stop', 'warn', got 'ignore'"),
    (dict(parameters=[("R1.R", 2.0)]), "parameters must be a dict {name: value}, got list"),
], ids=["n_points=0", "t_eval outside", "t_eval unsorted", "t_eval NaN", "rtol<0",
        "rtol=1", "rtol=5", "rtol=True", "atol=0", "atol<0", "atol unknown name",
        "atol=0 by name", "max_step=0", "max_order=6", "n_points=1.5", "t_end<t_start",
        "t_start=inf", "nonfinite", "parameters list"])
def test_bad_simulate_arguments_are_refused_by_name(kwargs, text):
    with _raises(ac.InvalidArgument, text):
        ac.simulate(RC(), t_end=0.1, **kwargs)


def test_an_absolute_tolerance_per_unknown():
    # C1.v = 1 - exp(-t / (R C)), R C = 10 ms: a tight atol on it alone holds it there
    compiled = ac.compile(RC())
    assert "C1.v" in compiled.names
    res = ac.simulate(compiled, t_end=0.05, rtol=1e-3, atol={"C1.v": 1e-10})
    loose = ac.simulate(compiled, t_end=0.05, rtol=1e-3)
    exact = 1.0 - np.exp(-res.t / 0.01)
    assert np.max(np.abs(res["C1.v"] - exact)) < 1e-3
    assert res.stats["steps"] >= loose.stats["steps"]
    others = [n for n in compiled.outputs if n not in compiled.names and n != "C1.v"]
    with _raises(ac.InvalidArgument, f"atol['{others[0]}']: {others[0]} is computed from "
                                     "the unknowns the integrator controls"):
        ac.simulate(compiled, t_end=0.05, atol={others[0]: 1e-9})


@pytest.mark.parametrize("value, exc, text", [
    ("abc", InvalidValue, "parameter 'R1.R' must be a real number, got 'abc' (str)"),
    (math.nan, InvalidValue, "parameter 'R1.R' must be finite, got nan"),
    (True, InvalidValue, "parameter 'R1.R' must be a real number, got True (bool)"),
])
def test_bad_parameter_values_at_run_time(value, exc, text):
    with _raises(exc, text):
        ac.simulate(RC(), t_end=0.1, parameters={"R1.R": value})


def test_unknown_parameter_names_the_ones_that_exist():
    with _raises(NotInModel, "no tunable parameter 'R9.R' (did you mean 'R1.R'?); "
                             "parameters named R: R1.R"):
        ac.simulate(RC(), t_end=0.1, parameters={"R9.R": 1.0})


def test_parameter_outside_its_declared_range_at_run_time():
    with _raises(InvalidValue, "parameter 'k' = -1.0 is outside its range [0.0, inf]"):
        ac.simulate(Decay(), t_end=1.0, parameters={"k": -1.0})
    res = ac.simulate(Decay(), t_end=1.0, rtol=1e-8, parameters={"k": 2.0})
    assert res.success
    assert abs(res["x"][-1] - np.exp(-2.0)) < 1e-6 * np.exp(-2.0)


class Wrapped(ac.Component):
    """A parameter of the model bound into a bounded one of its part (Resistor R >= 0)."""

    R = ac.Parameter(1.0)
    inner = Decay(k=ac.ref("R"))


def test_tuning_respects_the_bounds_of_the_parameters_bound_to_it():
    """As compiling Wrapped(R=-1) refuses inner.k = -1 (min 0), so does tuning R to -1
    after compilation, and it changes nothing; a valid value still decays as exp(-R t)."""
    with pytest.raises(InvalidValue, match=r"'inner' \(Decay\): parameter k"):
        ac.compile(Wrapped(R=-1.0), cache=False)
    compiled = ac.compile(Wrapped(), cache=False)
    with pytest.raises(InvalidValue, match=r"inner\.k.*outside its range"):
        compiled.set_parameters({"R": -1.0})
    assert compiled.p[compiled.param_names.index("R")] == 1.0
    res = ac.simulate(compiled, t_end=1.0, rtol=1e-9, parameters={"R": 2.0})
    assert abs(res["inner.x"][-1] - math.exp(-2.0)) <= 1e-6 * math.exp(-2.0)


class WrappedBounded(ac.Component):
    """A bounded parameter bound into a part's parameter of a wider range (k >= 0)."""

    R = ac.Parameter(1.0, min=0.5)
    inner = Decay(k=ac.ref("R"))


def test_a_copy_of_a_parameter_within_the_bounds_is_checked_by_its_own():
    """inner.k = R with R >= 0.5 and k >= 0: every R that passes its own range gives a
    valid k, so the compile keeps no check of k for tuning (meta "derived_bounds"), and
    tuning R still refuses what its range refuses and runs what it accepts."""
    compiled = ac.compile(WrappedBounded(), cache=False)
    assert compiled.meta["derived_bounds"] == []
    assert [n for n, *_ in ac.compile(Wrapped(), cache=False).meta["derived_bounds"]] \
        == ["inner.k"]
    with pytest.raises(InvalidValue, match=r"parameter 'R' = -1.0 is outside its range"):
        compiled.set_parameters({"R": -1.0})
    res = ac.simulate(compiled, t_end=1.0, rtol=1e-9, parameters={"R": 2.0})
    assert abs(res["inner.x"][-1] - math.exp(-2.0)) <= 1e-6 * math.exp(-2.0)


def test_a_start_value_outside_a_functions_domain_names_the_equation():
    with pytest.raises(ac.InitializationFailed) as err:
        ac.simulate(SqrtOfStart(), t_end=1.0)
    msg = str(err.value)
    assert "der(x)" in msg and "math domain error" in msg and "t = 0" in msg


class EmptyingTank(ac.Component):
    """der(h) = -sqrt(h) - 0.1 from h = 1: empty at t = 2 (1 - 0.1 ln 11), where the
    equation stops having a real solution (u = sqrt(h): 2u u' = -(u + 0.1))."""

    h = ac.Variable(start=1.0, fixed=True)

    def equations(self):
        return [ac.Eq(ac.der(self.h), -ac.sqrt(self.h) - 0.1)]


@pytest.mark.parametrize("rtol", [1e-6, 1e-8])
def test_a_derivative_that_becomes_infinite_is_not_called_structural(rtol):
    """The run stops where the tank is empty, names h, and (whether the step size or the
    iteration matrix gives out first) does not blame the model's structure."""
    with pytest.warns(RuntimeWarning, match="stopped early"):
        res = ac.simulate(EmptyingTank(), t_end=5.0, rtol=rtol)
    assert not res.success
    assert abs(res.t[-1] - 2 * (1 - 0.1 * math.log(11))) < 1e-3
    assert "['h']" in res.message and "higher-index" not in res.message
    assert "non-finite" in res.message or "step size too small" in res.message
