"""The symbolic side of the structural passes: expressions <-> the integer Structure.

``SymbolicSystem`` holds the equations of the model (sympy residuals, with provenance)
and the variable symbols, including derivative symbols ``der(x)``, indexed as in the
:class:`~acausal.compiler.structure.graph.Structure` it produces.  The structural passes work on
that Structure alone; when Pantelides asks for an equation to be differentiated, the
callback here differentiates the residual symbolically,

    d/dt r(x, der(x), t) = sum_v  dr/dv * der(v)  +  dr/dt,

creating the derivative symbols it needs, and reports the exact incidence back.
The same time derivative (:meth:`SymbolicSystem.time_derivative`) serves the
linear-combination conversion (:mod:`acausal.compiler.index.conversion`).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from functools import lru_cache, partial as bound

import sympy as sp

from ...components.realsymbol import SYMBOLS
from ...components.symbols import der, time
from .dag import depth
from .derivative import flat_symbols, forget_partials, partial, symbol_nodes, terms_with
from .substitution import forget_negated, negated, sort_args
from ..structure.graph import (LINEAR_CONST, LINEAR_PARAM, LINEAR_VAR, NONLINEAR, PREFER,
                               STATE_SELECT, UNASSIGNED, Names, Structure, state_tie_break)
from ...errors import ModelError

__all__ = ["SymbolicEquation", "SymbolicSystem", "ExactText", "coefficient_kind",
           "forget_expressions",
           "sum_partial", "symbols_of", "derivative_symbol", "signed_terms", "signed_sum"]


@dataclass
class SymbolicEquation:
    """An equation of the system; ``text`` is printed from ``source`` when first read
    (the text itself, an object with a ``text``, e.g. the FlatEquation, or a function of
    no arguments returning it): most texts of a large model are never shown."""

    residual: sp.Expr
    source: object            # what ``text`` is printed from (see the class docstring)
    component: str
    component_class: str
    kind: str = "equation"
    derivative_of: int | None = None     # index of the equation this is d/dt of
    order: int = 0                       # how many times differentiated from the source
    combination: tuple = ()              # (coefficient, name, order) of combined equations
    label: str | None = None             # the user's label (ac.Eq(..., label=...))

    @property
    def where(self) -> str:
        base = f"{self.component or '(model)'} ({self.component_class})"
        return f'{base}, "{self.label}"' if self.label else base

    @property
    def text(self) -> str:
        """As the user wrote it (for the original equations)."""
        src = self.source
        if not isinstance(src, str):
            src = self.source = src() if callable(src) else src.text
        return src

    def name(self, system: "SymbolicSystem") -> str:
        """The source equation with its component, and the differentiations applied:
        ``d^2/dt^2(x**2 + y**2 = L**2  [pendulum (Pendulum)])``."""
        base = self
        while base.derivative_of is not None:
            base = system.equations[base.derivative_of]
        if base.combination:          # its text names every equation and component
            core = base.text
        else:                         # whole: a report wraps it, never cuts it
            core = f"{base.text}  [{base.where}]"
        if self.order == 0:
            return core
        power = f"^{self.order}" if self.order > 1 else ""
        return f"d{power}/dt{power}({core})"


def _derived_text(eq: SymbolicEquation) -> str:
    """``d/dt(<text of eq>)``, printed when read."""
    return f"d/dt({eq.text})"


@dataclass
class SymbolicSystem:
    """Equations and variables of the flat model after alias elimination."""

    equations: list
    symbols: list                                 # index -> sympy Symbol
    parameters: set
    var_info: dict = field(default_factory=dict)  # base symbol -> FlatVariable
    derivatives: dict = field(default_factory=dict)  # symbol -> der symbol
    index: dict = field(default_factory=dict)     # symbol -> index
    # delayed-value symbol -> DelayValue, input symbol -> InputValue: values that vary,
    # read from p, never differentiated
    delays: dict = field(default_factory=dict)

    @classmethod
    def from_flat(cls, flat) -> "SymbolicSystem":
        eqs = [SymbolicEquation(e.residual, e, e.component, e.component_class, e.kind,
                                label=e.label)
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
        from ...components.userfunctions import has_calls, structural_symbols
        found = structural_symbols(r, symbols_of) if has_calls(r) else symbols_of(r)
        vars_ = sorted(self.index[s] for s in found if s in self.index)
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
        tie = [state_tie_break(self.var_info[sym].attrs.fixed,
                               self.var_info[sym].attrs.nominal)
               if sym in self.var_info else 0 for sym in self.symbols]
        return Structure(graph=graph, var_to_diff=var_to_diff,
                         eq_to_diff=[UNASSIGNED] * len(graph), coeff=coeff,
                         var_names=names,
                         eq_names=Names(self._namer(e) for e in self.equations),
                         state_priority=priority, tie_break=tie)

    def _namer(self, eq: SymbolicEquation):
        # a bound call, not a lambda: a structure naming its equations stays picklable
        return bound(SymbolicEquation.name, eq, self)

    # -- differentiation (the Pantelides callback) --------------------------------------
    def differentiate(self, s: Structure, e: int):
        """Append d/dt of equation e; return its incidence (vars, coeff) in s's indices.

        Pantelides has already created der(v) in ``s`` for every v in e; we mirror
        those variables here so the indices agree.
        """
        self._sync_variables(s)
        eq = self.equations[e]
        dr = self.time_derivative(eq.residual)
        self.equations.append(SymbolicEquation(dr, bound(_derived_text, eq), eq.component,
                                               eq.component_class, eq.kind,
                                               derivative_of=e, order=eq.order + 1))
        self._sync_variables(s)
        return self.incidence(dr)

    def time_derivative(self, r: sp.Expr) -> sp.Expr:
        """d/dt r = sum_v dr/dv der(v) + dr/dt over the variables v of r, creating the
        der(v) symbols it needs (appended to ``symbols`` in the order of v).  A delayed
        value in r is refused: its derivative would be the delay of a derivative, which
        has no history."""
        if self.delays:
            found = [self.delays[q] for q in symbols_of(r) if q in self.delays]
            if found:
                d = found[0]
                if hasattr(d, "not_differentiable"):     # a top-level input
                    raise ModelError(d.not_differentiable())
                raise ModelError(
                    f"{d.text} in {d.where} appears in an equation that index reduction "
                    "must differentiate (a constraint on a state, e.g. a delayed position "
                    "imposed on a mass); a delay cannot be differentiated: delay a "
                    "signal that enters the model through an integrator or a force, or "
                    "use PadeDelay")
        from ...components.userfunctions import has_calls
        if has_calls(r):        # a user-defined function: by its derivative function
            from ...components.userfunctions import time_derivative
            return time_derivative(r, self._chain_rule)
        return self._chain_rule(r)

    def _chain_rule(self, r: sp.Expr) -> sp.Expr:
        dr = partial(r, time) if time in symbols_of(r) else sp.Integer(0)
        for sym in sorted((q for q in symbols_of(r) if q in self.index),
                          key=lambda q: self.index[q]):
            dr += sum_partial(r, sym) * derivative_symbol(sym, self.derivatives)
            self._add_symbol(self.derivatives[sym])
        return dr

    def _sync_variables(self, s: Structure) -> None:
        """Mirror the derivative variables Pantelides created (indices must agree)."""
        for k in range(len(self.symbols), s.n_vars):
            parent = self.symbols[s.diff_to_var[k]]
            self._add_symbol(derivative_symbol(parent, self.derivatives))


def coefficient_kind(r: sp.Expr, s: sp.Symbol, index: dict, parameters: set) -> int:
    """How symbol s enters residual r (graph.LINEAR_CONST ... NONLINEAR)."""
    # most variables enter one term of a sum as s, k*s or p*s: the coefficient is read
    # from that term (what sum_partial returns, without building it)
    terms = terms_with(r).get(s, ()) if r.is_Add else (r,)
    if len(terms) == 1:
        kind = _factor_kind(terms[0], s, parameters)
        if kind is not None:
            return kind
    c = sum_partial(r, s)
    if s in symbol_nodes(c):           # c.has(s)
        return NONLINEAR
    if c.is_number:
        return LINEAR_CONST if c != 0 else NONLINEAR
    if symbols_of(c) <= parameters:
        return LINEAR_PARAM
    return LINEAR_VAR


def _factor_kind(t, s, parameters: set) -> int | None:
    """The kind of the coefficient of s in the term t when t is s or a product in which
    s is one factor and the others are numbers and symbols (``-C*der(v)``): read from
    the other factors, without building their product; None for any other term."""
    if t is s:
        return LINEAR_CONST
    if type(t) is not sp.Mul:
        return None
    kind, found = LINEAR_CONST, False
    for f in t.args:
        if f is s:
            found = True
        elif type(f) in SYMBOLS:
            if f == s:
                return None         # an equal symbol of another object: sympy decides
            kind = max(kind, LINEAR_PARAM if f in parameters else LINEAR_VAR)
        elif not f.is_Number:
            return None
    return kind if found else None


def sum_partial(r: sp.Expr, x: sp.Symbol) -> sp.Expr:
    """``partial(r, x)``, the same expression, without a walk over all of a sum.

    d/dx of a sum is the sum of d/dx of the terms that contain x.  A node's balance of
    currents or forces has one term per connected component, and every variable of it
    needs its coefficient: looking through all terms for each would be quadratic, so a
    sum is indexed once by which of its terms contain which symbols.
    """
    if not r.is_Add:
        return partial(r, x)
    terms = terms_with(r).get(x)
    if terms is None:
        return sp.S.Zero
    if len(terms) == 1:
        return partial(terms[0], x)
    return sp.Add(*[partial(t, x) for t in terms])


# -- expression helpers, shared with flattening and alias elimination -------------------
@lru_cache(maxsize=200_000)
def symbols_of(expr: sp.Basic) -> frozenset:
    """``expr.free_symbols``, computed once per expression: every pass asks for it, and
    sympy walks the whole tree each time.  Walked here over the DAG (a shared part once,
    without recursion); a node that binds symbols of its own (an integral) answers for
    itself."""
    if expr.is_Symbol:
        return frozenset((expr,))
    if type(expr) not in _BINDING:
        out = flat_symbols(expr)
        if out is not None:
            return frozenset(out)
    out, stack, seen = set(), [expr], set()
    while stack:
        e = stack.pop()
        if e.is_Symbol:
            out.add(e)
        elif e.is_Atom or e in seen:
            continue
        elif type(e) in _BINDING:
            out |= e.free_symbols
        else:                         # over the DAG: a shared subexpression once
            seen.add(e)
            stack.extend(e.args)
    return frozenset(out)


def equation_symbols(eq) -> frozenset:
    """``symbols_of(eq.residual)`` for a FlatEquation, read off its terms while its
    residual is not made (``FlatEquation.unmade``)."""
    terms = eq.unmade
    if terms is None:
        return symbols_of(eq.residual)
    out = set()
    for q in terms:
        if type(q) in SYMBOLS:
            out.add(q)
        else:                          # der(x)
            out |= symbols_of(q)
    return frozenset(out)


# nodes that bind symbols of their own: they answer for themselves
_BINDING = (sp.Lambda, sp.Integral, sp.Derivative, sp.Subs, sp.Sum, sp.Product)


def forget_expressions() -> None:
    """Empty the caches of :func:`symbols_of`, ``terms_with``, :func:`negated`, the
    partial derivatives and the depths of expressions (a compile's end): the expressions
    they keep would outlive the compile, in memory and in every walk of the garbage
    collector over the live objects."""
    symbols_of.cache_clear()
    terms_with.cache_clear()
    forget_negated()
    forget_partials()
    depth.cache_clear()


def derivative_symbol(x: sp.Symbol, derivatives: dict) -> sp.Symbol:
    d = derivatives.get(x)
    if d is None:
        d = sp.Symbol(f"der({x.name})", real=True)
        derivatives[x] = d
    return d


# Most equations of a model, and all of its connections, are sums of symbols with signs
# (v = p.v - n.v, 0 = p.i + n.i, i = p.i, w = der(phi)).  Flattening builds their
# residuals from the terms, in the order sympy's Add would give them (sympy's own sort,
# _addsort): the same expression as lhs - rhs without the general machinery of Add and
# Mul.
_MINUS = sp.S.NegativeOne


def _plain_term(t) -> bool:
    """A symbol, or der() of a symbol."""
    return type(t) in SYMBOLS or (type(t) is der and type(t.args[0]) in SYMBOLS)


def signed_terms(side, sign: int, coeffs: dict) -> bool:
    """Add the terms of side, a sum of +-symbols and +-der(symbol) (or 0), to coeffs with
    sign; False if side is anything else or repeats a term (sympy combines those)."""
    if side is sp.S.Zero:
        return True
    for t in (side.args if side.is_Add else (side,)):
        if _plain_term(t):
            q, c = t, sign
        elif (t.is_Mul and len(t.args) == 2 and t.args[0] is _MINUS
              and _plain_term(t.args[1])):
            q, c = t.args[1], -sign
        else:
            return False
        if q in coeffs:
            return False
        coeffs[q] = c
    return True


def signed_sum(coeffs: dict) -> sp.Expr:
    """sum of c * q over coeffs {symbol q: +-1}, as sympy's Add builds it."""
    terms = [q if c == 1 else negated(q) for q, c in coeffs.items()]
    if len(terms) == 1:
        return terms[0]
    sort_args(terms)     # sympy's _addsort
    return sp.Add(*terms, evaluate=False)


class ExactText:
    """An exact text of a sympy expression (or a plain value), as ``srepr`` would give
    but in linear time: every node by its class and arguments, symbols by class and name,
    numbers exactly (a Float by its binary mantissa and exponent).  Shared subexpressions
    are printed once (sympy's printers take ~0.5 ms per small expression: a key printed
    with them costs as much as the flattening)."""

    def __init__(self, plain=repr):
        self.sp = sp
        self.plain = plain          # the text of a value that is not an expression
        self.memo = {}
        self.names = {}

    def __call__(self, e) -> str:
        sp = self.sp
        if not isinstance(e, sp.Basic):
            return self.plain(e)
        out = self.memo.get(e)
        if out is not None:
            return out
        stack = [(e, False)]
        while stack:          # iterative: a long sum or chain must not recurse deeply
            node, expanded = stack.pop()
            if node in self.memo:
                continue
            args = node.args
            if not args:
                self.memo[node] = self._atom(node)
            elif expanded:
                self.memo[node] = self._name(node) + "(" + ",".join(
                    self.memo[a] for a in args) + ")"
            else:
                stack.append((node, True))
                stack.extend((a, False) for a in args if a not in self.memo)
        return self.memo[e]

    def _name(self, node) -> str:
        t = type(node)
        name = self.names.get(t)
        if name is None:
            name = self.names[t] = f"{t.__module__}.{t.__name__}"
        return name

    def _atom(self, node) -> str:
        sp = self.sp
        if isinstance(node, sp.Symbol):      # x and x (real) are different symbols
            facts = ",".join(f"{k}={v}" for k, v in sorted(node.assumptions0.items()))
            return f"{self._name(node)}[{node.name};{facts}]"
        if isinstance(node, sp.Float):
            return f"F{node._mpf_!r}"
        if isinstance(node, sp.Rational):
            return f"Q{node.p}/{node.q}"
        if isinstance(node, (sp.NumberSymbol, sp.core.numbers.Infinity,
                             sp.core.numbers.NegativeInfinity, sp.core.numbers.NaN,
                             sp.core.numbers.ComplexInfinity, sp.core.numbers.ImaginaryUnit)):
            return self._name(node)
        return self._name(node) + ":" + sp.srepr(node)
