"""The values a declaration is given, checked, never coerced.

Modelica's type rules for a ``Real`` (section 4.8 of the specification): a real number
is an ``int``, ``float``, numpy integer or floating scalar, ``Fraction``, ``Decimal`` or
sympy number whose value is real.  A ``bool`` is not a real number (``Resistor(R=True)``
is rejected: write ``1.0`` if one is meant); neither is a string, a list, a complex
number or NaN.  A Boolean is True or False, an Integer a whole number (the value types
of Modelica's simple types: :data:`TYPE_NAMES`).  A parameter's value may also be a
``ref`` to the enclosing component's parameter, a function of the component or a sympy
expression of other parameters.  The checks here raise ``ValueError`` describing the
value; the component that holds the declaration turns that into a ``ModelError`` naming
the component path and the declaration.
"""
from __future__ import annotations

import math
import numbers
import sys
from decimal import Decimal

import numpy as np

from ..errors import InvalidValue

__all__ = ["TYPE_NAMES", "typed_value", "value_type_checked", "is_symbolic", "real_number",
           "check_parameter_value", "check_structural_value", "bound_violation", "ref"]


# The value types of Modelica's simple types: Real (a float), Boolean and Integer.  A
# Boolean or Integer variable is discrete by nature: it changes only at events.
TYPE_NAMES = {float: "Real", bool: "Boolean", int: "Integer"}


def value_type_checked(typ, what: str = "type"):
    """``typ`` checked: float, bool or int (the Python types of Real, Boolean, Integer)."""
    if typ not in TYPE_NAMES:
        raise ValueError(f"{what} = {typ!r} must be float (Real), bool (Boolean) or int "
                         "(Integer)")
    return typ


def typed_value(value, typ, what: str):
    """``value`` as the Python value of type ``typ`` (float, bool or int), or a
    ValueError that starts with ``what = value``.  A Boolean is True or False (not 0 or
    1); an Integer is a whole number that is not a bool (3 or 3.0, not 3.5)."""
    if typ is float:
        return real_number(value, what)
    if typ is bool:
        if isinstance(value, (bool, np.bool_)):
            return bool(value)
        raise ValueError(f"{what} = {value!r} is not a Boolean (True or False)")
    if isinstance(value, (bool, np.bool_)):
        raise ValueError(f"{what} = {value!r} is a bool, not an Integer")
    if isinstance(value, numbers.Integral):
        return int(value)
    x = real_number(value, what)
    if math.isfinite(x) and x == int(x):
        return int(x)
    raise ValueError(f"{what} = {value!r} is not an Integer (a whole number)")


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


def check_parameter_value(value, what: str, typ=float) -> None:
    """A parameter value is a real number (of a Boolean parameter True or False, of an
    Integer parameter a whole number), ``ref``, function of the component or sympy
    expression of other parameters (whose symbols flattening checks); else ValueError."""
    if value is None or isinstance(value, ref):
        return
    if typ is not float and not is_symbolic(value) and (
            not callable(value) or isinstance(value, (numbers.Number, np.generic))):
        typed_value(value, typ, what)
        return
    if isinstance(value, (np.ndarray, list, tuple)):
        raise ValueError(f"{what} = {value!r} is not a real number (it is a "
                         f"{type(value).__name__}): the parameter is declared a scalar (an "
                         "array value or shape= declares an array)")
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


def check_structural_value(value, what: str, lo=None, hi=None, choices=None) -> None:
    """A structural parameter's value is a number or a bool, or a list or tuple of them
    (numbers within [lo, hi]), or one of its ``choices`` (strings, an enumeration: the
    MSL's ``initType``); else ValueError."""
    if choices is not None:
        if value not in choices:
            raise ValueError(f"{what} = {value!r} is not one of {', '.join(map(repr, choices))}")
        return
    items = value if isinstance(value, (list, tuple)) else [value]
    for item in items:
        if isinstance(item, (bool, np.bool_)):
            continue
        if isinstance(item, (list, tuple)):
            check_structural_value(item, what, lo, hi)
            continue
        x = real_number(item, what)
        why = bound_violation(x, lo, hi)
        if why:
            raise ValueError(f"{what} = {item!r} {why}")


def bound_violation(value: float, lo, hi) -> str | None:
    """Why ``value`` lies outside [lo, hi] (either may be None), or None."""
    if lo is not None and value < lo:
        return f"is below its minimum {lo!r}"
    if hi is not None and value > hi:
        return f"is above its maximum {hi!r}"
    return None


class ref:
    """A parameter binding to the enclosing component's parameter.

    ``Ra = Resistor(R=ac.ref("R"))`` inside a DCMotor is Modelica's ``Resistor Ra(R=R)``:
    the resistor's R is the motor's R, whatever value the motor is given.
    """

    def __init__(self, name: str):
        if not isinstance(name, str) or not name.isidentifier():
            raise InvalidValue(f"ref() takes the name of a parameter of the enclosing "
                               f"component, not {name!r}")
        self.name = name

    def __repr__(self):
        return f"ref({self.name!r})"
