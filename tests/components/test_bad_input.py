"""Bad input to the modelling language: a typed error in the user's names, never a
traceback from sympy or the generated code, and nothing dropped silently.

Each test gives one bad input and asserts the exception class and that the message
names the culprit (component path, parameter or variable, equation text).  The last
tests check that legitimate values of every numeric type, bindings and infinite limits
still work, against the closed-form RC step response.
"""
import decimal
import fractions
import math
import re

import numpy as np
import pytest
import sympy as sp

import acausal as ac
from acausal.compiler.frontend.flatten import flatten
from acausal.components import (InvalidConnection, InvalidEquation, InvalidHierarchy,
                                InvalidValue, NotInModel)
from acausal.library.blocks import PI
from acausal.library.electrical import Capacitor, ConstantVoltage, Ground, Resistor
from acausal.library.electromechanical import DCMotor


class RC(ac.Component):
    """A 1 V source charging C1 = 10 mF through R1: v_C = 1 - exp(-t / (R C))."""

    src = ConstantVoltage(V=1.0)
    R1 = Resistor()
    C1 = Capacitor(C=1e-2)
    gnd = Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.R1.p), ac.connect(self.R1.n, self.C1.p),
                ac.connect(self.C1.n, self.src.n, self.gnd.p)]


class Board(ac.Component):
    left = RC()
    right = RC()


def _raises(exc, text):
    """pytest.raises matching ``text`` literally."""
    return pytest.raises(exc, match=re.escape(text))


# -- parameter values ------------------------------------------------------------------
@pytest.mark.parametrize("value, why", [
    ([1, 2], "parameter R = [1, 2] is not a real number (it is a list)"),
    ("ten", "parameter R = 'ten' is not a real number (it is a str)"),
    (1j, "parameter R = 1j is not a real number (it is a complex)"),
    (float("nan"), "parameter R = nan is not a number (NaN)"),
    (True, "parameter R = True is a bool, not a real number"),
    (np.bool_(False), "parameter R = np.False_ is a bool, not a real number"),
    (sp.I, "parameter R = I is not a real number"),
])
def test_parameter_value_that_is_not_a_real_number(value, why):
    with _raises(InvalidValue, f"'R1' (Resistor): {why}"):
        flatten(RC(R1={"R": value}))


def test_parameter_value_in_a_class_level_declaration_fails_where_it_is_written():
    with _raises(InvalidValue, "Resistor: parameter R = 'ten' is not a real number"):
        class Direct(RC):
            R1 = Resistor(R="ten")


def test_parameter_value_several_levels_down_names_the_full_path():
    with _raises(InvalidValue, "'left.R1' (Resistor): parameter R = 'ten'"):
        flatten(Board(left={"R1": {"R": "ten"}}))


def test_infinite_parameter_that_makes_an_equation_infinite():
    with _raises(InvalidValue, "'R1' (Resistor): parameter R = inf makes the equation "
                               "'R1.v = R1.R*R1.i' in R1 (Resistor) infinite"):
        flatten(RC(R1={"R": float("inf")}))


def test_structural_zero_that_divides_names_the_parameter_and_the_equation():
    class Lag(ac.Component):
        T = ac.Parameter(1.0, unit="s")
        x = ac.Variable(start=1.0, fixed=True)

        def equations(self):
            return [ac.Eq(ac.der(self.x), -self.x / self.T)]

    with _raises(InvalidValue, "parameter T = 0 makes the equation 'der(x) = -x/T' in "
                               "(model) (Lag) divide by zero"):
        flatten(Lag(T=0))


def test_parameter_below_its_minimum():
    with _raises(InvalidValue, "'C1' (Capacitor): parameter C = -1 is below its minimum 0"):
        flatten(RC(C1={"C": -1}))


