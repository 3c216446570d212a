"""Alias elimination: equations a = b, a = -b and a = constant leave the system.

Connections alone produce most of a flat model's equations, and almost all of them are
trivial.  Removing them before structural analysis keeps the later passes small.  Every
eliminated variable stays in the alias table, so results, reports and errors still show
it under its own name.

Alias sets are kept in a union-find with signs (x = s * root).  The representative of a
set is chosen canonically: the strongest state_select hint, then a variable that appears
differentiated, then one with a fixed start value, then declaration order.  Attributes
are merged onto the representative (start and fixed carried across with the sign).
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field, replace

import sympy as sp

from ...components.realsymbol import SYMBOLS
from ...components.symbols import Assign, Reinit, When
from ..algebra.derivative import partial
from ..algebra.exact import exact_value, parameter_values
from ..algebra.substitution import fast_xreplace, has_undefined, negated
from ..algebra.symbolic import equation_symbols, signed_terms, symbols_of
from ..flatmodel import FlatEquation, FlatModel
from ..structure.graph import STATE_SELECT
from ...errors import InvalidEquation, ModelError

__all__ = ["resolve_aliases_in", "AliasTable", "eliminate_aliases"]


@dataclass
class AliasTable:
    """name -> (sign, representative name) or (None, constant expression)."""

    aliases: dict = field(default_factory=dict)
    constants: dict = field(default_factory=dict)
    equations_before: int = 0
    equations_after: int = 0
    removed: list = field(default_factory=list)   # the FlatEquations that were removed

    def resolve(self, name: str):
        """(sign, name) of the variable that stands for ``name`` in the reduced system."""
        return self.aliases.get(name, (1, name))


def eliminate_aliases(flat: FlatModel) -> tuple[FlatModel, AliasTable]:
    """Return a new FlatModel without trivial equations, and the alias table."""
    syms = [v.symbol for v in flat.variables]
    # the variables by number: the union-find, the constants and the incidence are kept
    # on numbers (a look-up by symbol hashes it in Python, a list is indexed in C)
    order = {v.symbol: k for k, v in enumerate(flat.variables)}
    differentiated = set(flat.derivatives)
    params = frozenset(p.symbol for p in flat.parameters)
    # the union-find on variable numbers: up[k] is k's parent, sign[k] = +-1 with
    # x_k = sign[k] * x_up[k]; a root has up[k] == k
    up, sign_of = list(range(len(syms))), [1] * len(syms)
    constants = {}       # root number -> constant expression
    removed = []

    def find_k(k):
        """(sign, root number) of variable number k."""
        path, sign = [], 1
        while up[k] != k:
            path.append(k)
            sign *= sign_of[k]
            k = up[k]
        # path compression (with signs): every visited node now points at the root
        acc = sign
        for q in path:
            acc, sign_of[q] = acc * sign_of[q], acc
            up[q] = k
        return sign, k

    def rank(k):
        v = flat.variables[k]
        a = v.attrs
        return (-STATE_SELECT[a.state_select], v.symbol not in differentiated,
                not a.fixed, k)

    # Removing an alias can make a neighbouring equation trivial (a node's current sum
    # that collapses to gnd.p.i = 0), so the equations of a variable whose representative
    # or value a removal changed are substituted and classified again: a worklist.
    # Invariant: an equation is rewritten in the round in which one of its variables
    # stops being a representative, so by_var[r] holds every live equation that reads
    # a variable of r's set; touching only the changed variables' equations (not every
    # equation sharing a variable with the removed one: the N + 1 equalities of a node
    # of N + 2 ports share one) keeps the worklist linear in the incidence.
    eqs = list(flat.equations)
    alive = [True] * len(eqs)
    by_var = [None] * len(order)     # variable number -> the equations that read it

    def enter(i):
        for q in equation_symbols(eqs[i]):
            k = order.get(q)
            if k is not None:
                readers = by_var[k]
                if readers is None:
                    by_var[k] = {i}
                else:
                    readers.add(i)

    for i in range(len(eqs)):
        enter(i)
    queue = set(range(len(eqs)))
    while queue:
        touched = set()
        for i in sorted(queue):
            if not alive[i]:
                continue
            changed = _classify(eqs[i], order, find_k, rank, up, sign_of, constants, params)
            if changed is not None:
                alive[i] = False
                removed.append(eqs[i])
                for k in changed:
                    if by_var[k]:
                        touched |= by_var[k]
        queue = set()
        for j in touched:
            if not alive[j]:
                continue
            local = _substitutions_for(equation_symbols(eqs[j]), order, syms, find_k,
                                       constants)
            if local:
                eqs[j] = (_with_terms(eqs[j], local) or
                          _with_residual(eqs[j], fast_xreplace(eqs[j].residual, local)))
                enter(j)
                queue.add(j)
    kept = [eq for eq, a in zip(eqs, alive) if a]

    # the union-find is final: every variable's (sign, representative), once, in order
    resolved = [(sign, syms[k]) for sign, k in map(find_k, range(len(syms)))]
    constants = {syms[k]: value for k, value in constants.items()}   # by representative

    def find(s):
        k = order.get(s)
        return (1, s) if k is None else resolved[k]

    _check_fixed_constants(flat, find, constants)
    table = AliasTable(equations_before=len(flat.equations), removed=removed)
    subs = {}
    signs = {1: sp.Integer(1), -1: sp.Integer(-1)}
    for v, (sign, root) in zip(flat.variables, resolved):
        if root in constants:
            subs[v.symbol] = value = _signed(sign, constants[root])
            table.constants[v.name] = value
        elif root is not v.symbol:
            subs[v.symbol] = _signed(sign, root)
            table.aliases[v.name] = (signs[sign], root.name)
    return _rebuild(flat, kept, subs, table, find, constants, resolved), table


def _check_fixed_constants(flat, find, constants) -> None:
    """A variable with a fixed start value that an equation fixes to another constant is a
    contradiction (Modelica: an over-specified initial problem); say so by name.  The
    constant may be an expression of parameters (a capacitor across a constant source's
    ``V``): it is judged at the parameters' values."""
    values = None
    for v in flat.variables:
        if not v.attrs.fixed or v.attrs.start is None:
            continue
        sign, root = find(v.symbol)
        if root not in constants:
            continue
        value = _signed(sign, constants[root])
        if not value.is_number:
            if values is None:
                values = parameter_values(flat.parameters)
            exact = exact_value(value, values)
            if exact is None:
                continue
            value = sp.Float(float(exact))
        if abs(float(value) - v.attrs.start) > 1e-12 * (1 + abs(v.attrs.start)):
            raise ModelError(f"'{v.name}' in {v.where} has fixed=True with start = "
                             f"{v.attrs.start}, but its equations make it the constant "
                             f"{float(value):g}: the initial problem is over-specified")


