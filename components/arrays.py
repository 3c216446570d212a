"""Arrays of variables and parameters: Modelica's ``Real q[n]`` and ``parameter Real M[2,2]``.

``ac.Variable(shape=(n,), ...)`` declares n unknowns and ``ac.Parameter(np.array(...))``
(or ``shape=``) a matrix of constants.  Read on a component, such a declaration is a numpy
array of the elements' symbols, so equations use numpy's notation and its rules::

    ac.Eq(self.M @ ac.der(self.v) + self.C @ self.v + self.K @ self.q, 0)
    ac.Eq(ac.der(self.q), self.v)          # one equation per element
    ac.Eq(self.q[0], 0.0)                  # an element; slices (self.q[1:]) work too

A shape is a tuple of sizes; a size is an int or the name of an attribute of the
component (``shape="n"`` is Modelica's ``Real x[n]`` with a structural ``n`` that
``__init__`` sets), or the whole shape is a function of the component.

Flattening turns every array into scalars named by their element, ``q[0]``, ``M[1,0]``,
with Python's 0-based indices: the name in results, reports and ``param_names`` is the
expression that reads the element in the model's code (and the names of lists of
sub-components, ``masses[0].s``, count from 0 too).  The structural passes therefore
see only scalars.

Attributes (start, fixed, nominal, min, max, state_select) are each a scalar, applied to
every element, or an array broadcast to the declaration's shape; unit and description
are one string for the whole array.  Every element of a parameter array is a tunable
parameter after compilation, a zero element included (a scalar parameter that is 0 is a
structural zero; an element of a matrix is usually 0 by its value, not by the model's
structure).

Errors: an equation between arrays of different shapes is ``InvalidEquation``, a value
of the wrong shape ``InvalidValue``, an index out of range ``InvalidIndex``, an array
where one value is expected (``ac.Eq(x, self.q)`` for a scalar x, ``ac.sin`` of a
non-array function...) ``InvalidEquation``; each names the component and the shapes.
"""
from __future__ import annotations

import itertools
import operator
from dataclasses import replace

import numpy as np

from .attributes import VariableAttributes
from .values import bound_violation, check_parameter_value, real_number, ref
from ..errors import InvalidEquation, InvalidIndex, InvalidValue, ModelError

__all__ = ["InvalidIndex", "SymbolArray", "ArrayAttributes", "declared_shape", "shape_of",
           "symbol_array", "element_index", "elements", "array_equations",
           "elementwise", "parameter_array", "check_array_value", "check_array_declaration",
           "array_of_name"]


# -- shapes ------------------------------------------------------------------------------
def declared_shape(shape):
    """The declaration's shape as given, normalized: None (a scalar), a tuple of sizes
    (ints >= 0 or attribute names), or a function of the component.  InvalidValue if
    not."""
    if shape is None or callable(shape):
        return shape
    if isinstance(shape, (int, np.integer, str)):
        shape = (shape,)
    if not isinstance(shape, (tuple, list)):
        raise InvalidValue(f"shape = {shape!r} must be a tuple of sizes (ints or names of "
                         "attributes of the component)")
    out = []
    for size in shape:
        if isinstance(size, str) and size.isidentifier():
            out.append(size)
        elif isinstance(size, (int, np.integer)) and not isinstance(size, bool) and size >= 0:
            out.append(int(size))
        else:
            raise InvalidValue(f"shape = {tuple(shape)!r}: a size is an int >= 0 or the name "
                             f"of an attribute of the component, not {size!r}")
    return tuple(out) if out else None


def shape_of(decl, comp, name: str) -> tuple:
    """The shape of declaration ``decl`` on component ``comp`` as a tuple of ints."""
    shape = decl.shape
    if callable(shape):
        try:
            shape = shape(comp)
        except Exception as err:   # the user's function: say whose it is
            raise InvalidValue(f"{comp._describe()}: the shape of {name} raised "
                               f"{type(err).__name__}: {err}") from err
    sizes = []
    for size in (shape if isinstance(shape, (tuple, list)) else (shape,)):
        if isinstance(size, str):
            if not hasattr(comp, size):
                raise InvalidValue(f"{comp._describe()}: the shape of {name} uses '{size}', "
                                   f"which the component does not have (set self.{size} "
                                   "in __init__ before the model is compiled)")
            size = getattr(comp, size)
        if isinstance(size, bool) or not isinstance(size, (int, np.integer)) or size < 0:
            raise InvalidValue(f"{comp._describe()}: the shape of {name} has the size "
                               f"{size!r}; a size is an int >= 0")
        sizes.append(int(size))
    return tuple(sizes)


