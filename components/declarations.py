"""Declarations inside a component class: Parameter and Variable.

A declaration is a descriptor.  Read on a bound instance it yields that instance's
sympy Symbol, named by the dotted path (``motor.R.R``), so equations read like the book:
``self.v - self.R*self.i``.  Values (parameter values, start values) live on the
instance and can be modified when a component is instantiated.

Values are checked, never coerced (Modelica's type rules for a ``Real``, section 4.8 of
the specification): a real number is an ``int``, ``float``, numpy integer or floating
scalar, ``Fraction``, ``Decimal`` or sympy number whose value is real.  A ``bool`` is
not a real number (``Resistor(R=True)`` is rejected: write ``1.0`` if one is meant);
neither is a string, a list, a complex number or NaN.  The checks here raise
``ValueError`` describing the value; the component that holds the declaration turns
that into a ``ModelError`` naming the component path and the declaration.
"""
from __future__ import annotations

import math
import numbers
import sys
from dataclasses import dataclass, fields, replace
from decimal import Decimal

import numpy as np

__all__ = ["Parameter", "Variable", "Across", "Through", "Signal", "VariableAttributes", "ref",
           "real_number", "check_parameter_value", "bound_violation", "is_symbolic"]

_STATE_SELECT = ("never", "avoid", "default", "prefer", "always")


def is_symbolic(value) -> bool:
    """True if ``value`` is a sympy object.  Declarations are checked when a class is
    created, before any model builds a symbol; sympy is imported only by the first symbol
    or equation, and until then no value can be a sympy object."""
    sympy = sys.modules.get("sympy")
    return sympy is not None and isinstance(value, sympy.Basic)


def real_number(value, what: str) -> float:
    """``value`` as a float if it is a real number (see the module docstring), else a
    ``ValueError`` that starts with ``what = value``.  Infinite values pass; NaN does not."""
    if isinstance(value, (bool, np.bool_)):
        raise ValueError(f"{what} = {value!r} is a bool, not a real number")
    if is_symbolic(value):
        if not value.is_number:
            raise ValueError(f"{what} = {value} is an expression, not a real number")
    elif not isinstance(value, (numbers.Real, Decimal)):
        raise ValueError(f"{what} = {value!r} is not a real number "
                         f"(it is a {type(value).__name__})")
    try:
        x = float(value)
    except (TypeError, ValueError, OverflowError):
        # sympy's I, zoo and other numbers without a real value end here
        raise ValueError(f"{what} = {value} is not a real number") from None
    if math.isnan(x):
        raise ValueError(f"{what} = {value!r} is not a number (NaN)")
    return x


def check_parameter_value(value, what: str) -> None:
    """A parameter value is a real number, ``ref``, function of the component or sympy
    expression of other parameters (whose symbols flattening checks); else ValueError."""
    if value is None or isinstance(value, ref):
        return
    if is_symbolic(value):
        from sympy import Expr    # already loaded: value is a sympy object
        if not isinstance(value, Expr):
            raise ValueError(f"{what} = {value} is a relation or a logical value, "
                             "not a real number")
        if value.is_number:
            real_number(value, what)
        return
    if callable(value) and not isinstance(value, (numbers.Number, Decimal, np.generic)):
        return
    real_number(value, what)


def bound_violation(value: float, lo, hi) -> str | None:
    """Why ``value`` lies outside [lo, hi] (either may be None), or None."""
    if lo is not None and value < lo:
        return f"is below its minimum {lo!r}"
    if hi is not None and value > hi:
        return f"is above its maximum {hi!r}"
    return None


def _is_real(value) -> bool:
    try:
        real_number(value, "")
        return True
    except ValueError:
        return False