def _signed(sign, expr):
    """``sign * expr`` for a sign of +-1, without sympy's multiplication (the same
    expression: 1*x is x, -1*x is -x)."""
    if sign == 1:
        return expr
    if sign == -1:
        return negated(expr) if type(expr) in SYMBOLS else -expr
    return sign * expr


def _substitutions_for(symbols, order, syms, find_k, constants) -> dict:
    """The substitution of the symbols whose variables are no longer representatives
    (``constants``: by representative number)."""
    out = {}
    for q in symbols:
        k = order.get(q)
        if k is None:
            continue
        sign, r = find_k(k)
        if r in constants:
            out[q] = _signed(sign, constants[r])
        elif r != k:
            out[q] = _signed(sign, syms[r])
    return out


def _with_residual(eq, residual):
    """``dataclasses.replace(eq, residual=residual)`` for a FlatEquation (whose fields
    have no __post_init__), without replace's field-by-field re-initialization."""
    out = object.__new__(type(eq))
    out.__dict__.update(eq.__dict__)
    out.residual = residual
    return out


def _with_terms(eq, subs):
    """A sum whose residual is not made yet (``FlatEquation.unmade``) with ``subs`` (each
    a +-symbol) applied to its terms, its residual still not made; None where ``subs``
    gives anything else or two terms of one symbol (the residual is made instead)."""
    terms = eq.unmade
    if terms is None:
        return None
    out = {}
    for q, c in terms.items():
        by = subs.get(q)
        if by is None:
            if q in out:
                return None
            out[q] = c
        elif by is sp.S.Zero or not signed_terms(by, c, out):
            return None
    made = object.__new__(type(eq))
    made.__dict__.update(eq.__dict__)
    made.terms = out
    return made


