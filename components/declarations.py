"""Declarations inside a component class: Parameter and Variable.

A declaration is a descriptor.  Read on a bound instance it yields that instance's
sympy Symbol, named by the dotted path (``motor.R.R``), so equations read like the book:
``self.v - self.R*self.i``.  Values (parameter values, start values) live on the
instance and can be modified when a component is instantiated.

Values are checked, never coerced (:mod:`acausal.components.values`: a ``bool`` is not
a real number, nor is a string, a list, a complex number or NaN); a variable's
attributes are Modelica's (:mod:`acausal.components.attributes`); an array declaration's
elements are checked one by one (:mod:`acausal.components.arrays`).
"""
from __future__ import annotations

import contextvars
import numbers
from dataclasses import fields

import numpy as np

from .arrays import ArrayAttributes, check_array_declaration, declared_shape, symbol_array
from .attributes import VariableAttributes
from .initparams import check_free_declaration, parameter_attributes
from .values import (TYPE_NAMES, bound_violation, check_parameter_value,
                     check_structural_value, is_symbolic, real_number, ref, typed_value,
                     value_type_checked)

# The root of the model being flattened, set by components.component.compiling
COMPILING = contextvars.ContextVar("acausal_compiling", default=None)

# the value checks and the attributes (modules of their own) are public names here too
__all__ = ["Parameter", "Variable", "Across", "Through", "Signal", "VariableAttributes", "ref",
           "real_number", "check_parameter_value", "check_structural_value",
           "bound_violation", "is_symbolic", "typed_value", "TYPE_NAMES"]


def _is_real(value) -> bool:
    try:
        real_number(value, "")
        return True
    except ValueError:
        return False


class _Declaration:
    """Common descriptor machinery: the attribute name and the per-instance symbol."""

    name: str = None

    def __set_name__(self, owner, name):
        self.name = name

    shape = None     # an array declaration's shape (see components.arrays)

    def __get__(self, instance, owner=None):
        if instance is None:
            return self
        if self.shape is not None:
            return symbol_array(instance, self.name, self)
        # the symbol made before, read here (every equation reads several): the
        # component makes it, and says what is wrong when none can be read
        sym = instance._symbols.get(self.name)
        if sym is not None:
            active = COMPILING.get()
            if active is None or instance._root is active:
                return sym
        return instance._symbol(self.name)


def _declared_shape(shape):
    return None if shape is None else declared_shape(shape)


