"""Flattening: instance tree -> FlatModel (dotted names, connections resolved).

Connection semantics follow the Modelica specification (section 9.2): every port of a
component takes part in connections either from *inside* (the port belongs to a
sub-component of the component that writes ``connect``) or from *outside* (it is the
writing component's own port).  The ports joined by connect() form a node: across
variables are equal, and the through variables sum to zero, inside ports counted with
+1 and outside ports with -1.  A port that is never connected from outside its own
component (for the root: its own ports) gets through = 0.

Flattening, where the names of equations and connections become known, checks what
the components cannot (raising ``ModelError`` subclasses): every symbol of an equation
belongs to the model, a connected port lies inside the component that connects it,
``der()`` applies to something that varies, parameter bindings depend on parameters only
and are not circular, values respect [min, max], and an infinite parameter leaves its
equations finite (``1/Tt`` with Tt = inf is 0; ``R*i`` with R = inf is not).
"""
from __future__ import annotations

import sympy as sp

from ...components import inheritance
from ...components.component import Component, Connection, Port, compiling, in_context
from ...components.declarations import Parameter, bound_violation
from ...components.expandable import drop_bus_members, resolve_buses
from ...components.initparams import parameter_start
from ...components.logic import INITIAL
from ...components.realsymbol import SYMBOLS
from ...components.portgroups import expand_connection, port_owner
from ...components.symbols import Equation, When, der, time
from ..algebra.substitution import fast_difference, fast_xreplace, has_undefined
from .flatarrays import collect_array
from .inputs import find_inputs
from .flatder import check_der_arguments, expand_derivatives, has_der
from ..algebra.symbolic import equation_symbols, signed_sum, signed_terms, symbols_of
from .usercode import failed_reading
from ..flatmodel import FlatEquation, FlatModel, FlatParameter, FlatVariable
from ...errors import (InvalidConnection, InvalidEquation, InvalidValue, ModelError,
                       NotInModel)

__all__ = ["flatten"]


def flatten(model: Component) -> FlatModel:
    """Bind the instance tree, collect its declarations and equations, resolve connections."""
    if not isinstance(model, Component):
        raise ModelError(f"acausal compiles Components, got {model!r}")
    model._bind("")
    nodes = drop_bus_members(list(_walk(model)))
    flat = FlatModel(name=type(model).__name__, variables=[], parameters=[], equations=[])
    connections = []
    with_der = set()     # ids of the flat equations whose residuals contain der()
    known = {}           # the classes' own equation methods (inheritance.collect)
    with compiling(model):
        for comp in nodes:
            flat.components[comp.path] = type(comp).__name__
            _collect_declarations(comp, flat)
            if isinstance(comp, Port):
                flat.ports.append((comp.path, type(comp).__name__, comp.effort, comp.flow))
                continue
            for item in _read(comp, "equations", known):
                if isinstance(item, Connection):
                    item.owner = comp
                    connections.extend(expand_connection(item))
                elif isinstance(item, When):
                    item.origin, item.origin_class = comp.path, type(comp).__name__
                    flat.whens.append(item)
                else:
                    flat.equations.append(_flat_equation(item, comp, "equation", with_der))
            for item in _read(comp, "initial_equations", known):
                if not isinstance(item, Equation):
                    raise InvalidEquation(f"{comp._describe()}.initial_equations() returned "
                                          f"{item!r}; expected ac.Eq(lhs, rhs)")
                flat.initial_equations.append(_flat_equation(item, comp, "initial", with_der))
            for item in _steady_state_equations(comp):
                flat.initial_equations.append(_flat_equation(item, comp, "initial", with_der))
    flat.uses_initial = bool(getattr(model, "_uses_initial", False))
    _check_connections(connections, model)
    connections, members = resolve_buses(connections, model)
    for member in members:         # the signals and buses on the model's buses
        nodes.append(member)
        flat.components[member.path] = type(member).__name__
        flat.ports.append((member.path, type(member).__name__, member.effort, member.flow))
        with compiling(model):
            _collect_declarations(member, flat)
    flat.equations.extend(_connection_equations(connections, nodes))
    flat.inputs = find_inputs(flat, model, connections)
    _check_symbols(flat, with_der)
    # substitution first: a structural zero removes the derivative it multiplies
    # (L*der(i) with L = 0), and no der(i) may be created for it (substituting
    # parameters makes no der(): with_der still holds every residual that has one)
    _substitute_parameter_expressions(flat)
    expand_derivatives(flat, with_der)
    _check_infinite_parameters(flat)
    return flat


