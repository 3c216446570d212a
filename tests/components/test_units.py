"""Units: every library model is dimensionally consistent; inconsistent equations are
rejected naming the equation, its component and the two dimensions; values given with
units are converted to the declared unit."""
import importlib
import pkgutil
import re
import warnings

import numpy as np
import pytest

import acausal as ac
from acausal.compiler.frontend.flatten import flatten
from acausal.compiler.frontend.unitcheck import check_units
from acausal.components.units import UnitError, UnitWarning, convert_value, parse_unit
from acausal.library import rotational as rot
from acausal.library.electrical import Capacitor, ConstantVoltage, Ground, Resistor


def _library_models():
    import acausal.library as lib
    found = []
    for m in pkgutil.walk_packages(lib.__path__, "acausal.library."):
        module = importlib.import_module(m.name)
        for name, cls in vars(module).items():
            if (isinstance(cls, type) and issubclass(cls, ac.Component)
                    and not issubclass(cls, ac.Port) and cls.__module__ == module.__name__
                    and not name.startswith(("_", "Partial"))):
                found.append(cls)
    return found


def test_every_library_component_and_example_is_dimensionally_consistent():
    """Each component on its own and each example model, flattened and checked with
    check_units="error" (a class that needs arguments or is abstract is skipped)."""
    checked, equations = [], 0
    for cls in _library_models():
        try:
            flat = flatten(cls())
        except (TypeError, ac.ModelError):
            continue            # needs constructor arguments, or is a partial model
        equations += check_units(flat, "error").checked
        checked.append(cls.__name__)
    assert len(checked) >= 180 and equations > 2000
    assert {"MotorDrive", "StickSlip", "KarnoppFriction", "DCMotor"} <= set(checked)


class WrongSpring(rot.PartialCompliant):
    """A torsional spring written with the angular velocity instead of the angle."""

    c = ac.Parameter(10.0, unit="N.m/rad", min=0)

    def equations(self):
        return [ac.Eq(self.tau, self.c * ac.der(self.phi_rel), label="Hooke's law")]


class Oscillator(ac.Component):
    housing = rot.Fixed()
    spring = WrongSpring()
    mass = rot.Inertia(J=0.1, phi={"start": 0.1, "fixed": True})

    def equations(self):
        return [ac.connect(self.housing.flange, self.spring.flange_a),
                ac.connect(self.spring.flange_b, self.mass.flange_a)]


WRONG = ("equation 'spring.tau = spring.c*der(spring.phi_rel)' in spring (WrongSpring), "
         "\"Hooke's law\": the sides differ: 'spring.tau' is N.m (kg.m2/s2) but "
         "'spring.c*der(spring.phi_rel)' is W (kg.m2/s3)")


def test_a_wrong_model_is_rejected_naming_equation_component_and_dimensions():
    with pytest.raises(UnitError, match=re.escape(WRONG)):
        ac.compile(Oscillator(), check_units="error", cache=False)
    assert issubclass(UnitError, ac.ModelError) and ac.UnitError is UnitError


def test_a_model_from_the_compile_cache_reports_its_findings_again(tmp_path, monkeypatch):
    """A flat-key hit reuses the entry's unit check (the key covers every unit and
    expression): the same mismatch is warned or raised in the mode of this compile."""
    monkeypatch.setenv("ACAUSAL_CACHE", str(tmp_path))
    monkeypatch.delenv("ACAUSAL_COMPILE_CACHE", raising=False)
    with pytest.warns(UnitWarning, match=re.escape(WRONG)):
        first = ac.compile(Oscillator(), check_units="warn", backend="numpy")
    with pytest.warns(UnitWarning, match=re.escape(WRONG)):
        again = ac.compile(Oscillator(), check_units="warn", backend="numpy")
    assert any("compile cache" in n for n in again.report.notes)
    assert again.report.units.mismatches == first.report.units.mismatches == [WRONG]
    with pytest.raises(UnitError, match=re.escape(WRONG)):
        ac.compile(Oscillator(), check_units="error", backend="numpy")
    with warnings.catch_warnings():
        warnings.simplefilter("error", UnitWarning)
        off = ac.compile(Oscillator(), check_units="off", backend="numpy")
    assert off.report.units.mode == "off" and off.report.units.mismatches == []


