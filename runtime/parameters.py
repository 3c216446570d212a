"""A compiled model's tunable parameters changed by name (``CompiledModel.set_parameters``):
values read as the type each parameter has, checked against its bounds and those of the
parameters bound to it, all or none; and why a name cannot be set."""
from __future__ import annotations

import math

import numpy as np

from ..components.arrays import array_of_name
from ..components.declarations import typed_value
from ..words import suggestion
from ..errors import InvalidValue, NotInModel
from ..words import listed
from .initparams import not_tunable

__all__ = ["tuned_parameters", "no_parameter_message"]


def tuned_parameters(model, values: dict) -> np.ndarray:
    """The parameter vector of ``model`` with ``values`` set (by name; a parameter array
    by element or whole); InvalidValue or NotInModel, and nothing changed, otherwise."""
    p = model.p.copy()
    for name, value in _by_element(values, model.param_names).items():
        if name not in model.param_names:
            raise NotInModel(no_parameter_message(model, name))
        why = not_tunable(model, name)
        if why:
            raise InvalidValue(why)
        x = _real_value(name, value, model.meta.get("parameter_types", {}).get(name))
        lo, hi = model.meta.get("parameter_bounds", {}).get(name, (None, None))
        if (lo is not None and x < lo) or (hi is not None and x > hi):
            raise InvalidValue(f"parameter '{name}' = {x!r} is outside its range "
                               f"[{'-inf' if lo is None else lo}, "
                               f"{'inf' if hi is None else hi}]")
        p[model.param_names.index(name)] = x
    for name, lo, hi, f in model.meta.get("derived_bounds", ()):
        x = float(f(p))
        if (lo is not None and x < lo) or (hi is not None and x > hi):
            given = ", ".join(f"{n} = {float(v)!r}" for n, v in values.items())
            raise InvalidValue(f"with {given}, parameter '{name}' (bound to it) would "
                               f"be {x!r}, outside its range "
                               f"[{'-inf' if lo is None else lo}, "
                               f"{'inf' if hi is None else hi}]")
    return p


def no_parameter_message(model, name) -> str:
    """Why ``name`` cannot be set: a structural zero, a derived parameter, a variable,
    or a name the model does not have (with "did you mean")."""
    zeros = model.meta.get("structural_zeros", ())
    if name in zeros:
        why = (" (it was 0 at compile time and was evaluated as a structural zero: "
               "compile with a non-zero value to tune it)")
    elif name in model.derived_parameters:
        why = " (it is bound to other parameters by an expression: change those)"
    elif name in model.outputs:
        why = " (it is a variable, not a parameter)"
    else:
        why = suggestion(str(name), model.param_names)
    leaf = str(name).split(".")[-1]
    close = [n for n in model.param_names if n.split(".")[-1] == leaf and n != name]
    hint = f"; parameters named {leaf}: {listed(close, 6)}" if close else ""
    return f"the model has no tunable parameter '{name}'{why}{hint}"


def _by_element(values: dict, names: list) -> dict:
    """``{"M": matrix}`` for a parameter array M as ``{"M[0,0]": ..., ...}``; a value of
    another shape is an InvalidValue naming both shapes."""
    out = {}
    for name, value in values.items():
        array = None if name in names else array_of_name(name, names)
        if array is None:
            out[name] = value
            continue
        shape, elements = array
        given = np.shape(value)
        if given != shape:
            raise InvalidValue(f"parameter array '{name}' has shape {shape}, the value "
                               f"given has shape {given}")
        out.update(zip(elements, np.asarray(value).ravel().tolist()))
    return out


def _real_value(name, value, kind=None) -> float:
    """A parameter's new value as the float p holds: a Boolean parameter's True/False as
    1/0, an Integer's whole number, a Real's real number."""
    if kind in ("Boolean", "Integer"):
        try:
            return float(typed_value(value, bool if kind == "Boolean" else int,
                                     f"parameter '{name}'"))
        except ValueError as err:
            raise InvalidValue(str(err)) from None
    if isinstance(value, (bool, np.bool_, complex, np.complexfloating)) or \
            not isinstance(value, (int, float, np.number)):
        raise InvalidValue(f"parameter '{name}' must be a real number, got {value!r} "
                         f"({type(value).__name__})")
    x = float(value)
    if not math.isfinite(x):
        raise InvalidValue(f"parameter '{name}' must be finite, got {value!r}")
    return x