def _steady_state_equations(comp) -> list:
    """``der(v) = 0`` at the start for each variable of ``comp`` declared or modified
    ``steady=True`` (a steady state: ``Inertia(w={"steady": True})``)."""
    out = []
    for name, decl in comp.declarations().items():
        if isinstance(decl, Parameter) or decl.shape is not None:
            continue
        if getattr(comp.variable_attributes(name), "steady", False):
            out.append(Equation(der(getattr(comp, name)), 0,
                                label=f"steady state of {name} at the start"))
    return out


def _walk(root: Component):
    stack = [root]
    while stack:
        comp = stack.pop()
        yield comp
        stack.extend(reversed(list(comp.children().values())))


def _read(comp: Component, method: str, known: dict) -> list:
    """The items of ``comp``'s ``method`` over its class hierarchy (``inheritance``):
    each class's own method once, base classes first, each item checked (``known``:
    the classes' own methods, found once per flattening)."""
    try:
        parts = inheritance.collect(comp, method, known)
    except ModelError as err:
        raise in_context(err, f"{comp._describe()}.{method}()") from err
    except Exception as err:  # the user's equations() raised: say where
        raise ModelError(failed_reading(method, comp._describe(), err)) from err
    items = []
    for klass, part in parts:
        if part is None:
            where = f"{comp._describe()}.{method}()"
            whose = where if klass is type(comp) else f"{where} (of {klass.__name__})"
            raise InvalidEquation(f"{whose} returned None; it must return a list of "
                                  "equations (is a 'return' missing?)")
        items.extend(part)
    for item in items:
        if not isinstance(item, (Equation, Connection, When)):
            hint = (" (a sympy relation or a truth value: acausal's equation is "
                    "ac.Eq(lhs, rhs))") if isinstance(item, (sp.Basic, bool)) else ""
            raise InvalidEquation(f"{comp._describe()}.{method}() returned {item!r}{hint}; "
                                  "expected ac.Eq(lhs, rhs), ac.connect(a, b) or "
                                  "ac.when(...)")
    return items


def _collect_declarations(comp: Component, flat: FlatModel) -> None:
    for name, decl in comp.declarations().items():
        if decl.shape is not None:
            collect_array(comp, name, decl, flat)
            continue
        sym = getattr(comp, name)
        if isinstance(decl, Parameter):
            try:    # found by initialization (fixed=False): its start is the guess
                start = parameter_start(comp, name, decl)
            except ValueError as err:
                raise InvalidValue(f"{comp._describe()}: {err}") from None
            value = comp.parameter_value(name) if start is None else start
            if value is None:
                raise ModelError(f"parameter '{sym.name}' of {comp._describe()} has no value")
            flat.parameters.append(FlatParameter(sym.name, sym, value, decl.unit,
                                                 decl.description, comp.path,
                                                 type(comp).__name__, decl.min, decl.max,
                                                 decl.type, start is None))
        else:
            hint = comp.hint if isinstance(comp, Port) else ""
            flat.variables.append(FlatVariable(sym.name, sym, comp.variable_attributes(name),
                                               comp.path, type(comp).__name__, decl.kind,
                                               hint))


def _flat_equation(eq: Equation, comp: Component, kind: str, with_der: set) -> FlatEquation:
    """The FlatEquation of ``eq``; its id is added to ``with_der`` if it has a der()."""
    eq.origin, eq.origin_class = comp.path, type(comp).__name__
    coeffs = {}
    plain = signed_terms(eq.lhs, 1, coeffs) and signed_terms(eq.rhs, -1, coeffs) and coeffs
    if plain:           # the residual is made from the terms when read (FlatEquation)
        residual = None
        ders = any(type(q) is der for q in coeffs)
    else:
        residual = fast_difference(eq.lhs, eq.rhs)     # eq.residual, built directly
        ders = has_der(residual)
    out = FlatEquation(residual, eq, comp.path, type(comp).__name__, kind, eq.label,
                       terms=coeffs if plain else None)
    if type(eq.lhs) in SYMBOLS:
        out.defines = eq.lhs
    if ders:
        with_der.add(id(out))
    return out