def _finite(value, what: str) -> float:
    x = real_number(value, what)
    if math.isinf(x):
        raise ValueError(f"{what} = {value!r} is not finite")
    return x


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
        """A checked copy with a modification applied: a number sets start, a dict any
        attribute.  Raises ValueError (bad value) or TypeError (unknown attribute)."""
        if isinstance(mod, dict):
            unknown = set(mod) - {f.name for f in fields(self)}
            if unknown:
                raise TypeError(f"unknown variable attribute(s) {sorted(unknown)}; "
                                f"allowed: {sorted(f.name for f in fields(self))}")
            return replace(self, **mod).checked()
        if isinstance(mod, (str, list, tuple, set)) or mod is None:
            raise ValueError(f"a modification of a variable is a number (its start value) "
                             f"or a dict of its attributes, not {mod!r}")
        return replace(self, start=mod).checked()

    def checked(self) -> "VariableAttributes":
        """A copy with numbers as floats, or ValueError naming the bad attribute.

        start is finite; fixed is True, False or None; nominal is finite and positive
        (it scales error weights); min <= max; start lies in [min, max]."""
        start = None if self.start is None else _finite(self.start, "start")
        nominal = None if self.nominal is None else _finite(self.nominal, "nominal")
        if nominal is not None and nominal <= 0:
            raise ValueError(f"nominal = {self.nominal!r} must be positive "
                             "(it is the variable's typical magnitude)")
        lo = None if self.min is None else real_number(self.min, "min")
        hi = None if self.max is None else real_number(self.max, "max")
        if lo is not None and hi is not None and lo > hi:
            raise ValueError(f"min = {self.min!r} is greater than max = {self.max!r}")
        if start is not None and ((lo is not None and start < lo)
                                  or (hi is not None and start > hi)):
            raise ValueError(f"start = {self.start!r} lies outside "
                             f"[min, max] = [{self.min!r}, {self.max!r}]")
        fixed = self.fixed
        if fixed is not None:
            if not isinstance(fixed, (bool, np.bool_)):
                raise ValueError(f"fixed = {fixed!r} must be True or False")
            fixed = bool(fixed)
        for name in ("unit", "description"):
            if not isinstance(getattr(self, name), str):
                raise ValueError(f"{name} = {getattr(self, name)!r} must be a string")
        _check_state_select(self.state_select)
        return replace(self, start=start, fixed=fixed, nominal=nominal, min=lo, max=hi)


def _check_state_select(value):
    if not isinstance(value, str) or value not in _STATE_SELECT:
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
    the component: ``Parameter(lambda c: c.J_m + c.J_L)``, or bound to the enclosing
    component's parameter with ``ref``.  ``min`` and ``max`` are enforced when the model
    is flattened.  An infinite value is accepted where the equations stay finite with it
    (a time constant in ``1/Tt``, an output limit); a bool is not a real number.
    """

    def __init__(self, value=None, unit: str = "", description: str = "",
                 min: float | None = None, max: float | None = None):
        self.value = value
        self.unit = unit
        self.description = description
        self.min = min
        self.max = max

    def check(self) -> None:
        """ValueError unless the declaration is consistent (checked once per class)."""
        check_parameter_value(self.value, "default value")
        lo = None if self.min is None else real_number(self.min, "min")
        hi = None if self.max is None else real_number(self.max, "max")
        if lo is not None and hi is not None and lo > hi:
            raise ValueError(f"min = {self.min!r} is greater than max = {self.max!r}")
        if _is_real(self.value):
            why = bound_violation(float(self.value), self.min, self.max)
            if why:
                raise ValueError(f"default value {self.value!r} {why}")
        for name in ("unit", "description"):
            if not isinstance(getattr(self, name), str):
                raise ValueError(f"{name} = {getattr(self, name)!r} must be a string")


class Variable(_Declaration):
    """An unknown of the model (a time function).

    ``Variable(start=0.0, fixed=False, unit="V", nominal=1.0, state_select="default")``:
    ``start`` is the initial value (or the guess, when ``fixed`` is False and the value
    is determined by equations), ``nominal`` scales error weights, ``state_select`` is
    the user's hint for state selection (never/avoid/default/prefer/always).  The
    attributes are checked when the class is created (``VariableAttributes.checked``).
    """

    kind = "variable"

    def __init__(self, start: float | None = None, fixed: bool | None = None, unit: str = "",
                 nominal: float | None = None, min: float | None = None,
                 max: float | None = None, state_select: str = "default",
                 description: str = ""):
        self.attributes = VariableAttributes(
            start=start, fixed=fixed, unit=unit, nominal=nominal, min=min, max=max,
            state_select=state_select, description=description)

    def check(self) -> None:
        """Replace the attributes by their checked copy (ValueError if one is bad)."""
        self.attributes = self.attributes.checked()


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
        if not isinstance(name, str) or not name.isidentifier():
            from .component import InvalidValue   # component.py imports this module
            raise InvalidValue(f"ref() takes the name of a parameter of the enclosing "
                               f"component, not {name!r}")
        self.name = name

    def __repr__(self):
        return f"ref({self.name!r})"