def test_parameter_above_its_maximum():
    class Valve(ac.Component):
        opening = ac.Parameter(0.5, min=0, max=1)
        q = ac.Variable()

        def equations(self):
            return [ac.Eq(self.q, self.opening)]

    class Plant(ac.Component):
        valve = Valve()

    with _raises(InvalidValue, "Valve: parameter opening = 1.5 is above its maximum 1"):
        Valve(opening=1.5)
    with _raises(InvalidValue, "'valve' (Valve): parameter opening = 1.5 is above its "
                               "maximum 1"):
        Plant(valve={"opening": 1.5})


def test_bound_parameter_outside_its_bounds_is_evaluated_and_named():
    class Holder(ac.Component):
        Cp = ac.Parameter(-2.0)
        C1 = Capacitor(C=ac.ref("Cp"))

    with _raises(InvalidValue, "'C1' (Capacitor): parameter C = Cp (= -2.0) is below its "
                               "minimum 0"):
        flatten(Holder())


def test_parameter_function_that_raises():
    class C(ac.Component):
        k = ac.Parameter(lambda c: c.missing)
        x = ac.Variable(start=1.0)

        def equations(self):
            return [ac.Eq(ac.der(self.x), -self.k * self.x)]

    with _raises(InvalidValue, "the model (C): evaluating parameter k raised AttributeError"):
        flatten(C())


def test_parameter_function_that_returns_a_string():
    class C(ac.Component):
        k = ac.Parameter(lambda c: "two")
        x = ac.Variable(start=1.0)

        def equations(self):
            return [ac.Eq(ac.der(self.x), -self.k * self.x)]

    with _raises(InvalidValue, "the model (C): parameter k = 'two' is not a real number"):
        flatten(C())


def test_parameter_bound_to_a_variable():
    class C(ac.Component):
        x = ac.Variable(start=1.0)
        k = ac.Parameter(lambda c: c.x)

        def equations(self):
            return [ac.Eq(ac.der(self.x), -self.k * self.x)]

    with _raises(InvalidValue, "the model (C): parameter k = x depends on the variable(s) x"):
        flatten(C())


def test_parameter_bound_to_time():
    with _raises(InvalidValue, "'R1' (Resistor): parameter R = time depends on time"):
        flatten(RC(R1={"R": ac.time}))


@pytest.mark.parametrize("bindings, cycle", [
    ({"a": lambda c: c.b, "b": lambda c: c.a}, "parameters a -> b -> a"),
    ({"a": lambda c: c.a + 1, "b": lambda c: 1.0}, "parameters a -> a"),
])
def test_parameter_bindings_that_depend_on_themselves(bindings, cycle):
    class C(ac.Component):
        a = ac.Parameter(1.0)
        b = ac.Parameter(1.0)
        x = ac.Variable(start=1.0)

        def equations(self):
            return [ac.Eq(ac.der(self.x), -self.a * self.b * self.x)]

    with _raises(InvalidValue, f"{cycle} are defined in terms of each other"):
        flatten(C(**bindings))


def test_ref_to_a_name_the_parent_lacks():
    class Holder(ac.Component):
        R1 = Resistor(R=ac.ref("R_missing"))

    with _raises(InvalidValue, "'R1' (Resistor): parameter 'R' refers to 'R_missing' of the "
                               "enclosing component, the model (Holder), which has no "
                               "parameter of that name"):
        flatten(Holder())


def test_ref_to_a_variable_of_the_parent():
    class Holder(ac.Component):
        v = ac.Variable()
        R1 = Resistor(R=ac.ref("v"))

    with _raises(InvalidValue, "refers to 'v' of the enclosing component, the model "
                               "(Holder), which is a variable, not a parameter"):
        flatten(Holder())


def test_ref_on_the_model_itself():
    with _raises(InvalidValue, "the model (Resistor): parameter R = ref('R0')"):
        flatten(Resistor(R=ac.ref("R0")))


def test_ref_that_is_not_a_name():
    with _raises(InvalidValue, "ref() takes the name of a parameter of the enclosing "
                               "component, not 3"):
        ac.ref(3)


