"""Components describe themselves: help(), inspect.signature and repr list the declared
parameters with their defaults, units and descriptions, built from the declarations
(never written per class)."""
import inspect
import pathlib
import pydoc

import pytest

import acausal as ac
from acausal.components.declarations import own_docstring
from acausal.library.electrical import Resistor
from acausal.library.electromechanical import DCMotor
from acausal.library.hydraulics.lines import LumpedLine


def test_signature_lists_parameters_with_defaults_and_units():
    sig = inspect.signature(Resistor)
    r = sig.parameters["R"]
    assert r.kind is inspect.Parameter.KEYWORD_ONLY and r.default == 1.0
    assert "Ohm" in repr(r.annotation)
    assert list(sig.parameters)[-1] == "modifications"
    sig.bind(R=2.0, v={"start": 1.0})          # variables and sub-components by keyword
    with pytest.raises(TypeError):
        sig.bind(2.0)                          # parameters are keyword-only, as __init__ is
    text = str(inspect.signature(DCMotor))
    assert text.startswith("(*, R: float [Ohm] = 1.0, L: ")
    assert "useSupport: structural = False" in text    # the conditional support's flag


def test_signature_keeps_a_structural_init_argument():
    sig = inspect.signature(LumpedLine)
    names = list(sig.parameters)
    assert names[:2] == ["n", "form"] and sig.parameters["n"].default == 10
    assert "beta" in names and names[-1] == "modifications"


def test_help_shows_description_unit_bounds_and_the_class_docstring():
    text = pydoc.render_doc(Resistor, renderer=pydoc.plaintext)
    assert "Ohm's law" in text                         # the class's own docstring
    assert "R : float [Ohm], default 1.0" in text
    assert "T_ref : float [K], default 300.15 (min 0)" in text
    assert "resistance" in text
    assert "<acausal.components.declarations.Parameter object>" not in text
    assert "Parameter(1.0, unit='Ohm', description='resistance')" in text
    assert "p : PositivePin" in text                   # ports listed too


def test_signature_and_doc_follow_the_declarations_of_any_subclass():
    class Heater(ac.Component):
        """A test heater."""
        P = ac.Parameter(5.0, unit="W", description="heating power")
        G = ac.Parameter(lambda c: 2 * c.P, unit="W/K")
        T = ac.Variable(start=293.15, unit="K", description="temperature")

    class BigHeater(Heater):
        """A bigger one."""
        P = ac.Parameter(50.0, unit="W", description="a bigger heating power")

    assert inspect.signature(Heater).parameters["P"].default == 5.0
    assert repr(inspect.signature(Heater).parameters["G"].default) == "computed"
    assert inspect.signature(BigHeater).parameters["P"].default == 50.0
    assert "a bigger heating power" in BigHeater.__doc__
    assert "A test heater" not in BigHeater.__doc__    # its own docstring, not the base's
    assert "T : variable [K], start 293.15" in Heater.__doc__


def test_summary_paragraph_is_kept():
    # tools that show a model's summary read the docstring's first paragraph
    summary = ("Ideal linear resistor (Modelica.Electrical.Analog.Basic.Resistor, MSL "
               "v4.0.0),\nOhm's law with a linear temperature coefficient:")
    assert Resistor.__doc__.split("\n\n")[0] == summary
    assert own_docstring(Resistor).startswith(summary + "\n\n    R_actual")
    assert own_docstring(DCMotor).startswith("DC motor") and "----" not in own_docstring(DCMotor)

    class Undocumented(ac.Component):
        P = ac.Parameter(5.0, unit="W")

    assert Undocumented.__doc__ is None
    assert "P: float [W] = 5.0" in str(inspect.signature(Undocumented))


def test_repr_shows_values_with_units():
    assert repr(Resistor()) == "<Resistor (unbound): R=1.0 Ohm, T_ref=300.15 K, alpha=0.0 1/K>"
    assert repr(Resistor(R=5.0)).startswith("<Resistor (unbound): R=5.0 Ohm, T_ref=")
    motor = DCMotor(L=2e-3)
    assert "L=0.002 H" in repr(motor) and "k=0.05 N.m/A" in repr(motor)
    assert repr(Resistor().p) == "<PositivePin (unbound)>"    # ports stay short


def test_package_is_marked_typed():
    root = pathlib.Path(ac.__file__).parent
    assert (root / "py.typed").is_file()