def test_warn_mode_warns_and_compiles_off_mode_is_silent():
    with pytest.warns(UnitWarning, match=re.escape(WRONG)):
        compiled = ac.compile(Oscillator(), check_units="warn", cache=False)
    assert len(compiled.report.units.mismatches) == 1
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        off = ac.compile(Oscillator(), check_units="off", cache=False)
    assert off.report.units.checked == 0
    with pytest.raises(ValueError, match="check_units must be one of"):
        ac.compile(Oscillator(), check_units="strict")


def _model(unit_x="m", unit_v="m/s", law=None):
    class M(ac.Component):
        x = ac.Variable(start=1.0, fixed=True, unit=unit_x)
        v = ac.Variable(unit=unit_v)
        k = ac.Parameter(2.0, unit="1/s")
        L = ac.Parameter(1.0, unit="m")
        f = ac.Parameter(1.0, unit="Hz")

        def equations(self):
            return [ac.Eq(ac.der(self.x), self.v),
                    ac.Eq(self.v, law(self) if law else -self.k * self.x)]
    return flatten(M())


def test_der_has_the_unit_per_second():
    assert not check_units(_model(), "error").mismatches
    with pytest.raises(UnitError, match=r"'der\(x\)' is m/s but 'v' is m\b"):
        check_units(_model(unit_v="m"), "error")


@pytest.mark.parametrize("law, ok", [
    (lambda c: -c.k * c.x * ac.exp(-c.x / c.L), True),
    (lambda c: -c.k * c.L * ac.sin(2 * ac.pi * c.f * ac.time), True),
    (lambda c: -c.k * c.x * ac.exp(-c.x), False),             # exp of a length
    (lambda c: -c.k * c.L * ac.sin(c.f), False),               # sin of a frequency
    (lambda c: -c.k * (c.x + 1), True),       # a number alone as a term adopts the unit
    (lambda c: -c.k * ac.sqrt(c.x**2 * c.L**2) / c.L, True),
    (lambda c: -c.k * c.x**c.k, False),       # symbolic exponent of a dimensioned base
    (lambda c: ac.if_else(c.x > c.L, -c.k * c.x, c.x), False),  # branches differ
    (lambda c: ac.if_else(c.x > c.f, -c.k * c.x, 0), False),    # relation sides differ
])
def test_functions_and_numbers(law, ok):
    result = check_units(_model(law=law), "warn" if ok else "off")
    if ok:
        assert not result.mismatches
    else:
        with pytest.raises(UnitError):
            check_units(_model(law=law), "error")


def test_unitless_variables_adopt_any_dimension_and_are_listed():
    flat = _model(unit_v="")
    result = check_units(flat, "error")
    assert result.unitless_variables == ["v"] and not result.mismatches
    assert "1 variable(s) without a unit (any dimension): v" in result.summary()


def test_derived_parameter_binding_is_checked_against_its_declared_unit():
    class Tank(ac.Component):
        rho = ac.Parameter(1000.0, unit="kg/m3")
        V = ac.Parameter(2.0, unit="m3")
        m = ac.Parameter(lambda c: c.rho * c.V, unit="kg")
        bad = ac.Parameter(lambda c: c.rho + c.V, unit="kg")
        x = ac.Variable(unit="kg")

        def equations(self):
            return [ac.Eq(self.x, self.m)]

    with pytest.raises(UnitError, match=r"parameter bad = .*terms of a sum differ: "):
        check_units(flatten(Tank()), "error")


def test_unit_strings_in_modelica_syntax():
    assert parse_unit("N.m/rad").dims == parse_unit("N.m").dims == parse_unit("J").dims
    assert parse_unit("kg.m2").dims == parse_unit("kg*m^2").dims
    assert parse_unit("m3/(s.Pa)").dims == parse_unit("m4.s/kg").dims
    assert parse_unit("1/s").dims == parse_unit("s-1").dims == parse_unit("Hz").dims
    assert parse_unit("") is None
    with pytest.raises(UnitError, match="unknown unit 'furlong'"):
        parse_unit("furlong/s")