# -- connections -----------------------------------------------------------------------
class _UnionFind:
    """Connection sets; the root of a set is its first port in declaration order."""

    def __init__(self):
        self.parent = {}

    def find(self, a):
        root = self.parent.setdefault(a, a)
        while self.parent[root] != root:
            root = self.parent[root]
        while self.parent[a] != root:  # path compression
            self.parent[a], a = root, self.parent[a]
        return root

    def union(self, a, b):
        ra, rb = sorted((self.find(a), self.find(b)), key=_order_key)
        self.parent[rb] = ra


def _order_key(node):
    return node[2], node[1]


def _check_connections(connections: list, root: Component) -> None:
    """Every port of a connect() is in the model, and is the writing component's own or
    lies inside one of its sub-components (Modelica 9.1)."""
    for conn in connections:
        for p in conn.ports:
            if p._root is not root:
                whose = (f"'{p.path}' of another model instance" if p._path is not None
                         else "a port of a component that was never made part of it")
                raise NotInModel(f"{conn!r} in {conn.owner._describe()}: the model "
                                 f"({type(root).__name__}) does not contain this "
                                 f"{type(p).__name__}: it is {whose}")
            node = p._parent
            while node is not None and node is not conn.owner:
                node = node._parent
            if node is None:
                raise InvalidConnection(
                    f"{conn!r} in {conn.owner._describe()}: port '{p.path}' is neither a "
                    f"port of {conn.owner._describe()} nor inside one of its "
                    "sub-components; connect it where both ends are visible")


def _connection_equations(connections: list, nodes: list) -> list:
    """Across equal and through summing to zero per node; unconnected through = 0."""
    uf = _UnionFind()
    order = {id(c): k for k, c in enumerate(nodes)}
    ports = {}
    for conn in connections:
        keys = []
        for p in conn.ports:
            role = "outside" if port_owner(p) is conn.owner else "inside"
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
            plain = a != b and type(a) in SYMBOLS and type(b) in SYMBOLS
            diff = None if plain else signed_sum({a: 1, b: -1}) if a != b else a - b
            eqs.append(FlatEquation(diff, f"{a.name} = {b.name}", where, "connect",
                                    "connect", terms={a: 1, b: -1} if plain else None))
    for name in first.through():
        signed = [(getattr(p, name), 1 if role == "inside" else -1) for p, role in members]
        coeffs = dict(signed)
        plain = len(coeffs) == len(signed) and all(type(q) in SYMBOLS for q in coeffs)
        if plain:       # printed from its residual, made when read (FlatEquation)
            eqs.append(FlatEquation(None, coeffs, where, "connect", "connect", terms=coeffs))
            continue
        total = sp.Add(*[c * q for q, c in signed])
        eqs.append(FlatEquation(total, total, where, "connect", "connect"))
    return eqs


# -- what equations and parameter bindings may refer to -----------------------------------
def _check_symbols(flat: FlatModel, with_der: set) -> None:
    """Parameter bindings use only parameters; equations use only the model's variables,
    parameters and time, and at least one variable (``with_der``: the ids of the
    equations with der(), whose arguments are checked)."""
    var_syms = {v.symbol for v in flat.variables}
    par_syms = {p.symbol for p in flat.parameters}
    allowed = var_syms | par_syms | {time, INITIAL}
    for p in flat.parameters:
        if isinstance(p.value, sp.Basic) and not p.value.is_number:
            _check_binding(p, p.value.free_symbols, var_syms, allowed)
    for eq in flat.equations + flat.initial_equations:
        if eq.kind not in ("equation", "initial"):
            continue   # connection equations are built from the model's own ports
        free = equation_symbols(eq)
        if not free <= allowed:
            _check_known(free - allowed, f"equation '{eq.text}' in {eq.where}")
        if id(eq) in with_der:
            check_der_arguments(eq, var_syms)
        if free.isdisjoint(var_syms):
            raise InvalidEquation(f"equation '{eq.text}' in {eq.where} involves no "
                                  "variable of the model (only parameters, time and "
                                  "numbers): it cannot determine anything")
    for w in flat.whens:
        free = set(w.condition.free_symbols)
        for act in w.actions:
            free |= act.variable.free_symbols | act.value.free_symbols
        if not free <= allowed:
            _check_known(free - allowed,
                         f"when {w.condition} in {w.origin or '(model)'} ({w.origin_class})")