def element_index(index: tuple) -> str:
    """``[0]``, ``[1,0]``: the index as element names write it."""
    return "[" + ",".join(str(i) for i in index) + "]"


def elements(shape: tuple):
    """The indices of an array of ``shape`` in row-major (C) order."""
    return itertools.product(*(range(n) for n in shape))


def array_of_name(name: str, known) -> tuple[tuple, list] | None:
    """(shape, element names in row-major order) of the array ``name`` among the element
    names ``known`` (``q`` -> ``q[0]``, ``q[1]`` ...), or None if it has no elements."""
    prefix = name + "["
    found = {}
    for n in known:
        if n.startswith(prefix) and n.endswith("]"):
            inner = n[len(prefix):-1]
            try:
                found[tuple(int(i) for i in inner.split(","))] = n
            except ValueError:
                continue
    if not found:
        return None
    ndims = {len(k) for k in found}
    if len(ndims) != 1:
        return None
    shape = tuple(max(k[d] for k in found) + 1 for d in range(ndims.pop()))
    names = [found.get(idx) for idx in elements(shape)]
    if any(n is None for n in names):
        return None
    return shape, names


# -- the symbols ---------------------------------------------------------------------------
class SymbolArray(np.ndarray):
    """A numpy object array of sympy expressions whose out-of-range indices raise
    ``InvalidIndex`` naming the array (numpy's IndexError names neither)."""

    def __new__(cls, values, name: str = ""):
        obj = np.asarray(values, dtype=object).view(cls)
        obj.name = name
        return obj

    def __array_finalize__(self, obj):
        # a result or a view of an array is no longer the declared array
        self.name = ""

    def __getitem__(self, index):
        try:
            return super().__getitem__(index)
        except IndexError as err:
            what = f"'{self.name}'" if self.name else "an array"
            raise InvalidIndex(f"index {_show_index(index)} is out of range for {what} of "
                               f"shape {self.shape} (indices count from 0, as in Python): "
                               f"{err}") from None

    def __repr__(self):
        return f"{self.name or 'array'} of shape {self.shape}: {np.asarray(self).tolist()!r}"

    # numpy's comparisons of object arrays ask each relation for a truth value, which a
    # relation between symbols has not: keep them as an array of relations
    def __lt__(self, other):
        return SymbolArray(np.frompyfunc(operator.lt, 2, 1)(np.asarray(self), other))

    def __le__(self, other):
        return SymbolArray(np.frompyfunc(operator.le, 2, 1)(np.asarray(self), other))

    def __gt__(self, other):
        return SymbolArray(np.frompyfunc(operator.gt, 2, 1)(np.asarray(self), other))

    def __ge__(self, other):
        return SymbolArray(np.frompyfunc(operator.ge, 2, 1)(np.asarray(self), other))

    def __bool__(self):
        # `if self.q:` or `self.q > 0` in a condition: a relation needs one value
        raise InvalidEquation(f"{self.name or 'an array'} of shape {self.shape} used where "
                              "one value or condition is expected; index it (q[0]) or "
                              "compare element by element")


def _show_index(index) -> str:
    return repr(index) if not isinstance(index, tuple) else \
        "[" + ", ".join(repr(i) for i in index) + "]"


def symbol_array(comp, name: str, decl) -> SymbolArray:
    """The symbols of array ``name`` of ``comp``, named ``path.name[i,j]``."""
    key = ("array", name)
    cached = comp._symbols.get(key)
    if cached is not None:
        if cached.size:
            comp._symbol(f"{name}{element_index((0,) * cached.ndim)}")   # model checks
        return cached
    shape = shape_of(decl, comp, name)
    syms = np.empty(shape, dtype=object)
    for idx in elements(shape):
        syms[idx] = comp._symbol(f"{name}{element_index(idx)}")
    arr = SymbolArray(syms, f"{comp.path}.{name}" if comp.path else name)
    arr.flags.writeable = False     # the declaration's symbols, shared by every read
    comp._symbols[key] = arr
    return arr


