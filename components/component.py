"""Component: the unit of modelling (Modelica's ``model``), and connect().

A component class declares ports, parameters, variables and sub-components as class
attributes and returns its equations from ``equations()``::

    class Resistor(OnePort):
        '''Ideal linear resistor:  v = R*i  (Ohm's law).'''
        R = ac.Parameter(1.0, unit="Ohm")

        def equations(self):
            return [ac.Eq(self.v, self.R * self.i)]

Instantiation takes modifications, several levels down if needed:
``SeriesRLC(R1={"R": 5.0}, C1={"v": {"start": 1.0, "fixed": True}})``.  A number given
for a variable sets its start value.  Sub-components may also be created in ``__init__``
(for structural parameters such as a number of segments), as attributes or lists.

A component becomes part of a model when the root is bound (``_bind``), which happens in
``acausal.compile``: only then do its variables have their dotted names.
"""
from __future__ import annotations

import copy
from typing import Iterable

import sympy as sp

from .declarations import Parameter, Variable, ref
from .symbols import Equation, When

__all__ = ["Component", "Port", "Connection", "connect", "ModelError"]


class ModelError(ValueError):
    """The model as written is not valid (unknown modification, bad connect, ...)."""


class Component:
    """Base class of every model and component (see the module docstring)."""

    def __init__(self, **modifications):
        object.__setattr__(self, "_mods", dict(modifications))
        object.__setattr__(self, "_path", None)
        object.__setattr__(self, "_children", {})
        object.__setattr__(self, "_symbols", {})
        object.__setattr__(self, "_param_values", {})
        object.__setattr__(self, "_var_attrs", {})
        for name, decl in _class_children(type(self)).items():
            setattr(self, name, decl._clone())

    # -- the instance tree -------------------------------------------------------------
    def __setattr__(self, name, value):
        if isinstance(value, Component):
            self._children[name] = value
        elif _is_component_list(value):
            for i, child in enumerate(value):
                self._children[f"{name}[{i}]"] = child
        object.__setattr__(self, name, value)

    def __new__(cls, *args, **kwargs):
        obj = super().__new__(cls)
        # Remember the constructor call so a class-level declaration can be cloned
        # faithfully, including structural arguments a subclass's __init__ consumes.
        object.__setattr__(obj, "_init_call", (args, copy.deepcopy(kwargs)))
        return obj

    def _clone(self) -> "Component":
        """A fresh, unbound copy of a class-level declaration (same arguments)."""
        args, kwargs = self._init_call
        return type(self)(*args, **copy.deepcopy(kwargs))

    @property
    def path(self) -> str:
        """The dotted path of this instance in the model ('' for the root)."""
        return self._path if self._path is not None else ""

    def children(self) -> dict:
        """Sub-components and ports, in declaration order."""
        return dict(self._children)

    # -- binding: names and modifications ----------------------------------------------
    def _bind(self, path: str = "", parent: "Component | None" = None) -> None:
        object.__setattr__(self, "_path", path)
        object.__setattr__(self, "_parent", parent)
        self._symbols.clear()
        decls = _declarations(type(self))
        for key, mod in self._mods.items():
            self._apply_modification(key, mod, decls)
        for name, child in self._children.items():
            child._bind(f"{path}.{name}" if path else name, self)

    def _apply_modification(self, key, mod, decls):
        if key in self._children:
            if not isinstance(mod, dict):
                raise ModelError(f"{self._describe()}: modification of sub-component "
                                 f"'{key}' must be a dict of its parameters, got {mod!r}")
            child = self._children[key]
            object.__setattr__(child, "_mods", {**child._mods, **mod})
        elif isinstance(decls.get(key), Parameter):
            self._param_values[key] = mod
        elif isinstance(decls.get(key), Variable):
            base = self._var_attrs.get(key, decls[key].attributes)
            try:
                self._var_attrs[key] = base.modified(mod)
            except (TypeError, ValueError) as err:
                raise ModelError(f"{self._describe()}: variable '{key}': {err}") from None
        else:
            known = sorted(set(decls) | set(self._children))
            raise ModelError(f"{self._describe()} has no parameter, variable or "
                             f"sub-component named '{key}' (it has: {', '.join(known)})")

    def _describe(self) -> str:
        where = f"'{self._path}'" if self._path else "the model"
        return f"{where} ({type(self).__name__})"

    def _symbol(self, name: str) -> sp.Symbol:
        sym = self._symbols.get(name)
        if sym is None:
            if self._path is None:
                raise ModelError(
                    f"{type(self).__name__}.{name} has no name yet: a component's "
                    "variables are named when the model is compiled (acausal.compile)")
            full = f"{self._path}.{name}" if self._path else name
            sym = sp.Symbol(full, real=True)
            self._symbols[name] = sym
        return sym

    # -- what the compiler reads -------------------------------------------------------
    def parameter_value(self, name: str):
        if name in self._param_values:
            value = self._param_values[name]
        else:
            value = _declarations(type(self))[name].value
        if isinstance(value, ref):
            parent = getattr(self, "_parent", None)
            if parent is None or value.name not in parent.declarations():
                raise ModelError(f"{self._describe()}: parameter '{name}' refers to "
                                 f"'{value.name}' of the enclosing component, which has none")
            return getattr(parent, value.name)
        return value(self) if callable(value) else value

    def variable_attributes(self, name: str):
        return self._var_attrs.get(name, _declarations(type(self))[name].attributes)

    def declarations(self) -> dict:
        """Parameters and variables declared by this component's class, in order."""
        return _declarations(type(self))

    def equations(self) -> Iterable:
        """The component's equations and connections (override)."""
        return []

    def initial_equations(self) -> Iterable:
        """Equations that hold only at the initial time (override), e.g. der(w) = 0."""
        return []

    def __repr__(self):
        return f"<{type(self).__name__} {self._path or '(unbound)'}>"


