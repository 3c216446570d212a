"""Modifications are checked where the instance is made: a typed error in the user's
names at the line that wrote the modification, with a suggestion for a misspelt name."""
import fractions
import re

import numpy as np
import pytest

import acausal as ac
from acausal.compiler.frontend.flatten import flatten
from acausal.library.electrical import Capacitor, ConstantVoltage, Ground, Resistor


class RC(ac.Component):
    src = ConstantVoltage(V=1.0)
    R1 = Resistor(R=1.0)
    C1 = Capacitor(C=1.0)
    gnd = Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.R1.p), ac.connect(self.R1.n, self.C1.p),
                ac.connect(self.C1.n, self.src.n, self.gnd.p)]


def _raises(exc, text):
    return pytest.raises(exc, match=re.escape(text))


def test_unknown_name_suggests_the_declared_one_at_the_line_that_wrote_it():
    with pytest.raises(ac.NotInModel, match=re.escape(
            "Resistor has no parameter, variable or sub-component named 'r' (did you "
            "mean 'R'?) (it has: R, T_ref, alpha, i, n, p, v)")) as err:
        Resistor(r=5)
    # the error comes from the construction in this test, not from a later compile
    assert "Resistor(r=5)" in str(err.traceback[0].statement)


def test_unknown_name_several_levels_down_names_the_path():
    with _raises(ac.NotInModel, "'R1' (Resistor) has no parameter, variable or "
                                "sub-component named 'RR' (did you mean 'R'?)"):
        RC(R1={"RR": 5.0})
    with _raises(ac.NotInModel, "RC has no parameter, variable or sub-component named "
                                "'R2' (did you mean 'R1'?)"):
        RC(R2={"R": 5.0})


@pytest.mark.parametrize("mods, exc, text", [
    (dict(R=[1, 2]), ac.InvalidValue, "Resistor: parameter R = [1, 2] is not a real number"),
    (dict(R=float("nan")), ac.InvalidValue, "Resistor: parameter R = nan is not a number (NaN)"),
    (dict(T_ref=-1.0), ac.InvalidValue,
     "Resistor: parameter T_ref = -1.0 is below its minimum 0"),
    (dict(R=True), ac.InvalidValue, "Resistor: parameter R = True is a bool"),
    (dict(v="high"), ac.InvalidValue, "Resistor: variable 'v': a modification of a "
                                      "variable is a number (its start value) or a dict"),
    (dict(v=[1.0]), ac.InvalidValue, "Resistor: variable 'v': a modification of a "
                                     "variable is a number (its start value)"),
    (dict(v={"strat": 1.0}), ac.InvalidValue, "Resistor: variable 'v' has no attribute "
                                              "'strat' (did you mean 'start'?)"),
    (dict(v={"start": float("nan")}), ac.InvalidValue, "Resistor: variable 'v': start = "
                                                       "nan is not a number (NaN)"),
    (dict(v={"fixed": "yes"}), ac.InvalidValue, "fixed = 'yes' must be True or False"),
])
def test_bad_values_fail_at_instantiation(mods, exc, text):
    with _raises(exc, text):
        Resistor(**mods)


def test_sub_component_modification_must_be_a_dict():
    with _raises(ac.InvalidValue, "RC: modification of sub-component 'R1' must be a dict "
                                  "of its parameters, got 5.0"):
        RC(R1=5.0)


def test_nested_value_outside_its_bounds_names_the_path():
    with _raises(ac.InvalidValue, "'C1' (Capacitor): parameter C = -1.0 is below its "
                                  "minimum 0"):
        RC(C1={"C": -1.0})


@pytest.mark.parametrize("value", [2.0, 2, np.float64(2.0), np.int32(2),
                                   fractions.Fraction(4, 2), "2 Ohm", "0.002 kOhm"])
def test_good_values_of_every_kind_are_taken_as_written(value):
    flat = flatten(RC(R1={"R": value}))
    R = next(p for p in flat.parameters if p.name == "R1.R")
    assert float(R.value) == pytest.approx(2.0, rel=1e-15)


def test_a_value_with_a_unit_gives_the_analytic_rc():
    """v_C = 1 - exp(-t/(R C)) with R = 0.002 kOhm = 2 Ohm."""
    t = np.linspace(0, 4, 9)
    res = ac.simulate(RC(R1={"R": "0.002 kOhm"}, C1={"v": {"start": 0.0, "fixed": True}}),
                      t_end=4.0, t_eval=t, rtol=1e-10, atol=1e-12)
    assert np.max(np.abs(res["C1.v"] - (1 - np.exp(-t / 2.0)))) < 1e-7


def test_start_values_given_with_units_are_converted():
    from acausal.library import rotational as rot
    inertia = rot.Inertia(J=1.0, w={"start": "60 rpm", "fixed": True}, phi="90 deg")
    flat = flatten(inertia)
    w, phi = flat.variable("w"), flat.variable("phi")
    assert w.attrs.start == pytest.approx(2 * np.pi, rel=1e-14)
    assert phi.attrs.start == pytest.approx(np.pi / 2, rel=1e-14)
    with _raises(ac.InvalidValue, "Inertia: variable 'w': start = '3 m' has dimension m, "
                                  "but w is declared in 'rad/s'"):
        rot.Inertia(w="3 m")