def _check_binding(p: FlatParameter, free: set, var_syms: set, allowed: set) -> None:
    if free <= allowed and time not in free and not p.value.has(der) \
            and free.isdisjoint(var_syms):
        return
    where = f"{p.describe()} = {sp.sstr(p.value)}"
    on_vars = sorted(s.name for s in free & var_syms)
    if on_vars:
        raise InvalidValue(f"{where} depends on the variable(s) {', '.join(on_vars)}; a "
                           "parameter's value may depend only on other parameters")
    if time in free:
        raise InvalidValue(f"{where} depends on time; a parameter is constant (declare a "
                           "Variable with an equation instead)")
    if p.value.has(der):
        raise InvalidValue(f"{where} contains der(); a parameter is constant")
    _check_known(free - allowed, where)


def _check_known(unknown: set, where: str) -> None:
    if unknown:
        names = ", ".join(f"'{s.name}'" for s in sorted(unknown, key=lambda s: s.name))
        raise NotInModel(f"{where} uses {names}, which the model being compiled does not "
                         "declare: a sympy Symbol made outside the model, or a variable "
                         "of another model instance (use the variables and parameters "
                         "of the model's own components)")


# -- parameters bound to expressions, and der() ----------------------------------------
def _substitute_parameter_expressions(flat: FlatModel) -> None:
    """Substitute parameters bound to expressions of other parameters, and zeros.

    A parameter whose value is exactly 0 is a *structural* zero (Modelica tools evaluate
    such parameters, as with Evaluate=true): L*der(i) = v with L = 0 is the algebraic
    equation 0 = v, and index reduction must see it so.  Give a parameter a non-zero
    value to keep it tunable after compilation.  Every value, bound or not, is checked
    against its declared [min, max].
    """
    resolved = _resolve_bindings(flat)
    # (a Boolean or Integer parameter stays tunable at 0: false, or a count of none)
    # (nor is a parameter found by initialization: its value is a guess)
    zeros = {p.symbol: sp.Integer(0) for p in flat.parameters
             if p.symbol not in resolved and _is_zero(p.value) and not hasattr(p, "tunable")
             and p.type is float and p.fixed}
    bound = {k: v.xreplace(zeros) for k, v in resolved.items()}
    bound.update(zeros)
    _check_bounds(flat, resolved)
    flat.structural_zeros = sorted(p.name for p in flat.parameters if bound.get(p.symbol) == 0)
    if not bound:
        return
    for eq in flat.equations + flat.initial_equations:
        used = equation_symbols(eq) & bound.keys()
        if used:
            eq.residual = fast_xreplace(eq.residual, bound)
            if has_undefined(eq.residual):
                _divided_by_zero(flat, used, zeros, eq)
    for w in flat.whens:
        w.condition = w.condition.xreplace(bound)
        for act in w.actions:
            act.value = act.value.xreplace(bound)


def _divided_by_zero(flat: FlatModel, used: set, zeros: dict, eq) -> None:
    """A structural zero (directly or through a parameter bound to it) that leaves an
    equation with 1/0: name the zero parameters and the equation."""
    names = {p.symbol: p for p in flat.parameters}
    culprits = {s for s in used if s in zeros}
    culprits |= {z for s in used - culprits
                 for z in sp.sympify(names[s].value).free_symbols if z in zeros}
    which = " and ".join(f"{names[s].describe()} = 0"
                         for s in sorted(culprits or used, key=lambda s: s.name))
    raise InvalidValue(f"{which} makes the equation '{eq.text}' in {eq.where} divide by "
                       "zero (a parameter of exactly 0 is a structural zero, substituted "
                       "before compiling); give it a non-zero value")


def _is_expression(value) -> bool:
    return isinstance(value, sp.Basic) and not value.is_number


def _resolve_bindings(flat: FlatModel) -> dict:
    """symbol -> its binding in unbound parameters only, in dependency order (Kahn);
    a cycle of bindings is an error naming it."""
    exprs = {p.symbol: sp.sympify(p.value) for p in flat.parameters if _is_expression(p.value)}
    waits = {s: e.free_symbols & exprs.keys() for s, e in exprs.items()}
    users = {s: [] for s in exprs}
    for s, deps in waits.items():
        for d in deps:
            users[d].append(s)
    ready = [s for s in exprs if not waits[s]]
    resolved = {}
    while ready:
        s = ready.pop()
        deps = exprs[s].free_symbols & exprs.keys()
        resolved[s] = exprs[s].xreplace({d: resolved[d] for d in deps})
        for u in users[s]:
            waits[u].discard(s)
            if not waits[u]:
                ready.append(u)
    if len(resolved) < len(exprs):
        raise _cycle_error(flat, exprs, {s: w for s, w in waits.items() if w})
    return resolved