def test_a_bad_unit_string_is_named_with_its_variable():
    class M(ac.Component):
        x = ac.Variable(unit="m/fortnight")

        def equations(self):
            return [ac.Eq(self.x, 1)]

    with pytest.raises(UnitError, match="x: unit 'm/fortnight': unknown unit 'fortnight'"):
        ac.compile(M(), check_units="warn", cache=False)


@pytest.mark.parametrize("given, declared, value", [
    ("2 kOhm", "Ohm", 2000.0), ("0.5 mF", "F", 5e-4), ("3 bar", "Pa", 3e5),
    ("20 degC", "K", 293.15), ("60 rpm", "rad/s", 2 * np.pi), ("1.5", "Ohm", 1.5),
    ("250 mm", "m", 0.25), ("1e3 N.m/rad", "N.m/rad", 1e3),
])
def test_values_given_with_units_are_converted(given, declared, value):
    assert convert_value(given, declared, "parameter p") == pytest.approx(value, rel=1e-14)


def test_resistor_given_in_kilo_ohm_simulates_as_the_analytic_rc():
    class RC(ac.Component):
        src = ConstantVoltage(V=1.0)
        R1 = Resistor(R="2 kOhm")
        C1 = Capacitor(C="0.5 mF", v={"start": 0.0, "fixed": True})
        gnd = Ground()

        def equations(self):
            return [ac.connect(self.src.p, self.R1.p), ac.connect(self.R1.n, self.C1.p),
                    ac.connect(self.C1.n, self.src.n, self.gnd.p)]

    model = RC()
    assert model.R1.parameter_value("R") == 2000.0 if model.R1._path is not None else True
    t = np.linspace(0, 3, 31)
    res = ac.simulate(ac.compile(model, check_units="error", cache=False), t_end=3.0,
                      t_eval=t, rtol=1e-10, atol=1e-12)
    assert res["R1.R"] == pytest.approx(2000.0) if "R1.R" in res.names else True
    assert np.max(np.abs(res["C1.v"] - (1 - np.exp(-t / 1.0)))) < 1e-7  # tau = R C = 1 s


@pytest.mark.parametrize("given, why", [
    ("2 kg", "parameter R = '2 kg' has dimension kg, but R is declared in 'Ohm'"),
    ("2 parsec", "parameter R = '2 parsec': unit 'parsec': unknown unit 'parsec'"),
    ("two", "parameter R = 'two' is not a real number (it is a str)"),
])
def test_a_value_with_a_wrong_unit_fails_where_it_is_given(given, why):
    with pytest.raises(ac.InvalidValue, match=re.escape(f"Resistor: {why}")):
        Resistor(R=given)


def test_a_reinit_that_changes_the_dimension_is_rejected():
    class Ball(ac.Component):
        h = ac.Variable(start=1.0, fixed=True, unit="m")
        v = ac.Variable(start=0.0, fixed=True, unit="m/s")
        e = ac.Parameter(0.8, unit="1")
        g = ac.Parameter(9.81, unit="m/s2")

        def equations(self):
            return [ac.Eq(ac.der(self.h), self.v), ac.Eq(ac.der(self.v), -self.g),
                    ac.when(self.h < 0, ac.reinit(self.v, -self.e * ac.pre(self.h)))]

    with pytest.raises(UnitError, match=r"when h < 0 in \(model\) \(Ball\): reinit changes "
                                        r"the dimension: 'v' is m/s but '-e\*pre\(h\)' is m"):
        check_units(flatten(Ball()), "error")


def test_simulate_takes_the_unit_check_mode_of_a_component_it_compiles():
    with pytest.raises(UnitError, match=re.escape(WRONG)):
        ac.simulate(Oscillator(), t_end=0.1, check_units="error")


def test_known_units_are_read_as_sympy_reads_them():
    from acausal.components.units import _KNOWN, _parse_with_sympy
    for text, (dims, scale) in _KNOWN.items():
        ref = _parse_with_sympy(text)
        assert (ref.dims, ref.scale, ref.offset) == (dims, scale, 0.0), text