class Parameter(_Declaration):
    """A constant of the model, with a value that can be modified per instance.

    ``Parameter(1.0, unit="Ohm", min=0, description="resistance")``.  A value may also
    be an expression of other parameters of the same component, given as a function of
    the component: ``Parameter(lambda c: c.J_m + c.J_L)``, or bound to the enclosing
    component's parameter with ``ref``.  ``min`` and ``max`` are enforced when the model
    is flattened.  An infinite value is accepted where the equations stay finite with it
    (a time constant in ``1/Tt``, an output limit); a bool is not a real number.
    An array value (``Parameter(np.eye(2))``) or ``shape=`` declares an array of
    parameters, one tunable parameter per element (:mod:`acausal.components.arrays`).

    ``type=bool`` declares a Boolean parameter (True or False; a bool default declares
    one: ``Parameter(False)``), ``type=int`` an Integer parameter (a whole number).  In
    equations they are 1/0 and the whole number; a Boolean parameter is a condition
    (``ac.if_else(self.use_limit, ...)``).

    ``choices=(...)`` declares a structural parameter that takes one of the given values
    (strings: an enumeration such as the MSL's ``initType``, ``ac.Init``).

    ``structural=True`` declares a parameter that shapes the model rather than entering
    its equations (a number of segments, the coefficients of a transfer function): its
    value is a plain Python value (a number or a bool, or a list or tuple of them)
    fixed when the component is made; ``self.name`` reads that value, and the
    component's ``build()`` creates the sub-components it implies.  It is not a
    parameter of the compiled model (changing it means a new model).

    ``fixed=False`` declares a parameter found by initialization (Modelica's
    ``parameter Real c(fixed=false, start=100)``): an unknown of the initial system,
    determined by an initial equation, its ``start`` (else its value) Newton's guess,
    then a constant of the run (:mod:`acausal.components.initparams`).
    """

    def __init__(self, value=None, unit: str = "", description: str = "",
                 min: float | None = None, max: float | None = None, shape=None,
                 structural: bool = False, type=None, choices=None, fixed: bool = True,
                 start=None):
        structural = bool(structural) or choices is not None
        self.fixed, self.start = fixed, start
        self.choices = tuple(choices) if choices is not None else None
        if type is None:
            type = bool if isinstance(value, (bool, np.bool_)) and not structural else float
        self.type = type
        if shape is None and not structural and isinstance(value, (np.ndarray, list, tuple)):
            shape = np.shape(value)      # a matrix parameter: its shape from its value
        self.shape = _declared_shape(shape)
        self.value = value
        self.unit = unit
        self.description = description
        self.min = min
        self.max = max
        self.structural = structural

    def __get__(self, instance, owner=None):
        if instance is None or not self.structural:
            return super().__get__(instance, owner)
        return instance._structural.get(self.name, self.value)

    def __repr__(self):
        # help() lists a declaration by its repr: show what it declares
        args = [repr(shown_value(self.value))]
        args += [f"{k}={getattr(self, k)!r}" for k in ("unit", "min", "max", "description")
                 if getattr(self, k) not in (None, "")]
        if self.type is int:
            args.append("type=int")
        if not self.fixed:
            args += ["fixed=False"] + ([f"start={self.start!r}"] if self.start is not None else [])
        if self.shape is not None and not isinstance(self.value, (np.ndarray, list, tuple)):
            args.append(f"shape={self.shape!r}")
        return f"Parameter({', '.join(args)})"

    def attributes_modified(self, comp, name, mod):
        """The value ``comp``'s parameter keeps after the modification ``mod``: ``mod``
        itself, or for a dict of attributes (``fixed``, ``start``) the value it had."""
        if not isinstance(mod, dict):
            return mod
        return parameter_attributes(comp, name, mod, self)

    def check(self) -> None:
        """ValueError unless the declaration is consistent (checked once per class)."""
        check_free_declaration(self)
        if self.structural:
            check_structural_value(self.value, "default value", self.min, self.max,
                                   self.choices)
            return
        value_type_checked(self.type)
        if self.type is not float and self.shape is not None:
            raise ValueError(f"a {TYPE_NAMES[self.type]} parameter is a scalar (arrays of "
                             "them are not supported)")
        if self.shape is not None:
            check_array_declaration(self)    # value, min and max element by element
        else:
            self._check_scalar()
        for name in ("unit", "description"):
            if not isinstance(getattr(self, name), str):
                raise ValueError(f"{name} = {getattr(self, name)!r} must be a string")

    def _check_scalar(self) -> None:
        check_parameter_value(self.value, "default value", self.type)
        if self.type is bool and (self.min is not None or self.max is not None or self.unit):
            raise ValueError("a Boolean parameter has no unit, min or max")
        lo = None if self.min is None else real_number(self.min, "min")
        hi = None if self.max is None else real_number(self.max, "max")
        if lo is not None and hi is not None and lo > hi:
            raise ValueError(f"min = {self.min!r} is greater than max = {self.max!r}")
        if _is_real(self.value):
            why = bound_violation(float(self.value), self.min, self.max)
            if why:
                raise ValueError(f"default value {self.value!r} {why}")