def elementwise(function, value):
    """``function`` applied to each element of an array (the result an array)."""
    out = np.empty(value.shape, dtype=object)
    for idx in elements(value.shape):
        out[idx] = function(value[idx])
    return SymbolArray(out)


# -- equations -------------------------------------------------------------------------------
def array_equations(lhs, rhs, label, make) -> list:
    """``ac.Eq`` between arrays: one equation per element, ``make(l, r, label)`` each.

    Both sides have the same shape; a number (no variable) may stand for every element
    (``ac.Eq(self.q, 0)``).  A scalar expression against an array is a shape mismatch,
    as in Modelica: broadcasting a variable to n equations is rarely what was meant."""
    lhs, rhs = (np.array(v, dtype=object) if isinstance(v, (list, tuple)) else v
                for v in (lhs, rhs))
    ls, rs = _shape(lhs), _shape(rhs)
    if ls != rs and not ((ls == () and _is_number(lhs)) or (rs == () and _is_number(rhs))):
        raise InvalidEquation(f"ac.Eq(lhs, rhs) between sides of different shapes: the "
                              f"left side {_shape_text(ls)}, the right side "
                              f"{_shape_text(rs)}; left: {_brief(lhs)}, right: {_brief(rhs)}"
                              + ("" if ls and rs else " (for the same value in every "
                                 "element, multiply it by np.ones(shape))"))
    shape = ls if ls != () else rs
    lhs, rhs = np.broadcast_to(np.asarray(lhs, dtype=object), shape), \
        np.broadcast_to(np.asarray(rhs, dtype=object), shape)
    return [make(lhs[idx], rhs[idx], None if label is None else label + element_index(idx))
            for idx in elements(shape)]


def _shape_text(shape: tuple) -> str:
    return f"has shape {shape}" if shape else "is a scalar"


def _shape(value) -> tuple:
    return value.shape if isinstance(value, np.ndarray) else ()


def _is_number(value) -> bool:
    if isinstance(value, np.ndarray):
        value = value.item()
    free = getattr(value, "free_symbols", None)
    return not free and not hasattr(value, "_sympy_")


def _brief(value) -> str:
    if isinstance(value, SymbolArray) and value.name:
        return value.name
    text = repr(np.asarray(value).tolist()) if isinstance(value, np.ndarray) else str(value)
    return text if len(text) <= 60 else text[:57] + "..."


# -- parameter values --------------------------------------------------------------------
def check_array_value(value, shape: tuple, what: str) -> np.ndarray:
    """``value`` (a number, an array or nested lists, of numbers or parameter
    expressions) broadcast to ``shape`` as an object array; ValueError naming ``what``
    and both shapes, or the element whose value is not valid."""
    if callable(value) and not isinstance(value, np.ndarray) \
            and not hasattr(value, "free_symbols"):
        return value                      # a function of the component: checked when read
    try:
        arr = np.array(value, dtype=object)
    except ValueError:
        raise ValueError(f"{what} = {value!r} is not a regular array") from None
    if arr.shape != shape and arr.ndim > 0:
        raise ValueError(f"{what} has shape {arr.shape}, but it is declared with shape "
                         f"{shape}")
    arr = np.broadcast_to(arr, shape)
    for idx in elements(shape):
        check_parameter_value(arr[idx], f"{what}{element_index(idx)}")
    return arr


def check_array_declaration(decl) -> None:
    """The value (where the shape is known), min and max of an array parameter's
    declaration, element by element; ValueError naming the first bad one."""
    bounds = {}
    for what in ("min", "max"):
        try:
            bounds[what] = np.array(getattr(decl, what), dtype=object)
        except ValueError:
            raise ValueError(f"{what} = {getattr(decl, what)!r} is not a regular array") \
                from None
        for idx in elements(bounds[what].shape):
            if bounds[what][idx] is not None:
                real_number(bounds[what][idx], f"{what}{element_index(idx) if idx else ''}")
    concrete = not callable(decl.shape) and all(isinstance(n, int) for n in decl.shape)
    shape = decl.shape if concrete else np.broadcast_shapes(*(b.shape for b in
                                                              bounds.values()))
    values = check_array_value(decl.value, shape, "default value") if concrete else None
    if callable(values):              # a function of the component: checked when read
        values = None
    try:
        lo, hi = (np.broadcast_to(b, shape) for b in bounds.values())
    except ValueError:
        raise ValueError(f"min/max of shapes {bounds['min'].shape}, {bounds['max'].shape} "
                         f"do not fit the shape {shape}") from None
    for idx in elements(shape):
        if lo[idx] is not None and hi[idx] is not None and lo[idx] > hi[idx]:
            raise ValueError(f"min{element_index(idx)} = {lo[idx]!r} is greater than "
                             f"max{element_index(idx)} = {hi[idx]!r}")
        value = None if values is None else values[idx]
        if isinstance(value, (int, float, np.integer, np.floating)) \
                and not isinstance(value, bool):
            why = bound_violation(float(value), lo[idx], hi[idx])
            if why:
                raise ValueError(f"default value{element_index(idx)} {value!r} {why}")


