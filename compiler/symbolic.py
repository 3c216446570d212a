"""The symbolic side of the structural passes: expressions <-> the integer Structure.

``SymbolicSystem`` holds the equations of the model (sympy residuals, with provenance)
and the variable symbols, including derivative symbols ``der(x)``, indexed as in the
:class:`~acausal.compiler.graph.Structure` it produces.  The structural passes work on
that Structure alone; when Pantelides asks for an equation to be differentiated, the
callback here differentiates the residual symbolically,

    d/dt r(x, der(x), t) = sum_v  dr/dv * der(v)  +  dr/dt,

creating the derivative symbols it needs, and reports the exact incidence back.
The same time derivative (:meth:`SymbolicSystem.time_derivative`) serves the
linear-combination conversion (:mod:`acausal.compiler.conversion`).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp

from ..components.symbols import time
from .derivative import partial
from .flatten import derivative_symbol
from .graph import (LINEAR_CONST, LINEAR_PARAM, LINEAR_VAR, NONLINEAR, PREFER, STATE_SELECT,
                    UNASSIGNED, Structure)

__all__ = ["SymbolicEquation", "SymbolicSystem", "coefficient_kind"]


@dataclass
class SymbolicEquation:
    residual: sp.Expr
    text: str                 # as the user wrote it (for the original equations)
    component: str
    component_class: str
    kind: str = "equation"
    derivative_of: int | None = None     # index of the equation this is d/dt of
    order: int = 0                       # how many times differentiated from the source
    combination: tuple = ()              # (coefficient, name, order) of combined equations

    @property
    def where(self) -> str:
        return f"{self.component or '(model)'} ({self.component_class})"

    def name(self, system: "SymbolicSystem") -> str:
        """The source equation with its component, and the differentiations applied:
        ``d^2/dt^2(x**2 + y**2 = L**2  [pendulum (Pendulum)])``."""
        base = self
        while base.derivative_of is not None:
            base = system.equations[base.derivative_of]
        if base.combination:          # its text names every equation and component
            core = base.text
        else:
            text = base.text if len(base.text) <= 60 else base.text[:57] + "..."
            core = f"{text}  [{base.where}]"
        if self.order == 0:
            return core
        power = f"^{self.order}" if self.order > 1 else ""
        return f"d{power}/dt{power}({core})"


@dataclass
class SymbolicSystem:
    """Equations and variables of the flat model after alias elimination."""

    equations: list
    symbols: list                                 # index -> sympy Symbol
    parameters: set
    var_info: dict = field(default_factory=dict)  # base symbol -> FlatVariable
    derivatives: dict = field(default_factory=dict)  # symbol -> der symbol
    index: dict = field(default_factory=dict)     # symbol -> index

    @classmethod
    def from_flat(cls, flat) -> "SymbolicSystem":
        eqs = [SymbolicEquation(e.residual, e.text, e.component, e.component_class, e.kind)
               for e in flat.equations]
        system = cls(eqs, [], {p.symbol for p in flat.parameters},
                     {v.symbol: v for v in flat.variables}, dict(flat.derivatives))
        for v in flat.variables:
            system._add_symbol(v.symbol)
        # derivative chains in order: der(x) after x, der(der(x)) after der(x)
        for v in flat.variables:
            s = v.symbol
            while s in system.derivatives:
                s = system.derivatives[s]
                system._add_symbol(s)
        return system

    def _add_symbol(self, s: sp.Symbol) -> int:
        if s not in self.index:
            self.index[s] = len(self.symbols)
            self.symbols.append(s)
        return self.index[s]

    def base_info(self, k: int):
        """The FlatVariable a (possibly derivative) variable k belongs to."""
        s = self.symbols[k]
        if s not in self.var_info:
            anti = {d: x for x, d in self.derivatives.items()}   # one dict per lookup chain
            while s not in self.var_info:
                s = anti[s]
        return self.var_info[s]

    def base_infos(self) -> list:
        """base_info for every variable, in one pass (linear in the number of variables)."""
        anti = {d: x for x, d in self.derivatives.items()}
        out = []
        for s in self.symbols:
            while s not in self.var_info:
                s = anti[s]
            out.append(self.var_info[s])
        return out

    # -- Structure ---------------------------------------------------------------------
    def incidence(self, r: sp.Expr) -> tuple[list, dict]:
        vars_ = sorted(self.index[s] for s in r.free_symbols if s in self.index)
        coeff = {v: coefficient_kind(r, self.symbols[v], self.index, self.parameters)
                 for v in vars_}
        return vars_, coeff

    def structure(self) -> Structure:
        graph, coeff = [], []
        for eq in self.equations:
            vs, cs = self.incidence(eq.residual)
            graph.append(vs)
            coeff.append(cs)
        var_to_diff = [UNASSIGNED] * len(self.symbols)
        for x, d in self.derivatives.items():
            if x in self.index and d in self.index:
                var_to_diff[self.index[x]] = self.index[d]
        names = [s.name for s in self.symbols]
        # a derivative variable der(x) shares x's hint, but 'always' belongs to x alone:
        # x and der(x) cannot both be forced to be states where an equation links der(x)
        # to a declared speed (w = der(phi), with phi and w always states)
        priority = [min(STATE_SELECT[info.attrs.state_select], PREFER)
                    if sym not in self.var_info else STATE_SELECT[info.attrs.state_select]
                    for sym, info in zip(self.symbols, self.base_infos())]
        return Structure(graph=graph, var_to_diff=var_to_diff,
                         eq_to_diff=[UNASSIGNED] * len(graph), coeff=coeff,
                         var_names=names, eq_names=[e.name(self) for e in self.equations],
                         state_priority=priority)

    # -- differentiation (the Pantelides callback) --------------------------------------
    def differentiate(self, s: Structure, e: int):
        """Append d/dt of equation e; return its incidence (vars, coeff) in s's indices.

        Pantelides has already created der(v) in ``s`` for every v in e; we mirror
        those variables here so the indices agree.
        """
        self._sync_variables(s)
        eq = self.equations[e]
        dr = self.time_derivative(eq.residual)
        self.equations.append(SymbolicEquation(dr, f"d/dt({eq.text})", eq.component,
                                               eq.component_class, eq.kind,
                                               derivative_of=e, order=eq.order + 1))
        self._sync_variables(s)
        return self.incidence(dr)

    def time_derivative(self, r: sp.Expr) -> sp.Expr:
        """d/dt r = sum_v dr/dv der(v) + dr/dt over the variables v of r, creating the
        der(v) symbols it needs (appended to ``symbols`` in the order of v)."""
        dr = sp.diff(r, time) if r.has(time) else sp.Integer(0)
        for sym in sorted((q for q in r.free_symbols if q in self.index),
                          key=lambda q: self.index[q]):
            dr += partial(r, sym) * derivative_symbol(sym, self.derivatives)
            self._add_symbol(self.derivatives[sym])
        return dr

    def _sync_variables(self, s: Structure) -> None:
        """Mirror the derivative variables Pantelides created (indices must agree)."""
        for k in range(len(self.symbols), s.n_vars):
            parent = self.symbols[s.diff_to_var[k]]
            self._add_symbol(derivative_symbol(parent, self.derivatives))


def coefficient_kind(r: sp.Expr, s: sp.Symbol, index: dict, parameters: set) -> int:
    """How symbol s enters residual r (graph.LINEAR_CONST ... NONLINEAR)."""
    c = partial(r, s)
    if c.has(s):
        return NONLINEAR
    if c.is_number:
        return LINEAR_CONST if c != 0 else NONLINEAR
    if c.free_symbols <= parameters:
        return LINEAR_PARAM
    return LINEAR_VAR
