"""Component: the unit of modelling (Modelica's ``model``), and connect().

A component class declares ports, parameters, variables and sub-components as class
attributes and returns its equations from ``equations()``::

    class Resistor(OnePort):
        '''Ideal linear resistor:  v = R*i  (Ohm's law).'''
        R = ac.Parameter(1.0, unit="Ohm")

        def equations(self):
            return [ac.Eq(self.v, self.R * self.i)]

``equations()`` returns only the class's own equations: the bases' (here OnePort's) are
included by the framework, as Modelica's ``extends`` includes them (``inheritance.py``;
``@ac.replaces(Base)`` replaces a base's equations instead).

Instantiation takes modifications, several levels down if needed:
``SeriesRLC(R1={"R": 5.0}, C1={"v": {"start": 1.0, "fixed": True}})``.  A number given
for a variable sets its start value.  Sub-components may also be created in ``__init__``
(for structural parameters such as a number of segments), as attributes or lists.

A component becomes part of a model when the root is bound (``_bind``), which happens in
``acausal.compile``: only then do its variables have their dotted names.

Bad input raises a ``ModelError`` naming the component path, the declaration and the
value, at the earliest point where those names are known: declarations when their class
is created (``Resistor.R: ...``), modifications when the instance is made
(``'R1' (Resistor): parameter R = 'ten' is not a real number``, ``validation.py``), the
instance tree when the model is bound, equations and connections when they are read by
flattening, units when the model is compiled (``units.py``).
"""
from __future__ import annotations

import copy
from contextlib import contextmanager
from typing import TYPE_CHECKING, Iterable

from . import inheritance
from .arrays import check_array_value, parameter_array, shape_of
from .conditional import Conditional, check_conditionals, make_conditionals
from .declarations import (COMPILING, Parameter, Variable, check_parameter_value,
                           check_structural_value, declaration_doc, is_symbolic,
                           parameter_signature, ref, shown_value)
from .declared import class_declarations, class_structurals, constructor_arguments
from .equationlist import Connection
from .validation import validate_modifications
from ..errors import InvalidConnection, InvalidHierarchy, InvalidValue, ModelError, NotInModel

if TYPE_CHECKING:
    import sympy

__all__ = ["Component", "Port", "Connection", "connect"]


# The root of the model being flattened: reading a variable of a component outside it is
# an error (its symbol would name a variable of another model, or one that does not exist).
# (declarations.py holds it: a declaration's own look-up reads it.)
_COMPILING = COMPILING


@contextmanager
def compiling(root: "Component"):
    """Within this block, equations may use only the variables of ``root``'s tree."""
    token = _COMPILING.set(root)
    try:
        yield
    finally:
        _COMPILING.reset(token)


def _describe_class(cls) -> None:
    """Give ``cls`` the signature and docstring its declarations imply, so that
    ``help(Resistor)`` and ``inspect.signature(Resistor)`` list R with its default, unit
    and description.  Collected here without the caches above: a class may still gain
    declarations after it is created, and the caches must see them."""
    params, variables, children = {}, {}, {}
    for klass in reversed(cls.__mro__):
        for name, value in vars(klass).items():
            if isinstance(value, Parameter):
                params[name] = value
            elif isinstance(value, Variable):
                variables[name] = value
            elif isinstance(value, Component):
                children[name] = value
            elif isinstance(value, Conditional):
                children[name] = value
    own_doc = vars(cls).get("__doc__")
    cls.__signature__ = parameter_signature(cls, params)
    if own_doc:
        # the docstring's first paragraph stays the class's summary (FMU descriptions and
        # the command line read it); a class without one keeps None rather than a summary
        # that would be a parameter table
        cls.__doc__ = declaration_doc(own_doc, params, variables, children)


class _ComponentType(type):
    """Checks an instance's modifications once its ``__init__`` (a subclass's too, which
    may create sub-components) has run: a bad modification fails at the line that made
    the instance (``validation.py``)."""

    def __call__(cls, *args, **kwargs):
        obj = super().__call__(*args, **kwargs)
        mods = getattr(obj, "_mods", None)
        if mods:
            object.__setattr__(obj, "_mods", validate_modifications(obj, mods, cls.__name__))
        return obj


