"""Equations over the class hierarchy: Modelica's ``extends``.

A component's ``equations()`` returns only the equations its own class adds; the
equations of its base classes are included by the framework, as ``extends`` includes
them in Modelica (specification, section 7.1).  ``collect(comp, "equations")`` walks the
method resolution order from the most basic class down and calls each class's *own*
``equations`` once, so ::

    class Resistor(OnePort):
        def equations(self):
            return [ac.Eq(self.v, self.R * self.i)]

yields OnePort's three equations followed by Ohm's law, in the order the former idiom
``[...]`` gave.  ``initial_equations`` is collected the same way.

A class that calls ``super().equations()`` (or ``Base.equations(self)``) would count its
bases' equations twice: that is refused with ``InvalidInheritance``, when the class is
created for the usual spelling (found in the method's byte code) and when the equations
are read for any other.

A subclass that must *replace* the equations of a base, rather than add to them, says
so on the method::

    class IdealDiode(Diode):
        @ac.replaces(Diode)
        def equations(self):
            ...

Then the named classes' own ``equations`` are left out for this class and its
subclasses (their bases' equations still count); the replacing method may call the
replaced ones (``Diode.equations(self)``, to filter what they return).  Replacing is an
explicit, visible act, as Modelica's ``redeclare``; nothing is ever dropped silently.
"""
from __future__ import annotations

import contextvars
import functools
import types

from .equationlist import flatten_equation_list
from ..errors import InvalidInheritance


__all__ = ["EQUATION_METHODS", "replaces", "prepare_class", "collect", "own_methods",
           "all_items"]

EQUATION_METHODS = ("equations", "initial_equations")
_REPLACES = "__acausal_replaces__"
_WRAPPED = "__acausal_own__"


def replaces(*bases):
    """Mark ``equations`` (or ``initial_equations``) as replacing the named base classes'
    own method instead of adding to it: ``@ac.replaces(Diode)``."""
    if not bases or not all(isinstance(b, type) for b in bases):
        raise InvalidInheritance(f"ac.replaces() takes the base classes whose equations the "
                                 f"method replaces, got {bases!r}")

    def mark(func):
        if not callable(func):
            raise InvalidInheritance(f"@ac.replaces(...) decorates a method, not {func!r}")
        setattr(func, _REPLACES, tuple(bases))
        return func
    return mark


# -- class creation -------------------------------------------------------------------------

def prepare_class(cls) -> None:
    """Check ``cls``'s own equation methods and guard them against super() calls.

    Raises ``InvalidInheritance`` for a method that calls the base's method of the same
    kind, or that replaces a class which is not a base with such a method of its own."""
    for name in EQUATION_METHODS:
        func = vars(cls).get(name)
        if not isinstance(func, types.FunctionType) or getattr(func, _WRAPPED, None):
            continue
        if _calls_super(func.__code__, name) and not getattr(func, _REPLACES, ()):
            raise InvalidInheritance(_super_message(cls, name))
        for base in getattr(func, _REPLACES, ()):
            _check_replaced(cls, name, base)
        setattr(cls, name, _guarded(cls, name, func))


def _super_message(cls, name: str, base=None) -> str:
    call = f"{base.__name__}.{name}(self)" if base is not None else f"super().{name}()"
    return (f"{cls.__name__}.{name} calls {call}; the bases' {_plural(name)} are "
            f"included automatically — remove the call (or mark the method "
            f"@ac.replaces(Base) to replace a base's {_plural(name)})")


def _plural(name: str) -> str:
    return name.replace("_", " ")


def _calls_super(code: types.CodeType, name: str) -> bool:
    """True if ``code`` (or a function, generator or comprehension inside it) loads
    ``super`` and an attribute called ``name``: ``super().name()`` in any spelling."""
    if "super" in code.co_names and name in code.co_names:
        return True
    return any(isinstance(c, types.CodeType) and _calls_super(c, name)
               for c in code.co_consts)


def _check_replaced(cls, name: str, base) -> None:
    if base not in cls.__mro__[1:]:
        raise InvalidInheritance(f"{cls.__name__}.{name} replaces {base.__name__}, "
                                 f"which is not a base class of {cls.__name__}")
    if name not in vars(base):
        raise InvalidInheritance(f"{cls.__name__}.{name} replaces {base.__name__}, "
                                 f"which has no {name}() of its own to replace")


# The class whose own method the framework is calling, per instance and method: a call of
# another class's own method on the same instance meanwhile is a super() call.
_CALLING = contextvars.ContextVar("acausal_equations_of", default=None)


def _guarded(cls, name: str, func):
    @functools.wraps(func)
    def own(self, *args, **kwargs):
        active = _CALLING.get()
        if active is not None and active[0] is self and active[1] == name \
                and active[2] is not cls and cls not in _replaced_by(active[2], name):
            raise InvalidInheritance(_super_message(active[2], name, cls))
        return func(self, *args, **kwargs)
    setattr(own, _WRAPPED, cls)
    return own


def _replaced_by(klass, name: str) -> tuple:
    """The classes whose own ``name`` the method of ``klass`` replaces: it may call those
    (to reuse or filter what they return), since the framework leaves them out."""
    return getattr(vars(klass).get(name), _REPLACES, ())


# -- reading the equations ------------------------------------------------------------------

def own_methods(cls, name: str) -> tuple:
    """``(class, function)`` of every class in ``cls``'s MRO that defines ``name`` itself,
    most basic first, without those a subclass replaces.  Read afresh each time (a few
    dictionary look-ups), so a method assigned after the class was made counts too."""
    mro = [k for k in reversed(cls.__mro__) if name in vars(k)]
    replaced = set()
    for klass in mro:
        replaced.update(getattr(vars(klass)[name], _REPLACES, ()))
    return tuple((k, vars(k)[name]) for k in mro if k not in replaced)


def collect(comp, name: str, known: dict | None = None) -> list:
    """``(class, items)`` for each class of ``comp`` with its own ``name`` method
    (``"equations"`` or ``"initial_equations"``), most basic class first; ``items`` is
    the flat list the method returned, or None if it returned None (the caller names
    that error).  Generators are run here, while the super() guard is active.
    ``known``: :func:`own_methods` by (class, name), kept by the caller while the
    classes do not change (one flattening)."""
    out = []
    cls = type(comp)
    if known is None:
        methods = own_methods(cls, name)
    else:
        methods = known.get((cls, name))
        if methods is None:
            methods = known[cls, name] = own_methods(cls, name)
    for klass, func in methods:
        token = _CALLING.set((comp, name, klass))
        try:
            raw = func.__get__(comp, type(comp))()
            items = None if raw is None else flatten_equation_list(raw)
        finally:
            _CALLING.reset(token)
        out.append((klass, items))
    return out


def all_items(comp, name: str = "equations") -> list:
    """Every item of ``comp``'s ``name`` over its class hierarchy, in one flat list
    (a method that returned None contributes nothing: flattening reports it)."""
    return [item for _, items in collect(comp, name) for item in (items or ())]