class Variable(_Declaration):
    """An unknown of the model (a time function).

    ``Variable(start=0.0, fixed=False, unit="V", nominal=1.0, state_select="default")``:
    ``start`` is the initial value (or the guess, when ``fixed`` is False and the value
    is determined by equations), ``nominal`` scales error weights, ``state_select`` is
    the user's hint for state selection (never/avoid/default/prefer/always).
    ``discrete=True`` declares a discrete-time variable: held between events, changed
    only by ``ac.assign`` in a when-clause, its start value the value before the first
    one (Modelica's ``discrete``).  The attributes are checked when the class is created
    (``VariableAttributes.checked``).  ``shape=(n,)`` declares an array of variables,
    each attribute a scalar for every element or an array
    (:mod:`acausal.components.arrays`).

    ``type=bool`` declares a Boolean variable, ``type=int`` an Integer one (Modelica's
    ``Boolean`` and ``Integer``): discrete by nature, they keep their value between
    events and change only at events, either by an equation ``ac.Eq(y, expr)`` that
    has the variable alone on its left (evaluated at every event, relations in it
    generating events) or by ``ac.assign`` in a when-clause.  Their start value
    (``False``, ``0`` by default) is ``pre(y)`` at the start.
    """

    kind = "variable"

    def __init__(self, start: float | None = None, fixed: bool | None = None, unit: str = "",
                 nominal: float | None = None, min: float | None = None,
                 max: float | None = None, state_select: str = "default",
                 description: str = "", discrete: bool = False, shape=None, type=float):
        self.shape = _declared_shape(shape)
        if type is not float and self.shape is not None:
            raise ValueError("Boolean and Integer variables are scalars (arrays of them "
                             "are not supported)")
        if self.shape is not None:
            attributes = ArrayAttributes     # per-element attributes
        else:
            attributes = VariableAttributes
        self.attributes = attributes(
            start=start, fixed=fixed, unit=unit, nominal=nominal, min=min, max=max,
            state_select=state_select, description=description, discrete=discrete,
            **({} if type is float else {"type": type}))

    @property
    def type(self):
        """float, bool or int: the variable's value type (Real, Boolean, Integer)."""
        return getattr(self.attributes, "type", float)

    def __repr__(self):
        a, default = self.attributes, VariableAttributes()
        args = [f"{f.name}={getattr(a, f.name)!r}" for f in fields(a)
                if getattr(a, f.name) != getattr(default, f.name)]
        if self.shape is not None:
            args.append(f"shape={self.shape!r}")
        return f"{type(self).__name__}({', '.join(args)})"

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


# -- what help(), inspect.signature and repr show of a component class -----------------------
# Built from the declarations when a class is created (Component.__init_subclass__), so no
# component writes its own signature or parameter list and none can drift from the code.

class _Shown:
    """A default value as the signature prints it (``computed`` for a function of the
    component, whose value exists only once the component is part of a model)."""

    def __init__(self, text: str):
        self.text = text

    def __repr__(self):
        return self.text


def shown_value(value):
    """A parameter value as help(), the signature and repr print it."""
    if isinstance(value, ref) or value is None:
        return value
    if isinstance(value, np.ndarray):
        return _Shown(repr(value.tolist()))     # on one line, as the array is written
    if callable(value) and not is_symbolic(value) and not isinstance(value, numbers.Number):
        return _Shown("computed")
    return value


def parameter_signature(cls, parameters: dict):
    """``inspect.Signature`` of ``cls(...)``: the arguments of its own ``__init__`` (a
    structural argument such as a number of segments), then every parameter as a
    keyword-only argument with its default (annotated ``float [unit]``),
    then ``**modifications`` (start values of variables, dicts for sub-components)."""
    import inspect

    init = inspect.signature(cls.__init__)
    own = [p for p in list(init.parameters.values())[1:]]
    if own and own[-1].kind is inspect.Parameter.VAR_KEYWORD:
        var_kw = own.pop().replace(name="modifications")
    elif not own:
        var_kw = inspect.Parameter("modifications", inspect.Parameter.VAR_KEYWORD)
    else:                           # an __init__ that takes no modifications at all
        return init.replace(parameters=own)
    taken = {p.name for p in own}
    keyword = []
    for name, decl in parameters.items():
        if name in taken or not name.isidentifier():
            continue
        kind = _kind(decl)
        annotation = _Shown(f"{kind} [{decl.unit}]") if decl.unit else \
            (float if kind == "float" else _Shown(kind))
        keyword.append(inspect.Parameter(name, inspect.Parameter.KEYWORD_ONLY,
                                         default=shown_value(decl.value),
                                         annotation=annotation))
    # keyword-only arguments go after *args, if the own __init__ has it
    positional = [p for p in own if p.kind is not inspect.Parameter.KEYWORD_ONLY]
    own_kw = [p for p in own if p.kind is inspect.Parameter.KEYWORD_ONLY]
    return inspect.Signature(positional + own_kw + keyword + [var_kw])


