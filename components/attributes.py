"""Modelica's attributes of a variable: start, fixed, unit, nominal, min, max,
stateSelect, and acausal's description, discrete, type and steady.

``VariableAttributes`` holds a scalar variable's, checked when its class is created
(:meth:`VariableAttributes.checked`): a Real's as numbers, a Boolean's or an Integer's as
its value type says (:func:`checked_discrete`: a start of its type, no unit for a
Boolean, no nominal or state selection).  An array variable's attributes, element by
element, are :class:`acausal.components.arrays.ArrayAttributes`.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, fields, replace

import numpy as np

from .values import (TYPE_NAMES, bound_violation, real_number, typed_value,
                     value_type_checked)

__all__ = ["VariableAttributes", "checked_discrete"]

_STATE_SELECT = ("never", "avoid", "default", "prefer", "always")


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
    discrete: bool = False   # changes only in when-clauses (Modelica's ``discrete`` prefix)
    type: type = float       # float (Real), bool (Boolean) or int (Integer)
    steady: bool = False     # der(v) = 0 at the start (an initial equation: steady state)

    def modified(self, mod) -> "VariableAttributes":
        """A checked copy with a modification applied: a number sets start, a dict any
        attribute.  Raises ValueError (bad value) or TypeError (unknown attribute)."""
        if isinstance(mod, dict):
            return self.with_attributes(mod)
        if isinstance(mod, (str, list, tuple, set)) or mod is None:
            raise ValueError(f"a modification of a variable is a number (its start value) "
                             f"or a dict of its attributes, not {mod!r}")
        return replace(self, start=mod).checked()

    def with_attributes(self, mod: dict) -> "VariableAttributes":
        """A checked copy with the attributes of ``mod`` set (TypeError naming the
        unknown ones)."""
        unknown = set(mod) - {f.name for f in fields(self)}
        if unknown:
            raise TypeError(f"unknown variable attribute(s) {sorted(unknown)}; "
                            f"allowed: {sorted(f.name for f in fields(self))}")
        return replace(self, **mod).checked()

    def checked(self) -> "VariableAttributes":
        """A copy with numbers as floats, or ValueError naming the bad attribute.

        start is finite; fixed is True, False or None; nominal is finite and positive
        (it scales error weights); min <= max; start lies in [min, max]."""
        typ = value_type_checked(self.type)
        if typ is not float:
            return checked_discrete(self, typ)
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
        if not isinstance(self.discrete, (bool, np.bool_)):
            raise ValueError(f"discrete = {self.discrete!r} must be True or False")
        if not isinstance(self.steady, (bool, np.bool_)):
            raise ValueError(f"steady = {self.steady!r} must be True or False")
        _check_state_select(self.state_select)
        return replace(self, start=start, fixed=fixed, nominal=nominal, min=lo, max=hi)

def _check_state_select(value):
    if not isinstance(value, str) or value not in _STATE_SELECT:
        raise ValueError(f"state_select must be one of {_STATE_SELECT}, not {value!r}")


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
    if start is not None and bound_violation(start, lo, hi):
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
