"""Parameters found by initialization (Modelica's ``parameter Real c(fixed=false)``).

A parameter declared ``Parameter(100.0, fixed=False)``, or modified so,
``Spring(c={"fixed": False, "start": 100.0})``, is not a constant given by the user but
an unknown of the initial system: its start value is Newton's first guess, and the
initial equations that remain after the states' conditions determine it (the MSL's
``MultiBody.Examples.Elementary.InitSpringConstant`` finds a spring constant so that a
body rests at a given position).  During the run it is a constant, as any parameter.

This module reads the attributes where the instance is made (``fixed``, ``start``) and
says what a component's parameter is when the model is flattened.
"""
from __future__ import annotations

from .units import convert_value
from .values import real_number
from ..errors import InvalidValue
from ..words import suggestion

__all__ = ["parameter_attributes", "parameter_start", "check_free_declaration",
           "attribute_values"]

_ATTRIBUTES = ("fixed", "start")


def check_free_declaration(decl) -> None:
    """ValueError unless ``fixed`` and ``start`` of the declaration ``decl`` are
    consistent: fixed a bool; a free parameter a scalar Real one; start a real number."""
    if not isinstance(decl.fixed, bool):
        raise ValueError(f"fixed = {decl.fixed!r} must be True or False")
    if decl.start is not None:
        real_number(decl.start, "start")
    if not decl.fixed and (decl.structural or decl.type is not float
                           or decl.shape is not None):
        raise ValueError("only a scalar Real parameter can be found by initialization "
                         "(fixed=False)")


def attribute_values(decl, key: str, mod: dict, where: str) -> dict:
    """A dict modification of parameter ``key`` checked where the instance is made: its
    attributes among ``fixed`` and ``start`` (a start with a unit converted); raises
    InvalidValue naming ``where``."""
    out = dict(mod)
    for attr in mod:
        if attr not in _ATTRIBUTES:
            raise InvalidValue(f"{where}: parameter '{key}' has no attribute '{attr}'"
                               f"{suggestion(str(attr), list(_ATTRIBUTES))} (a parameter is "
                               f"modified by its value or by a dict of {list(_ATTRIBUTES)})")
    try:
        if isinstance(mod.get("start"), str):
            out["start"] = convert_value(mod["start"], decl.unit, f"parameter {key}: start")
        parameter_attributes(_Probe(), key, out, decl)
    except ValueError as err:
        raise InvalidValue(f"{where}: {err}") from None
    return out


class _Probe:
    """A stand-in instance for checking attributes before the instance exists."""

    def __init__(self):
        self._param_values = {}


def parameter_attributes(comp, name: str, mod: dict, decl):
    """A parameter modified by a dict of attributes, ``{"fixed": False, "start": 100}``:
    the attributes are kept on ``comp`` (read by :func:`parameter_start`); returns the
    value the parameter keeps (its default or an earlier modification)."""
    unknown = sorted(set(mod) - set(_ATTRIBUTES))
    if unknown:
        raise ValueError(f"parameter {name}: unknown attribute(s) {unknown}; a parameter "
                         f"is modified by its value or by a dict of {list(_ATTRIBUTES)}")
    free = comp.__dict__.get("_param_free")
    if free is None:
        free = {}
        object.__setattr__(comp, "_param_free", free)
    fixed, start = free.get(name, (decl.fixed, decl.start))
    if "fixed" in mod:
        fixed = mod["fixed"]
        if not isinstance(fixed, bool):
            raise ValueError(f"parameter {name}: fixed = {fixed!r} must be True or False")
    if "start" in mod:
        start = real_number(mod["start"], f"parameter {name}: start")
    if not fixed and (decl.structural or decl.type is not float or decl.shape is not None):
        raise ValueError(f"parameter {name}: only a scalar Real parameter can be found "
                         "by initialization (fixed=False)")
    free[name] = (fixed, start)
    return comp._param_values.get(name, decl.value)


def parameter_start(comp, name: str, decl) -> float | None:
    """None for a parameter with a value (fixed=True, the default); for one found by
    initialization its start value, Newton's guess: the ``start`` given, else its value
    if that is a number, else 0 (Modelica's default start)."""
    fixed, start = comp.__dict__.get("_param_free", {}).get(name, (decl.fixed, decl.start))
    if fixed:
        return None
    if start is not None:
        return float(start)
    value = comp._param_values.get(name, decl.value)
    try:
        return float(value)
    except (TypeError, ValueError):
        raise ValueError(f"parameter {name} is found by initialization (fixed=False) and "
                         "bound to an expression: give it a start value (Newton's guess), "
                         f'e.g. {{"{name}": {{"fixed": False, "start": 1.0}}}}') from None