def _classify(eq, order, find_k, rank, up, sign_of, constants, params=frozenset()):
    """Record eq in the union-find (on variable numbers) if it is trivial.  None when it
    is kept; when it was removed, the numbers of the representatives whose resolution
    it changed (a set that now has a new representative, or a constant value)."""
    terms = eq.unmade
    pattern = _alias_pattern(eq.residual, order, params) if terms is None else \
        _terms_alias(terms, order)
    if pattern is False:                      # a sum of other terms: as made
        pattern = _alias_pattern(eq.residual, order, params)
    if pattern is None:
        return None
    kind, a, b, k = pattern
    if kind == "const":
        sa, ra = find_k(order[a])
        if ra in constants:
            return None           # a second value for the same variable: left for diagnosis
        constants[ra] = _signed(sa, k)
        return (ra,)
    k = int(k)
    (sa, ra), (sb, rb) = find_k(order[a]), find_k(order[b])
    if ra == rb or (ra in constants and rb in constants):
        return None               # a redundant or contradictory loop: left for diagnosis
    # a = k*b  =>  sa*ra = k*sb*rb  (all signs are +-1, so each is its own inverse)
    if rank(ra) <= rank(rb):
        child, root, sign = rb, ra, sa * k * sb
    else:
        child, root, sign = ra, rb, sb * k * sa
    up[child], sign_of[child] = root, sign
    if child in constants:
        constants[root] = _signed(sign, constants.pop(child))
        return child, root
    return (child,)


def _alias_pattern(residual: sp.Expr, info, params: frozenset = frozenset()):
    """Classify residual: ('alias', a, b, k) for a = k*b with k = +-1; ('const', a, None, c)
    for a = c with c a number or an expression of parameters.  None otherwise (``info``:
    the variables, as the keys of a mapping)."""
    fast = _plain_alias(residual, info)
    if fast is not None:
        return fast
    free = symbols_of(residual)
    # set operations on sets and dicts compare the hashes the sets keep (a look-up of
    # each symbol would hash it again, in Python)
    others = free.difference(info)
    if others - params:
        return None        # der(), time or unknown symbols: not a trivial equation
    syms = list(free - others)
    if len(syms) == 1:
        a = syms[0]
        ca = partial(residual, a)
        if not ca.is_number or ca == 0:
            return None
        if any(a in symbols_of(r) for r in residual.atoms(sp.core.relational.Relational)):
            return None    # a relation reads a: a = if a > p then .. (not a constant)
        rest = residual.xreplace({a: 0})
        return "const", a, None, -rest / ca
    if others or len(syms) != 2 or not residual.is_Add or len(residual.args) != 2:
        return None
    a, b = sorted(syms, key=lambda s: s.name)
    ca, cb = residual.coeff(a), residual.coeff(b)
    if ca in (1, -1) and cb in (1, -1):
        return "alias", a, b, -cb / ca
    return None


def _terms_alias(terms, info):
    """:func:`_alias_pattern` of the sum of ``terms`` {q: +-1} (not made yet) where they
    are all variables; False for another sum (which is made and takes the general
    path)."""
    if not all(type(q) in SYMBOLS and q in info for q in terms):
        return False
    if len(terms) > 2:
        return None               # three variables or more: no alias
    if len(terms) == 1:
        (q,) = terms
        return "const", q, None, sp.S.Zero
    a, b = sorted(terms, key=lambda s: s.name)
    return "alias", a, b, -terms[b] * terms[a]