class Component(metaclass=_ComponentType):
    """Base class of every model and component (see the module docstring)."""

    def __init__(self, **modifications):
        structural = {}
        for name, decl in class_structurals(type(self)).items():
            if name in modifications:
                value = copy.deepcopy(modifications.pop(name))
                if hasattr(value, "tolist"):        # a numpy array of coefficients
                    value = value.tolist()
                if isinstance(decl.value, bool) and not isinstance(value, bool):
                    raise InvalidValue(f"{type(self).__name__}: {name} must be True or "
                                       f"False, not {value!r}")
                try:
                    check_structural_value(value, f"structural parameter {name}",
                                           decl.min, decl.max, decl.choices)
                except ValueError as err:
                    raise InvalidValue(f"{type(self).__name__}: {err}") from None
                structural[name] = value
        object.__setattr__(self, "_structural", structural)
        object.__setattr__(self, "_mods", dict(modifications))
        object.__setattr__(self, "_path", None)
        object.__setattr__(self, "_parent", None)
        object.__setattr__(self, "_root", None)
        object.__setattr__(self, "_children", {})
        object.__setattr__(self, "_symbols", {})
        object.__setattr__(self, "_param_values", {})
        object.__setattr__(self, "_var_attrs", {})
        for name, decl in _class_children(type(self)).items():
            setattr(self, name, decl._clone())
        make_conditionals(self, structural)
        self.build()

    def build(self) -> None:
        """Create the sub-components that the structural parameters imply (override):
        called once, when the instance is made, after its structural parameters are set
        and its declared sub-components are created.  ``TransferFunction`` makes one
        integrator state per order of ``den`` here."""

    def __init_subclass__(cls, **kwargs):
        """Check the class's own declarations once, naming them ``Class.attribute``."""
        super().__init_subclass__(**kwargs)
        for name, decl in vars(cls).items():
            if isinstance(decl, (Parameter, Variable)):
                try:
                    decl.check()
                except ValueError as err:
                    raise InvalidValue(f"{cls.__name__}.{name}: {err}") from None
            elif isinstance(decl, Conditional) and not isinstance(decl.component, Component):
                raise InvalidValue(f"{cls.__name__}.{name}: ac.Conditional() takes a port or "
                                   f"component, got {decl.component!r}")
        check_conditionals(cls)
        inheritance.prepare_class(cls)
        _describe_class(cls)

    # -- the instance tree -------------------------------------------------------------
    def __setattr__(self, name, value):
        if value is self or (_is_component_list(value) and any(v is self for v in value)):
            raise InvalidHierarchy(f"{type(self).__name__}.{name}: a component cannot "
                                   "contain itself")
        if name in class_structurals(type(self)):
            raise InvalidValue(f"{type(self).__name__}.{name} is a structural parameter; set "
                               f"it when the component is made, {type(self).__name__}"
                               f"({name}=...)")
        if isinstance(class_declarations(type(self)).get(name), (Parameter, Variable)):
            # the assignment would hide the declaration: the equations would use the
            # value while the model still declares the parameter or variable
            raise InvalidValue(f"{type(self).__name__}.{name} is a declared "
                               f"{type(class_declarations(type(self))[name]).__name__.lower()}; "
                               f"set it by modification, {type(self).__name__}({name}=...), "
                               f"not by assigning self.{name}")
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
        """Name this tree (pre-order, so a parent's modifications reach its children
        before they are bound); a cycle or an instance held twice is an error."""
        seen = {}                       # id -> path of the instances named so far
        # the Boolean and Integer symbols of the model, by symbol (filled as they are
        # made, read by the equations' vocabulary: a Boolean is a condition)
        object.__setattr__(self, "_value_types", {})
        object.__setattr__(self, "_uses_initial", False)
        stack = [(self, path, parent)]
        while stack:
            comp, where, above = stack.pop()
            if id(comp) in seen:
                raise _hierarchy_error(comp, where, above, seen[id(comp)])
            seen[id(comp)] = where
            comp._bind_one(where, above, self)
            for name, child in reversed(list(comp._children.items())):
                stack.append((child, f"{where}.{name}" if where else name, comp))

    def _bind_one(self, path: str, parent, root) -> None:
        object.__setattr__(self, "_path", path)
        object.__setattr__(self, "_parent", parent)
        object.__setattr__(self, "_root", root)
        self._symbols.clear()
        decls = class_declarations(type(self))
        for key, mod in self._mods.items():
            self._apply_modification(key, mod, decls)

    def _apply_modification(self, key, mod, decls):
        if key in self._children:
            if not isinstance(mod, dict):
                raise ModelError(f"{self._describe()}: modification of sub-component "
                                 f"'{key}' must be a dict of its parameters, got {mod!r}")
            child = self._children[key]
            object.__setattr__(child, "_mods", {**child._mods, **mod})
        elif isinstance(decls.get(key), Parameter):
            try:    # a dict gives attributes: {"fixed": False, "start": 100} (initparams)
                mod = decls[key].attributes_modified(self, key, mod)
                if decls[key].shape is not None:
                    check_array_value(mod, shape_of(decls[key], self, key),
                                      f"parameter {key}")
                else:
                    check_parameter_value(mod, f"parameter {key}", decls[key].type)
            except InvalidValue:
                raise
            except ValueError as err:
                raise InvalidValue(f"{self._describe()}: {err}") from None
            self._param_values[key] = mod
        elif isinstance(decls.get(key), Variable):
            base = self._var_attrs.get(key, decls[key].attributes)
            try:
                self._var_attrs[key] = base.modified(mod)
            except (TypeError, ValueError) as err:
                raise InvalidValue(f"{self._describe()}: variable '{key}': {err}") from None
        elif key in constructor_arguments(type(self)):
            # a structural argument (a port that exists or not, a number of cells) shapes
            # the instance when it is created; a modification comes too late for that
            kind = type(self).__name__
            raise ModelError(f"{self._describe()}: '{key}' is an argument of the "
                             f"constructor, not a parameter; give it where the component "
                             f"is created: {kind}({key}={mod!r})")
        else:
            known = sorted(set(decls) | set(self._children))
            raise ModelError(f"{self._describe()} has no parameter, variable or "
                             f"sub-component named '{key}' (it has: {', '.join(known)})")

    def _describe(self) -> str:
        where = f"'{self._path}'" if self._path else "the model"
        return f"{where} ({type(self).__name__})"

    def _symbol(self, name: str) -> sympy.Symbol:
        active = _COMPILING.get()
        if active is not None and self._root is not active:
            raise _foreign_error(self, name, active)
        sym = self._symbols.get(name)
        if sym is None:
            if self._path is None:
                raise ModelError(
                    f"{type(self).__name__}.{name} has no name yet: a component's "
                    "variables are named when the model is compiled (acausal.compile)")
            full = f"{self._path}.{name}" if self._path else name
            # the first symbol of a model loads sympy, not the class
            from .realsymbol import real_symbol
            sym = real_symbol(full)
            self._symbols[name] = sym
            typ = getattr(class_declarations(type(self)).get(name), "type", float)
            if typ is not float and self._root is not None:
                self._root._value_types[sym] = typ
        return sym

    # -- what the compiler reads -------------------------------------------------------
    def parameter_value(self, name: str):
        """The value of parameter ``name``: a number, or a sympy expression of other
        parameters (a ``ref`` or a function of the component, evaluated here); of an
        array parameter, an array of them."""
        if class_declarations(type(self))[name].shape is not None:
            return parameter_array(self, name, class_declarations(type(self))[name])
        if name in self._param_values:
            value = self._param_values[name]
        else:
            value = class_declarations(type(self))[name].value
        if isinstance(value, ref):
            return self._referenced(name, value)
        if callable(value) and not is_symbolic(value):
            try:
                value = value(self)
            except ModelError:
                raise
            except Exception as err:  # the user's function raised: say whose it is
                raise InvalidValue(f"{self._describe()}: evaluating parameter {name} "
                                   f"raised {type(err).__name__}: {err}") from err
            if callable(value) and not is_symbolic(value):
                raise InvalidValue(f"{self._describe()}: parameter {name} is a function "
                                   f"that returned another function ({value!r})")
            if isinstance(value, ref):
                return self._referenced(name, value)
        try:
            check_parameter_value(value, f"parameter {name}",
                                  class_declarations(type(self))[name].type)
        except ValueError as err:
            raise InvalidValue(f"{self._describe()}: {err}") from None
        return value

    def _referenced(self, name: str, value: ref):
        parent = self._parent
        if parent is None:
            raise InvalidValue(f"{self._describe()}: parameter {name} = {value!r}, but "
                               "the model has no enclosing component to refer to")
        decl = parent.declarations().get(value.name)
        if not isinstance(decl, Parameter):
            what = ("is a variable, not a parameter" if decl is not None
                    else "has no parameter of that name")
            raise InvalidValue(f"{self._describe()}: parameter '{name}' refers to "
                               f"'{value.name}' of the enclosing component, "
                               f"{parent._describe()}, which {what}")
        return getattr(parent, value.name)

    def variable_attributes(self, name: str):
        return self._var_attrs.get(name, class_declarations(type(self))[name].attributes)

    def declarations(self) -> dict:
        """Parameters and variables declared by this component's class, in order."""
        return class_declarations(type(self))

    def equations(self) -> Iterable:
        """The equations and connections this class adds (override); the base classes'
        are included by the framework (``inheritance.collect``), never by super()."""
        return []

    def initial_equations(self) -> Iterable:
        """Equations that hold only at the initial time (override), e.g. der(w) = 0;
        the base classes' are included as for ``equations``."""
        return []

    def __repr__(self):
        # getattr: a subclass's __init__ may fail before Component.__init__ ran, and the
        # traceback still shows the half-built instance
        where = getattr(self, "_path", None) or "(unbound)"
        if isinstance(self, Port):
            return f"<{type(self).__name__} {where}>"
        given = {**getattr(self, "_mods", {}), **getattr(self, "_param_values", {})}
        shown = [f"{name}={getattr(self, '_structural', {}).get(name, decl.value)!r}"
                 for name, decl in class_structurals(type(self)).items()]
        for name, decl in self.declarations().items():
            if isinstance(decl, Parameter):
                value = given.get(name, decl.value)
                unit = f" {decl.unit}" if decl.unit else ""
                shown.append(f"{name}={shown_value(value)!r}{unit}")
        if len(shown) > 8:
            shown = shown[:8] + [f"... ({len(shown) - 8} more)"]
        return f"<{type(self).__name__} {where}" + (": " + ", ".join(shown) if shown else "") + ">"


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