def test_parameter_expression_of_a_symbol_outside_the_model():
    with _raises(NotInModel, "'R1' (Resistor): parameter R = 2*Rx uses 'Rx'"):
        flatten(RC(R1={"R": 2 * sp.Symbol("Rx")}))


def test_assigning_a_declared_parameter_in_init():
    class Fixed10(Resistor):
        def __init__(self, **mods):
            super().__init__(**mods)
            self.R = 10.0

    with _raises(InvalidValue, "Fixed10.R is a declared parameter; set it by modification"):
        Fixed10()


@pytest.mark.parametrize("declaration, why", [
    (dict(value="ten"), "C.k: default value = 'ten' is not a real number"),
    (dict(value=1.0, min=2, max=1), "C.k: min = 2 is greater than max = 1"),
    (dict(value=-1.0, min=0), "C.k: default value -1.0 is below its minimum 0"),
    (dict(value=1.0, unit=3), "C.k: unit = 3 must be a string"),
])
def test_bad_parameter_declaration_fails_when_the_class_is_made(declaration, why):
    with _raises(InvalidValue, why):
        class C(ac.Component):
            k = ac.Parameter(**declaration)


# -- variable attributes ---------------------------------------------------------------
@pytest.mark.parametrize("mod, why", [
    ({"start": "abc"}, "start = 'abc' is not a real number (it is a str)"),
    ({"start": [1.0]}, "start = [1.0] is not a real number (it is a list)"),
    ({"start": float("nan")}, "start = nan is not a number (NaN)"),
    ({"start": float("inf")}, "start = inf is not finite"),
    ({"start": True}, "start = True is a bool, not a real number"),
    ({"nominal": 0}, "nominal = 0 must be positive"),
    ({"nominal": -1.0}, "nominal = -1.0 must be positive"),
    ({"min": 2, "max": 1}, "min = 2 is greater than max = 1"),
    ({"start": 5.0, "min": 0, "max": 1}, "start = 5.0 lies outside [min, max] = [0, 1]"),
    ({"fixed": "yes"}, "fixed = 'yes' must be True or False"),
    ({"fixed": 1}, "fixed = 1 must be True or False"),
    ({"unit": 3}, "unit = 3 must be a string"),
    ({"state_select": "sometimes"}, "state_select must be one of"),
    ("1", "a modification of a variable is a number (its start value) or a dict of its "
          "attributes, not '1'"),
])
def test_bad_variable_attribute_names_component_and_variable(mod, why):
    with _raises(InvalidValue, f"'C1' (Capacitor): variable 'v': {why}"):
        flatten(RC(C1={"v": mod}))


def test_bad_variable_declaration_fails_when_the_class_is_made():
    with _raises(InvalidValue, "C.x: start = 'abc' is not a real number"):
        class C(ac.Component):
            x = ac.Variable(start="abc")


# -- equations -------------------------------------------------------------------------
def test_equation_on_a_component_that_is_not_part_of_the_model():
    stray = Resistor()

    class C(RC):
        def equations(self):
            return [ac.Eq(stray.v, 1.0)]

    with _raises(NotInModel, "in the model (C).equations(): Resistor.v: the model being "
                             "compiled (C) uses a Resistor that was never made part of it"):
        flatten(C())


def test_equation_on_a_variable_of_another_model_with_the_same_names():
    other = RC()
    flatten(other)           # other.R1.v is now named 'R1.v', as C's own R1.v

    class C(RC):
        def equations(self):
            return [ac.Eq(other.R1.v, 1.0)]

    with _raises(NotInModel, "uses 'R1.v' of a Resistor in another model instance"):
        flatten(C())


