"""The modelling language: declarations, inheritance, hierarchy, modifications, errors."""
import pytest

import acausal as ac
from acausal.compiler.frontend.flatten import flatten
from acausal.library.electrical import Capacitor, ConstantVoltage, Ground, OnePort, Resistor
from acausal.library.electromechanical import DCMotor
from acausal.library.rotational import Fixed


class Divider(ac.Component):
    src = ConstantVoltage(V=10.0)
    R1 = Resistor(R=1.0)
    R2 = Resistor(R=3.0)
    gnd = Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.R1.p), ac.connect(self.R1.n, self.R2.p),
                ac.connect(self.R2.n, self.src.n, self.gnd.p)]


class Board(ac.Component):
    """Two levels of hierarchy, for nested modifications."""

    left = Divider()
    right = Divider(R2={"R": 1.0})


def _value(flat, name):
    return next(p.value for p in flat.parameters if p.name == name)


def test_dotted_names_and_inheritance():
    flat = flatten(Divider())
    names = {v.name for v in flat.variables}
    # OnePort's variables are inherited by every resistor
    assert {"R1.v", "R1.i", "R1.p.v", "R1.n.i", "R2.v"} <= names
    assert isinstance(Divider().R1, OnePort)


def test_modifications_several_levels_down():
    flat = flatten(Board(left={"R1": {"R": 7.0}}, right={"src": {"V": 5.0}}))
    assert _value(flat, "left.R1.R") == 7.0
    assert _value(flat, "left.R2.R") == 3.0
    assert _value(flat, "right.R2.R") == 1.0     # the class-level modification
    assert _value(flat, "right.src.V") == 5.0


def test_start_value_modification():
    flat = flatten(Capacitor(v={"start": 2.0, "fixed": True}))
    v = flat.variable("v")
    assert v.attrs.start == 2.0 and v.attrs.fixed is True
    flat = flatten(Capacitor(v=3.0))
    assert flat.variable("v").attrs.start == 3.0


def test_instances_do_not_share_sub_components():
    a, b = Divider(), Divider()
    assert a.R1 is not b.R1


def test_hierarchical_motor_binds_parameters_to_its_own():
    flat = flatten(DCMotor(R=2.5))
    assert {"Ra.v", "La.i", "emf.w", "rotor.w"} <= {v.name for v in flat.variables}
    res = [e for e in flat.equations if "Ra.v" in e.text and "Ra.i" in e.text]
    assert res and "R" in str(res[0].residual.free_symbols)


def test_unknown_modification_names_the_component():
    with pytest.raises(ac.ModelError, match=r"'R1' \(Resistor\) has no parameter.*'Rx'"):
        flatten(Divider(R1={"Rx": 1.0}))


def test_error_inside_equations_names_the_component():
    class Broken(ac.Component):
        x = ac.Variable()

        def equations(self):
            return [ac.Eq(self.y, 1)]

    class Top(ac.Component):
        b = Broken()

    with pytest.raises(ac.ModelError, match=r"'b' \(Broken\).*AttributeError"):
        flatten(Top())


def test_connecting_different_port_types_is_an_error():
    class Bad(ac.Component):
        r = Resistor()
        f = Fixed()

        def equations(self):
            return [ac.connect(self.r.p, self.f.flange)]

    with pytest.raises(ac.ModelError, match="different types"):
        flatten(Bad())


def test_connection_sets_sum_currents_and_equate_potentials():
    flat = flatten(Divider())
    texts = [e.text for e in flat.equations if e.kind == "connect"]
    assert "R1.n.v = R2.p.v" in texts
    assert any("R1.n.i" in t and "R2.p.i" in t and t.endswith("= 0") for t in texts)