def connect(a: Port, b: Port, *more: Port) -> Connection:
    """Connect ports of the same type: ``ac.connect(self.R1.n, self.C1.p)``.

    A port made of ports (a polyphase plug of pins, Modelica's hierarchical connector)
    connects member by member: the result is then a list of connections, one per
    member."""
    ports = (a, b) + more
    bus = next((p for p in ports if getattr(p, "_bus_end", False)), None)
    if bus is not None:          # through a bus: the bus checks it, typed when flattened
        bus.check_bus_connection(ports)
        return Connection(ports)
    for p in ports:
        if isinstance(p, Component) and not isinstance(p, Port):
            own = [n for n, c in p.children().items() if isinstance(c, Port)]
            raise InvalidConnection(
                f"connect() takes ports, got the component '{p.path or type(p).__name__}' "
                f"({type(p).__name__})" + (f"; its ports: {', '.join(own)}" if own else ""))
        if not isinstance(p, Port):
            raise InvalidConnection(f"connect() takes ports, got {p!r} ({type(p).__name__})")
    kinds = {p.connection_type() for p in ports}
    if len(kinds) > 1:
        names = ", ".join(f"{p.path} ({type(p).__name__})" for p in ports)
        raise InvalidConnection(f"connect() of ports of different types: {names}")
    seen = set()
    for p in ports:
        if id(p) in seen:
            text = repr(Connection(ports))
            if len(ports) == 2:
                raise InvalidConnection(f"{text} connects port '{_port_name(p)}' to itself")
            raise InvalidConnection(f"{text}: port '{_port_name(p)}' appears more than "
                                    "once")
        seen.add(id(p))
    members = _member_ports(ports[0])
    if members:
        return [connect(*(p._children[name] for p in ports)) for name in members]
    return Connection(ports)