def test_equation_on_a_bare_sympy_symbol():
    class C(ac.Component):
        x = ac.Variable(start=1.0)

        def equations(self):
            return [ac.Eq(ac.der(self.x), -sp.Symbol("x"))]

    with _raises(NotInModel, "equation 'der(x) = -x' in (model) (C) uses 'x', which the "
                             "model being compiled does not declare"):
        flatten(C())


@pytest.mark.parametrize("returned, shown", [
    (["x = 1"], "returned 'x = 1'; expected ac.Eq(lhs, rhs)"),
    ([3], "returned 3; expected"),
    (lambda c: [sp.Eq(c.x, 1)], "returned Eq(b.x, 1) (a sympy relation or a truth value: "
                                "acausal's equation is ac.Eq(lhs, rhs))"),
    (None, "returned None; it must return a list of equations (is a 'return' missing?)"),
])
def test_equations_returning_something_that_is_not_an_equation(returned, shown):
    class B(ac.Component):
        x = ac.Variable()

        def equations(self):
            return returned(self) if callable(returned) else returned

    class Top(ac.Component):
        b = B()

    with _raises(InvalidEquation, f"'b' (B).equations() {shown}"):
        flatten(Top())


def test_initial_equations_returning_a_connection():
    class C(RC):
        def initial_equations(self):
            return [ac.connect(self.R1.p, self.C1.p)]

    with _raises(InvalidEquation, "the model (C).initial_equations() returned "
                                  "connect(R1.p, C1.p); expected ac.Eq(lhs, rhs)"):
        flatten(C())


def _model_with(extra):
    """A model with one variable x, der(x) = -x, and ``extra(self)`` added."""
    class M(ac.Component):
        k = ac.Parameter(2.0)
        x = ac.Variable(start=1.0)

        def equations(self):
            return [ac.Eq(ac.der(self.x), -self.x), *extra(self)]

    return M()


@pytest.mark.parametrize("extra, exc, why", [
    (lambda m: [ac.Eq(1, 1)], InvalidEquation,
     "ac.Eq(1, 1) holds whatever the variables are"),
    (lambda m: [ac.Eq(m.x, m.x)], InvalidEquation,
     "ac.Eq(x, x) holds whatever the variables are"),
    (lambda m: [ac.Eq(1, 2)], InvalidEquation, "ac.Eq(1, 2) can never hold"),
    (lambda m: [ac.Eq(m.x + 1, m.x)], InvalidEquation,
     "equation 'x + 1 = x' in (model) (M) involves no variable of the model"),
    (lambda m: [ac.Eq(m.k, 2)], InvalidEquation,
     "equation 'k = 2' in (model) (M) involves no variable of the model"),
    (lambda m: [ac.Eq(m.x, [1, 2])], InvalidEquation,
     "cannot use [1, 2] (a list) in an equation"),
    (lambda m: [ac.Eq(m.x, "x")], InvalidEquation, "cannot use 'x' (a str) in an equation"),
    (lambda m: [ac.Eq(m.x, m.x > 1)], InvalidEquation,
     "ac.Eq(x, x > 1): x > 1 is a relation or a logical value, not a value"),
    (lambda m: [ac.Eq(m.x, float("nan") * m.k)], InvalidEquation,
     "ac.Eq(x, nan) contains a value that is not a finite number"),
    (lambda m: [ac.Eq(m.x, 1, label=3)], InvalidEquation,
     "the label of ac.Eq(x, 1) must be a string, not 3"),
])
def test_equation_that_is_not_a_valid_equation(extra, exc, why):
    with _raises(exc, why):
        flatten(_model_with(extra))


def test_trivial_equation_message_names_the_component():
    with _raises(InvalidEquation, "in the model (M).equations(): ac.Eq(1, 1)"):
        flatten(_model_with(lambda m: [ac.Eq(1, 1)]))


