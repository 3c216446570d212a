"""Declarations inside a component class: Parameter and Variable.

A declaration is a descriptor.  Read on a bound instance it yields that instance's
sympy Symbol, named by the dotted path (``motor.R.R``), so equations read like the book:
``self.v - self.R*self.i``.  Values (parameter values, start values) live on the
instance and can be modified when a component is instantiated.
"""
from __future__ import annotations

from dataclasses import dataclass, replace

__all__ = ["Parameter", "Variable", "Across", "Through", "Signal", "VariableAttributes", "ref"]

_STATE_SELECT = ("never", "avoid", "default", "prefer", "always")


@dataclass
class VariableAttributes:
    """Modelica's attributes of a Real variable."""

    start: float | None = None
    fixed: bool | None = None
    unit: str = ""
    nominal: float | None = None
    min: float | None = None
    max: float | None = None
    state_select: str = "default"
    description: str = ""

    def modified(self, mod) -> "VariableAttributes":
        """A copy with a modification applied: a number sets start, a dict any attribute."""
        if isinstance(mod, dict):
            unknown = set(mod) - set(self.__dataclass_fields__)
            if unknown:
                raise TypeError(f"unknown variable attribute(s) {sorted(unknown)}; "
                                f"allowed: {sorted(self.__dataclass_fields__)}")
            out = replace(self, **mod)
        else:
            out = replace(self, start=float(mod))
        _check_state_select(out.state_select)
        return out


def _check_state_select(value):
    if value not in _STATE_SELECT:
        raise ValueError(f"state_select must be one of {_STATE_SELECT}, not {value!r}")


class _Declaration:
    """Common descriptor machinery: the attribute name and the per-instance symbol."""

    name: str = None

    def __set_name__(self, owner, name):
        self.name = name

    def __get__(self, instance, owner=None):
        if instance is None:
            return self
        return instance._symbol(self.name)


class Parameter(_Declaration):
    """A constant of the model, with a value that can be modified per instance.

    ``Parameter(1.0, unit="Ohm", min=0, description="resistance")``.  A value may also
    be an expression of other parameters of the same component, given as a function of
    the component: ``Parameter(lambda c: c.J_m + c.J_L)``.
    """

    def __init__(self, value=None, unit: str = "", description: str = "",
                 min: float | None = None, max: float | None = None):
        self.value = value
        self.unit = unit
        self.description = description
        self.min = min
        self.max = max


class Variable(_Declaration):
    """An unknown of the model (a time function).

    ``Variable(start=0.0, fixed=False, unit="V", nominal=1.0, state_select="default")``:
    ``start`` is the initial value (or the guess, when ``fixed`` is False and the value
    is determined by equations), ``nominal`` scales error weights, ``state_select`` is
    the user's hint for state selection (never/avoid/default/prefer/always).
    """

    kind = "variable"

    def __init__(self, start: float | None = None, fixed: bool | None = None, unit: str = "",
                 nominal: float | None = None, min: float | None = None,
                 max: float | None = None, state_select: str = "default",
                 description: str = ""):
        _check_state_select(state_select)
        self.attributes = VariableAttributes(
            start=start, fixed=fixed, unit=unit, nominal=nominal, min=min, max=max,
            state_select=state_select, description=description)


class Across(Variable):
    """A port variable that is equal at every connected port (potential, position)."""

    kind = "across"


class Through(Variable):
    """A port variable that sums to zero at a node, positive into the component."""

    kind = "through"


class Signal(Variable):
    """The value of a causal signal port (RealInput / RealOutput)."""

    kind = "signal"


class ref:
    """A parameter binding to the enclosing component's parameter.

    ``Ra = Resistor(R=ac.ref("R"))`` inside a DCMotor is Modelica's ``Resistor Ra(R=R)``:
    the resistor's R is the motor's R, whatever value the motor is given.
    """

    def __init__(self, name: str):
        self.name = name

    def __repr__(self):
        return f"ref({self.name!r})"
