"""Conditional components: a port (or sub-component) that exists only when a structural
Boolean parameter says so (Modelica's ``Support support if useSupport``, Language
Specification 3.6, sec. 4.4.5).

    class PartialElementaryOneFlangeAndSupport(PartialElementaryOneFlange):
        useSupport = ac.Parameter(False, structural=True,
                                  description="use the support flange, else it is fixed")
        support = ac.Conditional(RotationalFlange(), "useSupport")

        def phi_support(self):
            return self.support.phi if self.useSupport else 0

        def equations(self):
            return [ac.Eq(self.support.tau, -self.flange.tau)] if self.useSupport else []

The flag is given where the component is made, ``Torque(useSupport=True)``; with it the
port is made and must be connected; without it there is no port, and the component's
equations give the internal default in its place (a fixed support, a device temperature
``T`` for a heat port, a parameter for an input), as the MSL writes
``if not useSupport then phi_support = 0; end if``.  Reading or connecting an absent
port is an error that names the flag and how to set it.
"""
from __future__ import annotations

from .declared import class_structurals
from ..errors import AbsentComponent, InvalidValue


__all__ = ["Conditional", "make_conditionals", "check_conditionals"]

_CONDITIONAL_CACHE: dict = {}


def absent_error(owner, name: str, flag: str, when: bool = True):
    """The error for reading ``owner.name`` whose flag does not have the value ``when``."""
    kind = type(owner).__name__
    where = f"'{owner._path}' ({kind})" if getattr(owner, "_path", None) else kind
    return AbsentComponent(f"{where}.{name} exists only with {flag}={when} ({flag}="
                           f"{not when} here): create it with {kind}({flag}={when}) to use "
                           f"or connect {name}")


class Conditional:
    """``name = ac.Conditional(component, "flag")``: ``component`` (a port, usually) is
    made for an instance whose structural Boolean parameter ``flag`` is True (``when=
    False``: is False, as the MSL's ``Fixed fixed if not useSupport``); see the module
    docstring.  That ``component`` is a component is checked with the class that
    declares it (``Component.__init_subclass__``)."""

    def __init__(self, component, flag: str, when: bool = True):
        if not isinstance(flag, str) or not flag.isidentifier():
            raise InvalidValue(f"Conditional(): the flag is the name of a structural "
                               f"Boolean parameter, not {flag!r}")
        if not isinstance(when, bool):
            raise InvalidValue(f"Conditional(..., when={when!r}): when is True or False")
        self.component = component
        self.flag = flag
        self.when = when          # made where the flag has this value
        self.name = None

    def __set_name__(self, owner, name):
        self.name = name

    def __get__(self, instance, owner=None):
        if instance is None:
            return self
        # made, it is in the instance's dict and this is not reached
        raise absent_error(instance, self.name, self.flag, self.when)

    def __repr__(self):
        when = "" if self.when else ", when=False"
        return f"Conditional({type(self.component).__name__}(), {self.flag!r}{when})"

    def check(self, cls) -> None:
        """ValueError unless ``flag`` is a structural Boolean parameter of ``cls``."""
        decl = class_structurals(cls).get(self.flag)
        if decl is None or not isinstance(decl.value, bool):
            raise ValueError(f"Conditional(..., {self.flag!r}): {self.flag} must be a "
                             f"structural Boolean parameter of {cls.__name__}, "
                             f"{self.flag} = ac.Parameter(False, structural=True)")


def class_conditionals(cls) -> dict:
    """The ``ac.Conditional`` declarations of ``cls`` over its MRO, base classes first."""
    if cls not in _CONDITIONAL_CACHE:
        out = {}
        for klass in reversed(cls.__mro__):
            for name, value in vars(klass).items():
                if isinstance(value, Conditional):
                    out[name] = value
                elif name in out:
                    del out[name]          # redeclared as something else
        _CONDITIONAL_CACHE[cls] = out
    return _CONDITIONAL_CACHE[cls]


def make_conditionals(comp, structural: dict) -> None:
    """Make the conditional components of a new instance whose flags say so
    (``structural``: the structural parameters it was given)."""
    for name, cond in class_conditionals(type(comp)).items():
        use = structural.get(cond.flag, class_structurals(type(comp))[cond.flag].value)
        if not isinstance(use, bool):
            raise InvalidValue(f"{type(comp).__name__}: {cond.flag} must be True or "
                               f"False, not {use!r}")
        if use == cond.when:
            setattr(comp, name, cond.component._clone())


def check_conditionals(cls) -> None:
    """InvalidValue naming ``cls.name`` for a Conditional whose flag is no structural
    Boolean parameter (checked when the class is made)."""
    for name, decl in vars(cls).items():
        if isinstance(decl, Conditional):
            try:
                decl.check(cls)
            except ValueError as err:
                raise InvalidValue(f"{cls.__name__}.{name}: {err}") from None
