"""Modifications checked where the instance is made.

``Resistor(r=5)``, ``Resistor(R=[1, 2])``, ``Resistor(R=-1)`` (below its minimum),
``Resistor(R=float("nan"))`` and ``Drive(motor={"Ra": {"R": "x"}})`` fail at the line
that wrote them, with the names the user wrote: ``NotInModel`` for a name the component
does not have (with difflib's "did you mean 'R'?"), ``InvalidValue`` for a value that
is not a real number, NaN, outside the declared [min, max], or a sub-component
modification that is not a dict.  A value given as a string with a unit,
``Resistor(R="2 kOhm")``, ``Inertia(w={"start": "60 rpm"})``, is converted to the
declared unit (``components.units``).

Only what the modification itself decides is checked here; a value that is an
expression of other parameters (``ref``, a function of the component, a sympy
expression) is checked by flattening, where the values it uses are known.
"""
from __future__ import annotations

import math

from .declarations import Parameter, Signal, Variable
from .declared import class_declarations, class_structurals, constructor_arguments
from .initparams import attribute_values
from .units import convert_value, has_unit
from .values import bound_violation, check_parameter_value, is_symbolic
from ..errors import InvalidValue, NotInModel
from ..words import suggestion

__all__ = ["validate_modifications", "suggestion"]


def validate_modifications(comp, mods: dict, where: str) -> dict:
    """``mods`` checked against ``comp``'s declarations and sub-components, with values
    given with units converted; raises NotInModel or InvalidValue naming ``where``
    (``Resistor`` or ``'R1' (Resistor)``) and the declaration."""
    decls = class_declarations(type(comp))
    children = comp._children
    out = {}
    for key, mod in mods.items():
        if key in children:
            child = children[key]
            inner = f"'{_child_path(where, key)}' ({type(child).__name__})"
            if _is_signal_port(child) and not (isinstance(mod, dict) and "signal" in mod):
                mod = {"signal": mod}      # a signal port by its value: FirstOrder(y=1.0)
            if not isinstance(mod, dict):
                raise InvalidValue(f"{where}: modification of sub-component '{key}' must "
                                   f"be a dict of its parameters, got {mod!r}")
            out[key] = validate_modifications(child, mod, inner)
        elif isinstance(decls.get(key), Parameter):
            out[key] = _parameter_value(decls[key], key, mod, where)
        elif isinstance(decls.get(key), Variable):
            allowed = list(decls[key].attributes.__dataclass_fields__)
            for attr in (mod if isinstance(mod, dict) else ()):
                if attr not in allowed:
                    raise InvalidValue(f"{where}: variable '{key}' has no attribute "
                                       f"'{attr}'{suggestion(attr, allowed)} (its "
                                       f"attributes: {', '.join(allowed)})")
            mod = _variable_values(decls[key], key, mod, where)
            try:
                decls[key].attributes.modified(mod)
            except (TypeError, ValueError) as err:
                raise InvalidValue(f"{where}: variable '{key}': {err}") from None
            out[key] = mod
        elif key in constructor_arguments(type(comp)):
            # a structural argument (a port that exists or not) shapes the instance when
            # it is created; a modification comes too late for that
            kind = type(comp).__name__
            raise InvalidValue(f"{where}: '{key}' is an argument of the constructor, not a "
                               f"parameter; give it where the component is created: "
                               f"{kind}({key}={mod!r})")
        elif key in class_structurals(type(comp)):
            raise InvalidValue(f"{where}: '{key}' is a structural parameter, fixed when the "
                               f"component is made: write {type(comp).__name__}({key}=...) "
                               "where it is declared")
        else:
            known = sorted(set(decls) | set(children))
            raise NotInModel(f"{where} has no parameter, variable or sub-component named "
                             f"'{key}'{suggestion(key, known)} (it has: {', '.join(known)})")
    return out


def _is_signal_port(comp) -> bool:
    """A port that carries one signal (RealInput, BooleanOutput, ...: its one declaration
    a ``Signal``): a modification of it that is a number or a dict of attributes is its
    signal's (``FirstOrder(y=1.0)`` starts y at 1, as results name the signal by its
    port)."""
    decls = class_declarations(type(comp))
    return list(decls) == ["signal"] and isinstance(decls["signal"], Signal)


def _child_path(where: str, key: str) -> str:
    if where.startswith("'"):
        return where[1:where.index("'", 1)] + "." + key
    return key


def _parameter_value(decl: Parameter, key: str, value, where: str):
    what = f"parameter {key}"
    if isinstance(value, dict):     # attributes: {"fixed": False, "start": 100}
        return attribute_values(decl, key, value, where)
    if decl.shape is not None:
        # an array parameter: its shape may be the instance's (shape="n"), so its value
        # is checked element by element where it is applied (components.arrays)
        return value
    if isinstance(value, str) and _has_unit(value):
        try:
            value = convert_value(value, decl.unit, what)
        except ValueError as err:
            raise InvalidValue(f"{where}: {err}") from None
    try:
        check_parameter_value(value, what, decl.type)
    except ValueError as err:
        raise InvalidValue(f"{where}: {err}") from None
    if _plain_number(value):
        why = bound_violation(float(value), decl.min, decl.max)
        if why:
            raise InvalidValue(f"{where}: {what} = {value!r} {why}")
    return value


_WITH_UNIT = ("start", "nominal", "min", "max")


def _has_unit(value) -> bool:
    if not isinstance(value, str):
        return False
    return has_unit(value)


def _variable_values(decl: Variable, key: str, mod, where: str):
    """A variable's start value (or start/nominal/min/max in a dict) given with a unit,
    ``Inertia(w="60 rpm")``, converted to the variable's declared unit."""
    unit = decl.attributes.unit

    def converted(value, attr):
        if not _has_unit(value):
            return value          # a number, or what the attribute check rejects
        try:
            return convert_value(value, unit, attr, key)
        except ValueError as err:
            raise InvalidValue(f"{where}: variable '{key}': {err}") from None

    if isinstance(mod, dict):
        return {a: converted(v, a) if a in _WITH_UNIT else v for a, v in mod.items()}
    return converted(mod, "start")


def _plain_number(value) -> bool:
    if value is None or callable(value) and not is_symbolic(value):
        return False
    if is_symbolic(value) and not value.is_number:
        return False
    try:
        return not math.isnan(float(value))
    except (TypeError, ValueError):
        return False
