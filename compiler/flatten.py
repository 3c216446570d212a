"""Flattening: instance tree -> FlatModel (dotted names, connections resolved).

Connection semantics follow the Modelica specification (section 9.2): every port of a
component takes part in connections either from *inside* (the port belongs to a
sub-component of the component that writes ``connect``) or from *outside* (it is the
writing component's own port).  The ports joined by connect() form a node: across
variables are equal, and the through variables sum to zero, inside ports counted with
+1 and outside ports with -1.  A port that is never connected from outside its own
component (for the root: its own ports) gets through = 0.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp

from ..components.component import (Component, Connection, ModelError, Port,
                                     flatten_equation_list)
from ..components.declarations import Parameter, VariableAttributes
from ..components.symbols import Equation, When, der, pre, time

__all__ = ["FlatVariable", "FlatParameter", "FlatEquation", "FlatModel", "flatten"]


@dataclass
class FlatVariable:
    name: str
    symbol: sp.Symbol
    attrs: VariableAttributes
    component: str
    component_class: str
    kind: str = "variable"
    hint: str = ""            # the port's likely-mistake hint, for port variables

    @property
    def where(self) -> str:
        return f"{self.component or '(model)'} ({self.component_class})"


@dataclass
class FlatParameter:
    name: str
    symbol: sp.Symbol
    value: object
    unit: str = ""
    description: str = ""
    component: str = ""


@dataclass
class FlatEquation:
    residual: sp.Expr
    source: object            # the text, or the Equation it is printed from on demand
    component: str
    component_class: str
    kind: str = "equation"       # equation | connect | unconnected | initial
    label: str | None = None

    @property
    def where(self) -> str:
        return f"{self.component or '(model)'} ({self.component_class})"

    @property
    def text(self) -> str:
        """The equation as written (printed lazily: printing is slow on large models)."""
        if not isinstance(self.source, str):
            self.source = f"{sp.sstr(self.source.lhs)} = {sp.sstr(self.source.rhs)}"
        return self.source

    def describe(self) -> str:
        return f"{self.text}   [{self.kind} in {self.where}]"


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

    def variable(self, name: str) -> FlatVariable:
        for v in self.variables:
            if v.name == name:
                return v
        raise KeyError(name)


def flatten(model: Component) -> FlatModel:
    """Bind the instance tree, collect its declarations and equations, resolve connections."""
    if not isinstance(model, Component):
        raise ModelError(f"acausal compiles Components, got {model!r}")
    model._bind("")
    nodes = list(_walk(model))
    flat = FlatModel(name=type(model).__name__, variables=[], parameters=[], equations=[])
    connections = []
    for comp in nodes:
        flat.components[comp.path] = type(comp).__name__
        _collect_declarations(comp, flat)
        if isinstance(comp, Port):
            flat.ports.append((comp.path, type(comp).__name__, comp.effort, comp.flow))
            continue
        for item in _read(comp, "equations"):
            if isinstance(item, Connection):
                item.owner = comp
                connections.append(item)
            elif isinstance(item, When):
                item.origin, item.origin_class = comp.path, type(comp).__name__
                flat.whens.append(item)
            else:
                flat.equations.append(_flat_equation(item, comp, "equation"))
        for item in _read(comp, "initial_equations"):
            flat.initial_equations.append(_flat_equation(item, comp, "initial"))
    flat.equations.extend(_connection_equations(connections, nodes))
    _substitute_parameter_expressions(flat)
    _expand_derivatives(flat)
    return flat


def _walk(root: Component):
    stack = [root]
    while stack:
        comp = stack.pop()
        yield comp
        stack.extend(reversed(list(comp.children().values())))


def _read(comp: Component, method: str) -> list:
    try:
        items = flatten_equation_list(getattr(comp, method)())
    except ModelError:
        raise
    except Exception as err:  # the user's equations() raised: say where
        raise ModelError(f"while reading the {method.replace('_', ' ')} of "
                         f"{comp._describe()}: {type(err).__name__}: {err}") from err
    for item in items:
        if not isinstance(item, (Equation, Connection, When)):
            raise ModelError(f"{comp._describe()}.{method}() returned {item!r}; expected "
                             "ac.Eq(lhs, rhs), ac.connect(a, b) or ac.when(...)")
    return items


def _collect_declarations(comp: Component, flat: FlatModel) -> None:
    for name, decl in comp.declarations().items():
        sym = getattr(comp, name)
        if isinstance(decl, Parameter):
            value = comp.parameter_value(name)
            if value is None:
                raise ModelError(f"parameter '{sym.name}' of {comp._describe()} has no value")
            flat.parameters.append(FlatParameter(sym.name, sym, value, decl.unit,
                                                 decl.description, comp.path))
        else:
            hint = comp.hint if isinstance(comp, Port) else ""
            flat.variables.append(FlatVariable(sym.name, sym, comp.variable_attributes(name),
                                               comp.path, type(comp).__name__, decl.kind,
                                               hint))


def _flat_equation(eq: Equation, comp: Component, kind: str) -> FlatEquation:
    eq.origin, eq.origin_class = comp.path, type(comp).__name__
    return FlatEquation(eq.residual, eq, comp.path, type(comp).__name__, kind, eq.label)


# -- connections -----------------------------------------------------------------------
class _UnionFind:
    def __init__(self):
        self.parent = {}

    def find(self, a):
        self.parent.setdefault(a, a)
        root = a
        while self.parent[root] != root:
            root = self.parent[root]
        while self.parent[a] != root:  # path compression
            self.parent[a], a = root, self.parent[a]
        return root

    def union(self, a, b):
        ra, rb = self.find(a), self.find(b)
        if ra != rb:
            self.parent[max(ra, rb, key=_order_key)] = min(ra, rb, key=_order_key)


def _order_key(node):
    return node[2], node[1]


def _connection_equations(connections: list, nodes: list) -> list:
    """Across equal and through summing to zero per node; unconnected through = 0."""
    uf = _UnionFind()
    order = {id(c): k for k, c in enumerate(nodes)}
    ports = {}
    for conn in connections:
        keys = []
        for p in conn.ports:
            role = "outside" if getattr(p, "_parent", None) is conn.owner else "inside"
            key = (id(p), role, order[id(p)])
            ports[key] = p
            keys.append(key)
        for k in keys[1:]:
            uf.union(keys[0], k)
    groups = {}
    for key in sorted(ports, key=_order_key):
        groups.setdefault(uf.find(key), []).append(key)
    out = []
    for members in groups.values():
        out.extend(_node_equations([(ports[k], k[1]) for k in members], connections))
    connected_inside = {k[0] for k in ports if k[1] == "inside"}
    for comp in nodes:
        if isinstance(comp, Port) and id(comp) not in connected_inside:
            for name in comp.through():
                sym = getattr(comp, name)
                out.append(FlatEquation(sym, f"{sym.name} = 0", comp.path,
                                        type(comp).__name__, "unconnected"))
    return out


def _node_equations(members: list, connections: list) -> list:
    first, _ = members[0]
    where = ", ".join(p.path for p, _ in members)
    eqs = []
    for name in first.across():
        a = getattr(first, name)
        for p, _ in members[1:]:
            b = getattr(p, name)
            eqs.append(FlatEquation(a - b, f"{a.name} = {b.name}", where, "connect", "connect"))
    for name in first.through():
        terms = [(1 if role == "inside" else -1) * getattr(p, name) for p, role in members]
        total = sp.Add(*terms)
        eqs.append(FlatEquation(total, f"{sp.sstr(total)} = 0", where, "connect", "connect"))
    return eqs


# -- parameters bound to expressions, and der() ----------------------------------------
def _substitute_parameter_expressions(flat: FlatModel) -> None:
    """Substitute parameters bound to expressions of other parameters, and zeros.

    A parameter whose value is exactly 0 is a *structural* zero (Modelica tools evaluate
    such parameters, as with Evaluate=true): L*der(i) = v with L = 0 is the algebraic
    equation 0 = v, and index reduction must see it so.  Give a parameter a non-zero
    value to keep it tunable after compilation.
    """
    bound = {p.symbol: sp.sympify(p.value) for p in flat.parameters
             if isinstance(p.value, sp.Basic) and not p.value.is_number}
    zeros = {p.symbol: sp.Integer(0) for p in flat.parameters
             if not isinstance(p.value, sp.Basic) and _is_zero(p.value)}
    bound.update(zeros)
    for _ in range(64):  # resolve chains of bindings (depth = nesting of components)
        new = {k: v.xreplace(bound) for k, v in bound.items()}
        if new == bound:
            break
        bound = new
    flat.structural_zeros = sorted(p.name for p in flat.parameters if bound.get(p.symbol) == 0)
    if not bound:
        return
    for eq in flat.equations + flat.initial_equations:
        eq.residual = eq.residual.xreplace(bound)
    for w in flat.whens:
        w.condition = w.condition.xreplace(bound)
        for act in w.actions:
            act.value = act.value.xreplace(bound)


def _is_zero(value) -> bool:
    try:
        return float(value) == 0.0
    except (TypeError, ValueError):
        return False


def _expand_derivatives(flat: FlatModel) -> None:
    """Replace der(expr) by symbols der(x), expanding der of expressions by the chain rule."""
    var_syms = {v.symbol for v in flat.variables}
    for eq in flat.equations + flat.initial_equations:
        if eq.residual.has(der):
            eq.residual = _replace_der(eq.residual, var_syms, flat.derivatives)


def derivative_symbol(x: sp.Symbol, derivatives: dict) -> sp.Symbol:
    d = derivatives.get(x)
    if d is None:
        d = sp.Symbol(f"der({x.name})", real=True)
        derivatives[x] = d
    return d


def _replace_der(expr, var_syms, derivatives):
    def total_derivative(arg):
        arg = _replace_der(arg, var_syms, derivatives) if arg.has(der) else arg
        if arg in var_syms:
            return derivative_symbol(arg, derivatives)
        out = sp.diff(arg, time) if arg.has(time) else sp.Integer(0)
        for s in sorted(arg.free_symbols & (var_syms | set(derivatives.values())),
                        key=lambda s: s.name):
            if s in var_syms:
                var_syms_d = derivative_symbol(s, derivatives)
            else:  # s is already a derivative symbol: its derivative is the next one
                var_syms.add(s)
                var_syms_d = derivative_symbol(s, derivatives)
            out += sp.diff(arg, s) * var_syms_d
        return out

    return expr.replace(lambda e: isinstance(e, der), lambda e: total_derivative(e.args[0]))