def _member_ports(port) -> list:
    """The names of the ports a port is made of (a plug's ``pin[0]``, ...), if it declares
    no variables of its own."""
    if port.declarations():
        return []
    return [name for name, c in port._children.items() if isinstance(c, Port)]


def in_context(err: ModelError, where: str) -> ModelError:
    """The same kind of error, its message prefixed by where it happened."""
    text = f"in {where}: {err}"
    try:
        return type(err)(text)
    except TypeError:   # a subclass with another constructor
        return ModelError(text)


def _port_name(p: Port) -> str:
    return p.path or repr(p)


def _connection_type(self):
    """Ports connect when they carry the same across/through variable names, of the same
    value types (a Boolean signal does not connect to a Real one)."""
    decls = self.declarations()
    members = _member_ports(self)
    if members:     # a port made of ports: the same members, each of the same type
        return ("members",) + tuple((n, self._children[n].connection_type()) for n in members)
    across = tuple(self.across())
    types = tuple(getattr(decls[n], "type", float).__name__ for n in across)
    return (across, tuple(self.through()), types)


Port.connection_type = _connection_type

_CHILD_CACHE: dict = {}


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


def _hierarchy_error(comp, where: str, above, first: str) -> InvalidHierarchy:
    """An instance met twice while binding: a cycle if it encloses ``where``."""
    kind = type(comp).__name__
    node = above
    while node is not None:
        if node is comp:
            name = f"'{first}'" if first else "the model"
            return InvalidHierarchy(f"{name} ({kind}) contains itself: its sub-component "
                                    f"'{where}' is {name} again")
        node = node._parent
    return InvalidHierarchy(f"the same {kind} instance is part of the model twice, as "
                            f"'{first}' and as '{where}'; give each place its own "
                            f"instance ({kind}(...))")


def _foreign_error(comp, name: str, root) -> NotInModel:
    kind = type(comp).__name__
    if comp._path is None:
        whose = f"a {kind} that was never made part of it"
    else:
        full = f"{comp._path}.{name}" if comp._path else name
        whose = f"'{full}' of a {kind} in another model instance"
    return NotInModel(f"{kind}.{name}: the model being compiled ({type(root).__name__}) "
                      f"uses {whose}; equations may use only the model's own components "
                      "(self and its sub-components)")


def _is_component_list(value) -> bool:
    return (isinstance(value, (list, tuple)) and len(value) > 0
            and all(isinstance(v, Component) for v in value))