class Port(Component):
    """A connector: across variables (equal at a node) and through variables (sum zero).

    ``effort`` and ``flow`` name the power pair (effort*flow = power into the component);
    ``hint`` is printed when a port's variables end up undetermined.
    """

    effort: str = None
    flow: str = None
    hint: str = ""

    def across(self) -> list:
        return [n for n, d in self.declarations().items() if getattr(d, "kind", "") in
                ("across", "signal")]

    def through(self) -> list:
        return [n for n, d in self.declarations().items() if getattr(d, "kind", "") == "through"]


class Connection:
    """connect(a, b, ...): the ports form one node (across equal, through sum to zero)."""

    __slots__ = ("ports", "owner")

    def __init__(self, ports):
        self.ports = tuple(ports)
        self.owner = None

    def __repr__(self):
        return "connect(" + ", ".join(p.path or repr(p) for p in self.ports) + ")"


def connect(a: Port, b: Port, *more: Port) -> Connection:
    """Connect ports of the same type: ``ac.connect(self.R1.n, self.C1.p)``."""
    ports = (a, b) + more
    for p in ports:
        if not isinstance(p, Port):
            raise ModelError(f"connect() takes ports, got {p!r} ({type(p).__name__})")
    kinds = {p.connection_type() for p in ports}
    if len(kinds) > 1:
        names = ", ".join(f"{p.path} ({type(p).__name__})" for p in ports)
        raise ModelError(f"connect() of ports of different types: {names}")
    return Connection(ports)


def _connection_type(self):
    """Ports connect when they carry the same across/through variable names."""
    return (tuple(self.across()), tuple(self.through()))


Port.connection_type = _connection_type

_CHILD_CACHE: dict = {}
_DECL_CACHE: dict = {}


def _class_children(cls) -> dict:
    """Class-level sub-component declarations over the MRO, base classes first."""
    if cls not in _CHILD_CACHE:
        out = {}
        for klass in reversed(cls.__mro__):
            for name, value in vars(klass).items():
                if isinstance(value, Component):
                    out[name] = value
        _CHILD_CACHE[cls] = out
    return _CHILD_CACHE[cls]


def _declarations(cls) -> dict:
    if cls not in _DECL_CACHE:
        out = {}
        for klass in reversed(cls.__mro__):
            for name, value in vars(klass).items():
                if isinstance(value, (Parameter, Variable)):
                    out[name] = value
        _DECL_CACHE[cls] = out
    return _DECL_CACHE[cls]


def _is_component_list(value) -> bool:
    return (isinstance(value, (list, tuple)) and len(value) > 0
            and all(isinstance(v, Component) for v in value))


def flatten_equation_list(items) -> list:
    """Equations may be returned as nested lists or generators; make one flat list."""
    out = []
    stack = [iter(items if items is not None else [])]
    while stack:
        try:
            item = next(stack[-1])
        except StopIteration:
            stack.pop()
            continue
        if isinstance(item, (Equation, Connection, When)):
            out.append(item)
        elif isinstance(item, (list, tuple)) or hasattr(item, "__next__"):
            stack.append(iter(item))
        else:
            out.append(item)
    return out