def _cycle_error(flat: FlatModel, exprs: dict, waits: dict) -> InvalidValue:
    by_symbol = {p.symbol: p for p in flat.parameters}
    start = next(p.symbol for p in flat.parameters if p.symbol in waits)
    chain = [start]
    while True:   # follow unresolved dependencies until one repeats: that is a cycle
        nxt = min(waits[chain[-1]], key=lambda s: s.name)
        if nxt in chain:
            cycle = chain[chain.index(nxt):] + [nxt]
            break
        chain.append(nxt)
    steps = ", ".join(f"{s.name} = {sp.sstr(exprs[s])}" for s in cycle[:-1])
    return InvalidValue(f"parameters {' -> '.join(s.name for s in cycle)} are defined in "
                        f"terms of each other ({steps}); a parameter binding may not "
                        f"depend on itself [{by_symbol[start].where}]")


def _check_bounds(flat: FlatModel, resolved: dict) -> None:
    """Each parameter's value (a binding evaluated with the values it uses) is a real
    number within its declared [min, max]."""
    # the values bindings are evaluated with: only those of the parameters they read
    read = set().union(*(e.free_symbols for e in resolved.values())) if resolved else ()
    leaf = {q.symbol: _as_sympy_number(q.value) for q in flat.parameters
            if q.symbol in read and q.symbol not in resolved}
    free = {q.symbol for q in flat.parameters if not q.fixed}   # found by initialization
    for p in flat.parameters:
        if p.symbol in resolved:
            expr = resolved[p.symbol].xreplace(leaf)
            try:
                value = float(expr)
            except (TypeError, ValueError):
                raise InvalidValue(f"{p.describe()} = {sp.sstr(p.value)} (= {sp.sstr(expr)}) "
                                   "is not a real number") from None
            if value != value:
                raise InvalidValue(f"{p.describe()} = {sp.sstr(p.value)} (= {value!r}) "
                                   "is not a number (NaN)")
            source = sp.sstr(p.value)
            if resolved[p.symbol].free_symbols & free:   # it follows a value still unknown
                flat.derived[p.name] = (source, None)
                continue
            flat.derived[p.name] = (source, value)
            why = bound_violation(value, p.min, p.max)
            if why:
                raise InvalidValue(f"{p.describe()} = {source} (= {value!r}) {why}")
        else:
            value = float(p.value)
            why = bound_violation(value, p.min, p.max)
            if why:
                raise InvalidValue(f"{p.describe()} = {p.value!r} {why}")


def _as_sympy_number(value) -> sp.Expr:
    x = float(value)
    if abs(x) == float("inf"):
        return sp.oo if x > 0 else -sp.oo
    return sp.sympify(value) if isinstance(value, (int, sp.Basic)) else sp.Float(x)


def _is_zero(value) -> bool:
    try:
        return float(value) == 0.0
    except (TypeError, ValueError):   # an expression of parameters
        return False


_NON_FINITE = (sp.oo, -sp.oo, sp.zoo, sp.nan)


def _check_infinite_parameters(flat: FlatModel) -> None:
    """An infinite parameter value must leave the equations finite (1/Tt -> 0, a limit
    of a clip never reached); where it does not (R*i), name the equation."""
    infinite = {p.symbol: _as_sympy_number(p.value) for p in flat.parameters
                if not _is_expression(p.value) and abs(float(p.value)) == float("inf")}
    if not infinite:
        return
    names = {p.symbol: p for p in flat.parameters}
    checks = [(eq.residual, f"equation '{eq.text}' in {eq.where}")
              for eq in flat.equations + flat.initial_equations]
    checks += [(act.value, f"reinit({act.variable}, {act.value}) in "
                f"{w.origin or '(model)'} ({w.origin_class})")
               for w in flat.whens for act in w.actions]
    for expr, where in checks:
        used = symbols_of(expr) & infinite.keys()
        if used and expr.xreplace(infinite).has(*_NON_FINITE):
            which = " and ".join(f"{names[s].describe()} = {names[s].value!r}"
                                 for s in sorted(used, key=lambda s: s.name))
            raise InvalidValue(f"{which} makes the {where} infinite or undefined; an "
                               "infinite value is allowed only where the equations have a "
                               "finite limit (as 1/Tt for Tt = inf)")