# the headings of the sections declaration_doc appends to a class's own docstring
SECTION_HEADINGS = ("Parameters", "Variables", "Ports and sub-components")


def own_docstring(cls) -> str:
    """The docstring a component class was written with, without the sections that
    ``declaration_doc`` appended (for pages that show the declarations another way)."""
    import inspect
    doc = inspect.cleandoc(vars(cls).get("__doc__") or "")
    for heading in SECTION_HEADINGS:
        doc = doc.split(f"\n\n{heading}\n{'-' * len(heading)}\n")[0]
    return doc


def _shape(shape) -> str:
    if callable(shape):
        return "(computed)"
    return "[" + ", ".join(str(n) for n in shape) + "]"


def _kind(decl) -> str:
    """``float``, ``structural``, or ``array [2, 2]`` / ``array [n]`` for an array
    parameter."""
    if getattr(decl, "structural", False):
        return "structural"
    if getattr(decl, "type", float) is not float:
        return decl.type.__name__
    return "float" if decl.shape is None else f"array {_shape(decl.shape)}"


def _unit(text: str) -> str:
    return f" [{text}]" if text else ""


def declaration_doc(own_doc: str | None, parameters: dict, variables: dict,
                    children: dict) -> str:
    """The class docstring (its physics and source) followed by numpydoc sections that
    list the parameters (default, unit, bounds, description), the variables (unit, start)
    and the ports and sub-components, as ``help()`` shows them."""
    import inspect
    text = inspect.cleandoc(own_doc) if own_doc else ""
    sections = []
    if parameters:
        lines = [SECTION_HEADINGS[0], "-" * len(SECTION_HEADINGS[0])]
        for name, d in parameters.items():
            bounds = ", ".join(b for b in (f"min {d.min!r}" if d.min is not None else "",
                                           f"max {d.max!r}" if d.max is not None else "") if b)
            lines.append(f"{name} : {_kind(d)}{_unit(d.unit)}, "
                         f"default {shown_value(d.value)!r}"
                         + (f" ({bounds})" if bounds else ""))
            if d.description:
                lines.append(f"    {d.description}")
        sections.append("\n".join(lines))
    if variables:
        lines = [SECTION_HEADINGS[1], "-" * len(SECTION_HEADINGS[1])]
        for name, v in variables.items():
            a = v.attributes
            extra = [f"start {a.start!r}" if a.start is not None else "",
                     "fixed" if a.fixed else "",
                     f"state_select {a.state_select}" if a.state_select != "default" else ""]
            extra = ", ".join(e for e in extra if e)
            shape = "" if v.shape is None else f" array {_shape(v.shape)}"
            typ = "" if v.type is float else f" {TYPE_NAMES[v.type]}"
            lines.append(f"{name} : {v.kind}{typ}{shape}{_unit(a.unit)}"
                         + (f", {extra}" if extra else ""))
            if a.description:
                lines.append(f"    {a.description}")
        sections.append("\n".join(lines))
    if children:
        lines = [SECTION_HEADINGS[2], "-" * len(SECTION_HEADINGS[2])]
        lines += [f"{name} : {type(c.component).__name__} (if "
                  f"{'' if c.when else 'not '}{c.flag})"
                  if hasattr(c, "flag") else f"{name} : {type(c).__name__}"
                  for name, c in children.items()]
        sections.append("\n".join(lines))
    return "\n\n".join(s for s in [text, *sections] if s)
