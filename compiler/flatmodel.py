"""The flat model: what flattening makes of the instance tree, and what every pass after
it reads -- variables, parameters and equations under their dotted names, each with the
component (path and class) that declared it.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp

from ..components.declarations import VariableAttributes
from ..components.symbols import Equation, text

__all__ = ["FlatVariable", "FlatParameter", "FlatEquation", "FlatModel"]


class _Located:
    @property
    def where(self) -> str:
        """The component, and an equation's label: ``spring (Spring), "Hooke's law"``."""
        base = f"{self.component or '(model)'} ({self.component_class})"
        label = getattr(self, "label", None)
        return f'{base}, "{label}"' if label else base


@dataclass
class FlatVariable(_Located):
    name: str
    symbol: sp.Symbol
    attrs: VariableAttributes
    component: str
    component_class: str
    kind: str = "variable"
    hint: str = ""            # the port's likely-mistake hint, for port variables


@dataclass
class FlatParameter(_Located):
    name: str
    symbol: sp.Symbol
    value: object
    unit: str = ""
    description: str = ""
    component: str = ""
    component_class: str = ""
    min: float | None = None
    max: float | None = None
    type: object = float      # float, bool or int (Real, Boolean, Integer)
    fixed: bool = True        # False: found by initialization, ``value`` its start

    def describe(self) -> str:
        """``'R1' (Resistor): parameter R``, as the component's own errors say it."""
        owner = f"'{self.component}'" if self.component else "the model"
        local = self.name[len(self.component) + 1:] if self.component else self.name
        return f"{owner} ({self.component_class}): parameter {local}"


@dataclass
class FlatEquation(_Located):
    residual: sp.Expr
    source: object            # the text; or the Equation, or the sum (printed "sum = 0")
                              # or its terms {q: +-1}, it is printed from on demand
    component: str
    component_class: str
    kind: str = "equation"       # equation | connect | unconnected | initial
    label: str | None = None
    # the residual as flattened when it is a sum of +-symbols and +-der(symbol): while
    # it is still the residual (``plain is residual``) it holds no function of another
    # kind, and the passes that look for floor() or delay() need not walk it
    plain: object = field(default=None, repr=False, compare=False)
    # the variable alone on the left of ``ac.Eq`` as written (a Boolean or Integer
    # variable's equation gives its value: compiler/sampled.py), else None
    defines: object = field(default=None, repr=False, compare=False)
    # a sum of +-symbols and +-der(symbol) as its terms {q: +-1}: ``residual`` (given as
    # None) is made from them when first read (most of them are aliases, which alias
    # elimination reads as terms and drops); see ``unmade``
    terms: object = field(default=None, repr=False, compare=False)

    @property
    def unmade(self):
        """The terms {q: +-1} of a sum whose residual is not made yet, else None: a pass
        that reads only its symbols or its terms' units reads these instead."""
        return self.terms if self.__dict__["residual"] is None else None

    def is_plain(self) -> bool:
        """A sum of +-symbols and +-der(symbol) as flattened, unchanged since (it holds no
        function of another kind: floor(), delay(), pre())."""
        r = self.__dict__["residual"]
        return self.terms is not None if r is None else self.plain is r

    @property
    def text(self) -> str:
        """The equation as written (printed lazily: printing is slow on large models)."""
        if not isinstance(self.source, str):
            src = self.source
            if isinstance(src, dict):          # the terms of a sum {q: +-1}
                from .algebra.symbolic import signed_sum
                src = signed_sum(src)
            self.source = src.text if isinstance(src, Equation) else f"{text(src)} = 0"
        return self.source

    def describe(self) -> str:
        return f"{self.text}   [{self.kind} in {self.where}]"


def _residual(eq):
    r = eq.__dict__["residual"]
    if r is None and eq.terms is not None:
        from .algebra.symbolic import signed_sum
        r = eq.__dict__["residual"] = eq.__dict__["plain"] = signed_sum(eq.terms)
    return r


def _set_residual(eq, residual):
    eq.__dict__["residual"] = residual


# a property over the dataclass field (whose __init__, comparison and repr go through it)
FlatEquation.residual = property(_residual, _set_residual,
                                 doc="the equation as ``residual = 0`` (sympy)")


@dataclass
class FlatModel:
    name: str
    variables: list
    parameters: list
    equations: list
    initial_equations: list = field(default_factory=list)
    derivatives: dict = field(default_factory=dict)   # variable symbol -> der symbol
    whens: list = field(default_factory=list)         # When clauses (condition, reinits)
    structural_zeros: list = field(default_factory=list)  # parameters evaluated as 0
    ports: list = field(default_factory=list)         # (path, Port class, effort, flow)
    components: dict = field(default_factory=dict)    # path -> class name
    derived: dict = field(default_factory=dict)       # bound parameter -> (binding, value)
    uses_initial: bool = False                        # an equation reads initial()
    inputs: list = field(default_factory=list)        # top-level inputs (frontend/inputs)

    def variable(self, name: str) -> FlatVariable:
        for v in self.variables:
            if v.name == name:
                return v
        raise KeyError(name)