@pytest.mark.parametrize("argument, what", [
    (lambda m: m.k, "der(k) is the derivative of a parameter"),
    (lambda m: 3, "der(3) is the derivative of a number"),
    (lambda m: 2 * m.k, "der(2*k) is the derivative of an expression of parameters"),
])
def test_der_of_a_constant(argument, what):
    class M(ac.Component):
        k = ac.Parameter(2.0)
        x = ac.Variable(start=1.0)

        def equations(self):
            return [ac.Eq(ac.der(self.x), -self.x + ac.der(argument(self)))]

    with _raises(InvalidEquation, what):
        flatten(M())


@pytest.mark.parametrize("event, why", [
    (lambda m: ac.when(m.x, ac.reinit(m.x, 1.0)),
     "when() takes a condition such as x > 0 (a relation), not x"),
    (lambda m: ac.Eq(m.k, ac.if_else(m.x, 1, 0)),
     "if_else() takes a condition such as x > 0 (a relation), not x"),
    (lambda m: ac.when(m.x < 0.5, ac.reinit(m.x, float("nan"))),
     "reinit(x, ...) takes a finite value, got nan"),
    (lambda m: ac.when(m.x < 0.5, ac.reinit(m.k * 2, 1.0)),
     "reinit() takes a variable, got 2*k"),
])
def test_bad_event_expressions(event, why):
    with _raises(InvalidEquation, why):
        flatten(_model_with(lambda m: [event(m)]))


# -- connections -----------------------------------------------------------------------
def test_connect_to_a_pin_of_a_component_outside_the_model():
    stray = Resistor()

    class C(RC):
        def equations(self):
            return [ac.connect(self.R1.p, stray.p)]

    with _raises(NotInModel, "the model (C) does not contain this PositivePin: it is a port "
                             "of a component that was never made part of it"):
        flatten(C())


def test_connect_to_a_pin_of_another_model():
    other = RC()
    flatten(other)

    class C(RC):
        def equations(self):
            return [ac.connect(self.R1.p, other.C1.p)]

    with _raises(NotInModel, "it is 'C1.p' of another model instance"):
        flatten(C())


def test_same_port_twice_in_one_connect():
    class C(RC):
        def equations(self):
            return [ac.connect(self.src.p, self.R1.p, self.src.p),
                    ac.connect(self.R1.n, self.C1.p),
                    ac.connect(self.C1.n, self.src.n, self.gnd.p)]

    with _raises(InvalidConnection, "connect(src.p, R1.p, src.p): port 'src.p' appears "
                                    "more than once"):
        flatten(C())


def test_port_connected_to_itself():
    class C(RC):
        def equations(self):
            return [ac.connect(self.R1.p, self.R1.p)]

    with _raises(InvalidConnection, "connect(R1.p, R1.p) connects port 'R1.p' to itself"):
        flatten(C())


def test_connect_of_a_port_outside_the_writing_component():
    class Inner(ac.Component):
        R = Resistor()

    class Meddler(ac.Component):
        def equations(self):
            return [ac.connect(self._parent.a.R.p, self._parent.b.R.p)]

    class Top(ac.Component):
        a = Inner()
        b = Inner()
        m = Meddler()

    with _raises(InvalidConnection, "connect(a.R.p, b.R.p) in 'm' (Meddler): port 'a.R.p' is "
                                    "neither a port of 'm' (Meddler) nor inside one of its "
                                    "sub-components"):
        flatten(Top())


def test_connect_of_a_component_that_is_not_a_port():
    class C(RC):
        def equations(self):
            return [ac.connect(self.R1, self.C1.p)]

    with _raises(InvalidConnection, "connect() takes ports, got the component 'R1' (Resistor); "
                                    "its ports: p, n"):
        flatten(C())


# -- the instance tree -----------------------------------------------------------------
def test_component_holding_itself_directly():
    class Selfish(ac.Component):
        def __init__(self, **mods):
            super().__init__(**mods)
            self.me = self

    with _raises(InvalidHierarchy, "Selfish.me: a component cannot contain itself"):
        Selfish()