def _plain_alias(residual: sp.Expr, info):
    """The pattern of the residuals connections make, read off their arguments: ``x``
    (x = 0) and ``+-a +- b``; None for anything else (which takes the general path,
    with the same result for these)."""
    if type(residual) in SYMBOLS:
        return ("const", residual, None, sp.S.Zero) if residual in info else None
    if not residual.is_Add or len(residual.args) != 2:
        return None
    signs = {}
    for t in residual.args:
        if type(t) in SYMBOLS and t in info:
            signs[t] = 1
        elif (t.is_Mul and len(t.args) == 2 and t.args[0] is sp.S.NegativeOne
              and type(t.args[1]) in SYMBOLS and t.args[1] in info):
            signs[t.args[1]] = -1
        else:
            return None
    a, b = sorted(signs, key=lambda s: s.name)
    return "alias", a, b, -signs[b] * signs[a]      # -sb/sa, the signs being +-1


def _rebuild(flat, kept, subs, table, find, constants, resolved):
    variables = [v for v, (_, root) in zip(flat.variables, resolved)
                 if root is v.symbol and root not in constants]
    merged, restated = _merge_attributes(flat, variables, resolved)
    derivatives = _derivatives_after_aliases(flat, find, constants, subs)
    equations = []
    for eq in kept:
        terms = eq.unmade                    # a sum not made yet: made substituted
        if terms is not None and not subs.keys().isdisjoint(terms):
            eq = _with_terms(eq, subs) or eq
        r = eq.residual
        if any(q in subs for q in symbols_of(r)):
            r = fast_xreplace(r, subs)
        if has_undefined(r):
            raise _divides_by_zero(eq, flat, find, constants)
        if r.is_Number and r == 0:
            by_name = {v.name: v.hint for v in flat.variables if v.hint}
            hints = sorted({by_name[w] for w in re.findall(r"[\w.\[\]]+", eq.text)
                            if w in by_name})
            raise ModelError(f"equation '{eq.text}' in {eq.where} is redundant: after "
                             "resolving aliases it reads 0 = 0 (over-determined model)"
                             + (": " + "; ".join(hints) if hints else ""))
        equations.append(_with_residual(eq, r))
    initial = [replace(eq, residual=eq.residual.xreplace(subs)) for eq in flat.initial_equations]
    initial += restated
    for eq in initial:
        if eq.residual.has(sp.zoo, sp.nan):
            raise _divides_by_zero(eq, flat, find, constants)
    table.equations_after = len(equations)
    whens = [_when_after_aliases(w, subs, find, constants) for w in flat.whens]
    return replace(flat, variables=merged, equations=equations, initial_equations=initial,
                   derivatives=derivatives, whens=whens)


def _divides_by_zero(eq, flat, find, constants) -> InvalidEquation:
    """An equation that divides by an expression its variables' constant values make 0
    (x = p and 1/(x - p)): a branch that cannot be taken is dropped by the substitution
    itself, so this division is reached whenever its branch is."""
    words = set(re.findall(r"[\w.\[\]]+", eq.text))
    fixed = []
    for v in flat.variables:
        sign, root = find(v.symbol)
        if v.name in words and root in constants:
            fixed.append(f"{v.name} = {sp.sstr(_signed(sign, constants[root]))}")
    why = (f" with {', '.join(fixed)} (their equations make them constants)" if fixed
           else " with its variables' constant values")
    return InvalidEquation(f"equation '{eq.text}' in {eq.where} divides by zero{why}; "
                           "the denominator is zero whenever this is evaluated: guard it "
                           "by a condition that is false there, or rewrite it")


