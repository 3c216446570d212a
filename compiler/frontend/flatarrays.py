"""Flattening of array declarations: one scalar variable or parameter per element.

The element ``(i, j)`` of ``M`` in component ``c`` is the scalar ``c.M[i,j]`` (Python's
0-based indices, see :mod:`acausal.components.arrays`), so every pass after flattening
sees scalars only.  Elements of parameter arrays are ``ArrayElement``s: they stay
tunable when their value is 0 instead of becoming structural zeros.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...components.arrays import elements, parameter_array
from ...components.component import InvalidValue, Port
from ...components.declarations import Parameter
from .flatten import FlatParameter, FlatVariable

__all__ = ["collect_array", "ArrayElement"]


@dataclass
class ArrayElement(FlatParameter):
    """An element of a parameter array: a tunable parameter even when its value is 0
    (a matrix has zeros by its values, which tuning may change, not by structure)."""

    tunable = True


def collect_array(comp, name: str, decl, flat) -> None:
    """One scalar per element, named ``name[i,j]`` (see components.arrays)."""
    syms = getattr(comp, name)
    if isinstance(decl, Parameter):
        values = parameter_array(comp, name, decl)
        try:
            lo = np.broadcast_to(np.array(decl.min, dtype=object), syms.shape)
            hi = np.broadcast_to(np.array(decl.max, dtype=object), syms.shape)
        except ValueError:
            raise InvalidValue(f"{comp._describe()}: min/max of parameter {name} do not "
                               f"fit its shape {syms.shape}") from None
        for idx in elements(syms.shape):
            sym = syms[idx]
            flat.parameters.append(ArrayElement(
                sym.name, sym, values[idx], decl.unit, decl.description, comp.path,
                type(comp).__name__, lo[idx], hi[idx]))
        return
    if isinstance(comp, Port):
        raise InvalidValue(f"{comp._describe()}: port variable {name} is an array; a port "
                           "carries scalars (use a list of ports for several)")
    attrs = comp.variable_attributes(name)
    for idx in elements(syms.shape):
        sym = syms[idx]
        try:
            element = attrs.element(syms.shape, idx, f"variable {name}")
        except ValueError as err:
            raise InvalidValue(f"{comp._describe()}: {err}") from None
        flat.variables.append(FlatVariable(sym.name, sym, element, comp.path,
                                           type(comp).__name__, decl.kind))