def parameter_array(comp, name: str, decl) -> np.ndarray:
    """The values of parameter array ``name`` of ``comp``, one per element (numbers or
    sympy expressions of parameters, a ``ref`` resolved to the enclosing array)."""
    shape = shape_of(decl, comp, name)
    value = comp._param_values.get(name, decl.value)
    if isinstance(value, ref):
        value = comp._referenced(name, value)
    elif callable(value) and not hasattr(value, "free_symbols") \
            and not isinstance(value, np.ndarray):
        try:
            value = value(comp)
        except ModelError:
            raise
        except Exception as err:
            raise InvalidValue(f"{comp._describe()}: evaluating parameter {name} raised "
                               f"{type(err).__name__}: {err}") from err
    if value is None:
        raise ModelError(f"parameter '{name}' of {comp._describe()} has no value")
    try:
        return check_array_value(value, shape, f"parameter {name}")
    except ValueError as err:
        raise InvalidValue(f"{comp._describe()}: {err}") from None


# -- variable attributes --------------------------------------------------------------------
_PER_ELEMENT = ("start", "fixed", "nominal", "min", "max", "state_select")


class ArrayAttributes(VariableAttributes):
    """The attributes of an array variable: each of start, fixed, nominal, min, max and
    state_select a scalar (every element) or nested lists broadcast to the shape."""

    def modified(self, mod) -> "ArrayAttributes":
        """A number or array sets start; a dict any attributes (each scalar or array)."""
        if isinstance(mod, dict):
            return self.with_attributes(mod)
        if isinstance(mod, (str, set, dict)) or mod is None:
            raise ValueError(f"a modification of an array variable is its start value (a "
                             f"number or an array) or a dict of its attributes, not {mod!r}")
        return replace(self, start=mod).checked()

    def checked(self) -> "ArrayAttributes":
        """Array-valued attributes as nested lists, each element checked as a scalar
        variable's (start within [min, max] element by element)."""
        values = {}
        for name in _PER_ELEMENT:
            v = getattr(self, name)
            if isinstance(v, (np.ndarray, list, tuple)):
                try:
                    v = np.array(v, dtype=object)
                except ValueError:
                    raise ValueError(f"{name} = {v!r} is not a regular array") from None
                values[name] = v.tolist() if v.ndim else v.item()
            else:
                values[name] = v
        out = replace(self, **values)
        try:
            shape = np.broadcast_shapes(*(np.shape(values[n]) for n in _PER_ELEMENT))
        except ValueError:
            shapes = {n: np.shape(values[n]) for n in _PER_ELEMENT if np.shape(values[n])}
            raise ValueError(f"attribute arrays of different shapes: {shapes}") from None
        for idx in elements(shape):
            try:
                out._scalar(shape, idx)
            except ValueError as err:
                raise ValueError(f"element {element_index(idx)}: {err}") from None
        return out

    def _scalar(self, shape: tuple, idx: tuple) -> VariableAttributes:
        given = {n: np.broadcast_to(np.array(getattr(self, n), dtype=object), shape)[idx]
                 for n in _PER_ELEMENT}
        return VariableAttributes(unit=self.unit, description=self.description,
                                  discrete=self.discrete, **given).checked()

    def element(self, shape: tuple, idx: tuple, what: str) -> VariableAttributes:
        """The attributes of element ``idx`` of an array of ``shape``; ValueError if an
        attribute array does not fit the shape."""
        for n in _PER_ELEMENT:
            s = np.shape(getattr(self, n))
            if s and s != shape[len(shape) - len(s):]:
                raise ValueError(f"{what}: attribute {n} has shape {s}, the variable has "
                                 f"shape {shape}")
        return self._scalar(shape, idx)