def test_component_holding_itself_in_a_list():
    class Selfish(ac.Component):
        def __init__(self, **mods):
            super().__init__(**mods)
            self.parts = [Resistor(), self]

    with _raises(InvalidHierarchy, "Selfish.parts: a component cannot contain itself"):
        Selfish()


def test_cycle_of_sub_components():
    class Node(ac.Component):
        pass

    class Ring(ac.Component):
        def __init__(self, **mods):
            super().__init__(**mods)
            self.a, self.b = Node(), Node()
            self.a.peer = self.b
            self.b.peer = self.a

    with _raises(InvalidHierarchy, "'a' (Node) contains itself: its sub-component "
                                   "'a.peer.peer' is 'a' again"):
        flatten(Ring())


def test_cycle_through_the_model():
    class Node(ac.Component):
        pass

    class Top(ac.Component):
        def __init__(self, **mods):
            super().__init__(**mods)
            self.a = Node()
            self.a.back = self

    with _raises(InvalidHierarchy, "the model (Top) contains itself: its sub-component "
                                   "'a.back' is the model again"):
        flatten(Top())


def test_one_instance_at_two_places():
    class Twice(ac.Component):
        def __init__(self, **mods):
            super().__init__(**mods)
            self.r1 = self.r2 = Resistor()

    with _raises(InvalidHierarchy, "the same Resistor instance is part of the model twice, "
                                   "as 'r1' and as 'r2'"):
        flatten(Twice())


# -- legitimate input keeps working ----------------------------------------------------
@pytest.mark.parametrize("R", [2, 2.0, np.float64(2.0), np.int64(2), np.float32(2.0),
                               fractions.Fraction(2, 1), decimal.Decimal("2.0"),
                               sp.Integer(2), sp.Float(2.0)],
                         ids=lambda v: type(v).__name__)
def test_every_numeric_type_is_a_parameter_value(R):
    flat = flatten(RC(R1={"R": R}))
    value = next(p.value for p in flat.parameters if p.name == "R1.R")
    assert float(value) == 2.0


def test_exact_and_symbolic_values_simulate_the_rc_step_response():
    """R = 3/2 (Fraction), C = pi/100 (sympy): v_C(t) = 1 - exp(-t / (R C))."""
    R, C = fractions.Fraction(3, 2), sp.pi / 100
    tau = float(R) * float(C)
    res = ac.simulate(RC(R1={"R": R}, C1={"C": C}), t_end=3 * tau, rtol=1e-9, atol=1e-12,
                      t_eval=np.linspace(0, 3 * tau, 31))
    exact = 1 - np.exp(-res.t / tau)
    assert np.max(np.abs(res["C1.v"] - exact)) < 1e-6 * np.max(np.abs(exact))


def test_bindings_functions_and_expressions_of_parameters_still_work():
    class Load(ac.Component):
        J_m = ac.Parameter(1.0)
        J_L = ac.Parameter(2.0)
        J = ac.Parameter(lambda c: c.J_m + c.J_L, min=0)
        w = ac.Variable(start=1.0)

        def equations(self):
            return [ac.Eq(self.J * ac.der(self.w), -self.w)]

    flat = flatten(Load(J_L=fractions.Fraction(1, 2)))
    eq = flat.equations[0].residual
    J_m, J_L = (p.symbol for p in flat.parameters[:2])
    assert eq.has(J_m) and eq.has(J_L)          # J was replaced by J_m + J_L
    motor = flatten(DCMotor(R=2.5))             # ac.ref bindings
    assert "R" in {p.name for p in motor.parameters}


def test_infinite_values_where_the_equations_have_a_finite_limit():
    flat = flatten(PI(Tt=float("inf")))         # (y - v)/Tt -> 0; yMax = inf by default
    assert math.isinf(next(p.value for p in flat.parameters if p.name == "Tt"))


def test_structural_zero_is_kept():
    flat = flatten(DCMotor(L=0))
    assert "L" in flat.structural_zeros
