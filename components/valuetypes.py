"""The value types of Modelica's simple types: Real (a float), Boolean and Integer.

A Boolean or Integer variable is discrete by nature (it changes only at events); its
values are checked as its type says (:func:`typed_value`), and its attributes
(:func:`checked_discrete`): a start of its type, no unit (a Boolean), nominal or state
selection.
"""
from __future__ import annotations

import math
import numbers
from dataclasses import replace

import numpy as np

__all__ = ["TYPE_NAMES", "typed_value", "value_type_checked", "checked_discrete"]


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
        return _real_number(value, what)
    if typ is bool:
        if isinstance(value, (bool, np.bool_)):
            return bool(value)
        raise ValueError(f"{what} = {value!r} is not a Boolean (True or False)")
    if isinstance(value, (bool, np.bool_)):
        raise ValueError(f"{what} = {value!r} is a bool, not an Integer")
    if isinstance(value, numbers.Integral):
        return int(value)
    x = _real_number(value, what)
    if math.isfinite(x) and x == int(x):
        return int(x)
    raise ValueError(f"{what} = {value!r} is not an Integer (a whole number)")


def checked_discrete(self, typ):
    """A Boolean or Integer variable: its start (and an Integer's min and max) of its
    type; no unit, nominal or state selection (it is never a state)."""
    name = TYPE_NAMES[typ]
    for attr, default in (("nominal", None), ("state_select", "default")):
        if getattr(self, attr) != default:
            raise ValueError(f"{attr} = {getattr(self, attr)!r}: a {name} variable has "
                             f"no {attr} (it is never a state)")
    if typ is bool and (self.min is not None or self.max is not None or self.unit):
        raise ValueError("a Boolean variable has no unit, min or max")
    start = None if self.start is None else typed_value(self.start, typ, "start")
    lo = None if self.min is None else typed_value(self.min, typ, "min")
    hi = None if self.max is None else typed_value(self.max, typ, "max")
    if lo is not None and hi is not None and lo > hi:
        raise ValueError(f"min = {self.min!r} is greater than max = {self.max!r}")
    if start is not None and _bound_violation(start, lo, hi):
        raise ValueError(f"start = {self.start!r} lies outside "
                         f"[min, max] = [{self.min!r}, {self.max!r}]")
    for attr in ("unit", "description"):
        if not isinstance(getattr(self, attr), str):
            raise ValueError(f"{attr} = {getattr(self, attr)!r} must be a string")
    if self.fixed is not None and not isinstance(self.fixed, (bool, np.bool_)):
        raise ValueError(f"fixed = {self.fixed!r} must be True or False")
    if not isinstance(self.discrete, (bool, np.bool_)):
        raise ValueError(f"discrete = {self.discrete!r} must be True or False")
    return replace(self, start=start, min=lo, max=hi,
                   fixed=None if self.fixed is None else bool(self.fixed))


def _real_number(value, what):
    from .declarations import real_number
    return real_number(value, what)


def _bound_violation(value, lo, hi):
    from .declarations import bound_violation
    return bound_violation(value, lo, hi)