def _derivatives_after_aliases(flat, find, constants, subs) -> dict:
    """The derivative chains of the representatives; subs maps every derivative of an
    eliminated variable onto its representative's (0 for a constant).

    A chain is followed to its end: with s = flange.s and der(der(flange.s)) written,
    der(der(flange.s)) becomes der(der(s)) (sign included), and the representative's
    chain grows where an alias's is longer; a derivative left behind would be a symbol
    that no equation defines."""
    chains = []
    for v in flat.variables:
        chain, at = [], v.symbol
        while at in flat.derivatives:
            at = flat.derivatives[at]
            chain.append(at)
        if chain:
            chains.append((find(v.symbol), v.symbol, chain))
    derivatives = {}
    # the representatives' own chains first: the symbols their equations already use
    for (sign, root), x, chain in chains:
        if root is x and root not in constants:
            derivatives.update(zip([x, *chain[:-1]], chain))
    for (sign, root), x, chain in chains:
        if root in constants:
            subs.update({dx: sp.Integer(0) for dx in chain})
        elif root is not x:
            at = root
            for dx in chain:
                if at not in derivatives:
                    derivatives[at] = sp.Symbol(f"der({at.name})", real=True)
                subs[dx] = _signed(sign, derivatives[at])
                at = derivatives[at]
    return derivatives


def _when_after_aliases(w, subs, find, constants):
    """A when-clause in representative variables: reinit(a, e) with a = s*r is reinit(r, s*e)."""
    actions = []
    for act in w.actions:
        if isinstance(act, Assign):          # writes a held value, not a variable
            actions.append(Assign(act.variable, act.value.xreplace(subs)))
            continue
        sign, root = find(act.variable)
        if root in constants:
            raise ModelError(f"reinit({act.variable}) in {w.origin or '(model)'}: the variable "
                             "is fixed by an equation (a constant), it cannot be re-initialized")
        actions.append(Reinit(root, _signed(sign, act.value.xreplace(subs))))
    out = When(w.condition.xreplace(subs), *actions)
    out.origin, out.origin_class, out.equation = w.origin, w.origin_class, w.equation
    out.pulse = w.pulse
    return out


def _merge_attributes(flat, variables, resolved):
    """Carry start/fixed/nominal/state_select from aliases onto their representative
    (``resolved``: each flat variable's (sign, representative)).  Returns the merged
    attributes and, for every alias whose fixed start value its representative already
    has one of, that condition as an initial equation on the representative: a second
    condition on the same value is redundant, checked and dropped at the initial point
    when the two agree, an error naming both when they do not
    (:mod:`acausal.runtime.redundant`)."""
    out = {v.symbol: v.attrs for v in variables}
    restated = []
    for v, (sign, root) in zip(flat.variables, resolved):
        if root is v.symbol or root not in out:
            continue
        a, r = v.attrs, out[root]
        if a.start is not None:
            sign = sp.Integer(sign)   # the signed start value is a sympy number, as ever
        new = r
        if a.start is not None and (r.start is None or (a.fixed and not r.fixed)):
            new = replace(new, start=sign * a.start, fixed=a.fixed or r.fixed)
        elif a.fixed and a.start is not None and r.start is not None and r.fixed:
            restated.append(FlatEquation(
                root - sign * a.start,
                f"{v.name} = {a.start} (fixed start value; an alias of {root.name})",
                v.component, v.component_class, kind="initial"))
        if a.nominal and (not r.nominal or a.nominal > r.nominal):
            new = replace(new, nominal=a.nominal)
        if STATE_SELECT[a.state_select] > STATE_SELECT[new.state_select]:
            new = replace(new, state_select=a.state_select)
        out[root] = new
    # a representative whose attributes nothing changed is kept as it is (the same
    # value replace() would copy)
    return [v if out[v.symbol] is v.attrs else replace(v, attrs=out[v.symbol])
            for v in variables], restated


def resolve_aliases_in(values, flat, aliases) -> None:
    """Values found before alias elimination (frozen floor values, delays) whose arguments
    get the same substitution as the equations: ``mod(u, 1)`` of a ``u`` that is an alias
    of the state ``x`` reads ``x``."""
    if not values:
        return
    by_name = {v.name: v.symbol for v in flat.variables}
    subs = {}
    for v in flat.variables:
        if v.name in aliases.constants:
            subs[v.symbol] = sp.sympify(aliases.constants[v.name])
            continue
        sign, root = aliases.resolve(v.name)
        if root != v.name and root in by_name:
            subs[v.symbol] = sign * by_name[root]
    for d in values:
        if d.argument.free_symbols & subs.keys():
            d.argument = d.argument.xreplace(subs)
