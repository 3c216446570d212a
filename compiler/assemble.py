"""The ``assemble`` and ``codegen`` passes: the index-reduced system put in the form the
solver sees (full or causal, :mod:`acausal.compiler.structure.causalize`), and its
relations, initial equations, when-clauses and delays with the generated code of each
(:mod:`acausal.compiler.backends.codegen`), gathered in a :class:`ModelCode`.
"""
from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import sympy as sp

from ..components.declarations import TYPE_NAMES
from ..components.logic import INITIAL
from ..components.symbols import time
from ..components.units import output_tables
from ..components.userfunctions import has_calls, inline_functions
from .algebra.derivative import solve_linear
from .algebra.symbolic import symbols_of
from .backends.cbackend import programs
from .backends.codegen import FrozenSymbols, event_form, extract_relations, generate
from .backends.domains import output_checks
from .backends.parametric import parameter_functions
from .frontend.outline import definition_of
from .frontend.sampled import when_rows as clause_rows
from .index.numeric import CoefficientValues, is_number
from .initrows import choose_initial_rows, followers, free_parameters
from .modelcode import (DelayCode, DynamicSets, InitialCode, InputCode, ModelCode, RelationInfo,
                        WhenCode)
from .report import EquationNames
from .structure.causalize import causalize, full_form
from .structure.graph import LINEAR_CONST, UNASSIGNED
from ..components.operators import no_event
from ..errors import InvalidEquation, ModelError
from ..words import shortened

__all__ = ["assemble", "model_code", "choose_initial_rows", "delay_code", "feeds_back"]


def assemble(system, reduction, reduced, report, discretes, helds=()):
    """The form the solver sees (:class:`~acausal.compiler.structure.causalize.Causalization`):
    with dynamic state selection every variable stays an unknown (the full form); else the
    BLT order and tearing decide what the solver vector holds, torn blocks checked
    numerically at the compile-time values of their coefficients."""
    syms = system.symbols
    _inline_after_index_reduction(system, reduction)
    if reduction.dynamic:
        caus = full_form(reduction, len(syms), len(system.equations),
                         _fixed_definitions(system, reduction))
    else:
        held_items = [SimpleNamespace(symbol=s) for h in helds for s in (h.symbol, h.pre)]
        held_items.append(SimpleNamespace(symbol=INITIAL))
        values = CoefficientValues(system, reduced.parameters, list(discretes) + held_items)
        caus = causalize(reduction, values)
        untorn = [b for b in caus.blocks if b.get("not_torn")]
        for b in untorn[:5]:
            report.notes.append(f"algebraic block of {b['size']} equations not torn "
                                f"({b['not_torn']}), e.g. {syms[b['variables'][0]].name}")
    report.blocks = caus.blocks
    report.kept_for_fill = [syms[v].name for v in caus.kept_for_fill]
    return caus


def model_code(system, reduction, caus, reduced, flat, aliases, report, discretes,
               helds=(), delays=(), programs_made=None) -> ModelCode:
    """The ModelCode of the index-reduced ``system`` in the form ``caus``.
    ``programs_made``, if given, is called with the generated Programs by prefix
    (:func:`acausal.compiler.backends.cbackend.programs`) as soon as they are all made,
    before the rest of the ModelCode: the C backend can print and compile them meanwhile
    (:mod:`acausal.compiler.pipeline`)."""
    syms = system.symbols
    z_syms = [syms[v] for v in caus.z]
    assigned = [(syms[v], solve_linear(system.equations[e].residual, syms[v]))
                for v, e in caus.assignments]
    for (x, expr), (v, e) in zip(assigned, caus.assignments):
        _check_live_self_reference(system, e, x, expr)
    rows = [system.equations[e].residual for e in caus.residual_eqs]
    n_res = len(rows)
    s = reduction.structure
    if caus.causal:   # der(s) of every state, computed by the assignments
        rows += [syms[s.var_to_diff[v]] for v in caus.z[: caus.n_states]]
        state_z, pairs, dummies = list(range(caus.n_states)), [], []
    else:
        zpos = {v: k for k, v in enumerate(caus.z)}
        state_z = []
        pairs = [(zpos[a], zpos[b]) for a, b in reduction.pairs]
        dummies = [zpos[d] for d in reduction.dummies]
    init_rows, init_text, n_mandatory, init_sizes = _initial_rows(system, reduced,
                                                                   reduction, caus)
    when_rows, when_layout = clause_rows(reduced.whens, z_syms, caus, pairs, helds, assigned)
    delay_rows = [d.argument for d in delays]
    sizes = [len(assigned), len(rows), len(init_rows), len(when_rows), len(delay_rows)]
    everything = [e for _, e in assigned] + rows + init_rows + when_rows + delay_rows
    # user-defined functions are inlined once index reduction has differentiated them
    everything = [inline_functions(e) for e in everything]
    uses_initial = bool(getattr(flat, "uses_initial", False))
    # m: relation values, floor values, then held(y) and pre(y) of the discrete
    # variables, then initial() if the model reads it
    dsyms = [d.symbol for d in discretes] + [h.symbol for h in helds] + \
        [h.pre for h in helds] + ([INITIAL] if uses_initial else [])
    exprs, crossings, modes, origin = extract_relations(
        everything, _frozen(reduced, dsyms, assigned))
    parts = np.split(np.array(exprs, dtype=object), np.cumsum(sizes)[:-1])
    assigned = [(a, e) for (a, _), e in zip(assigned, parts[0])]
    rows, init_rows, when_rows = list(parts[1]), list(parts[2]), list(parts[3])
    delay_rows = list(parts[4])
    zeros = set(reduced.structural_zeros)
    params = [p for p in reduced.parameters if is_number(p.value) and p.name not in zeros]
    psyms = [p.symbol for p in params]
    # the delayed values are read from p after the tunable parameters (runtime/delays.py)
    # then the top-level inputs' values, written by the runtime (runtime/inputs.py)
    model_inputs = list(getattr(flat, "inputs", ()))
    inputs = psyms + [d.symbol for d in delays] + [i.symbol for i in model_inputs]
    rel_list = list(modes.values())
    code = generate(rows, z_syms, inputs, len(modes),
                    crossings + [d.argument for d in discretes], assigned, outputs=syms,
                    discretes=dsyms,
                    scales=[event_form(sp.Abs(r.lhs) + sp.Abs(r.rhs)) for r in rel_list])
    init_code = generate(init_rows, z_syms, inputs, len(modes), None, assigned,
                         discretes=dsyms)
    delays_code = generate(delay_rows, z_syms, inputs, len(modes), None, assigned,
                           discretes=dsyms) if delays else None
    whens_code = generate(when_rows, z_syms, inputs, len(modes), None, assigned,
                         discretes=dsyms) if reduced.whens else None
    if programs_made is not None:
        programs_made(programs(code, init_code, whens_code, delays_code))
    names = [q.name for q in z_syms]
    relations = RelationInfo(
        ops=[type(r).__name__ for r in rel_list],
        texts=[_relation_text(r, k, origin, system, caus, assigned, init_text, reduced,
                              (len(init_rows), when_layout, helds))
               for k, r in enumerate(rel_list)],
        nominal=[_relation_nominal(system, g, assigned) for g in crossings],
        discrete_texts=[d.text for d in discretes],
        held_names=[h.name for h in helds], held_start=[h.start for h in helds],
        has_initial=uses_initial, held_types=_type_names(flat, helds),
        time_linear=_time_linear(crossings + [d.argument for d in discretes], assigned,
                                 set(psyms) | set(dsyms)))
    free = free_parameters(params, assigned, rows, init_rows)
    kept, redundant = choose_initial_rows(code, init_code, n_res, n_mandatory,
                                          reduction.n_states, len(z_syms), free)
    if free is not None:          # found by initialization: said in the report
        report.initial_parameters = dict(zip(free.names, free.start))
    initial = InitialCode(init_code, init_text, kept, redundant, n_mandatory, init_sizes)
    if redundant:
        report.notes.append(
            f"{len(redundant)} of {n_mandatory} initial conditions are redundant "
            "structurally (more conditions than states, or several fixing the same "
            "unknowns): checked at the initial point, dropped if consistent: "
            + "; ".join(init_text[k] for k in redundant))
    out = ModelCode(
        code, names, [p.name for p in params], [float(p.value) for p in params], n_res,
        state_z, pairs, dummies, [_nominal(system, v) for v in caus.z],
        [_start(system, v) for v in caus.z],
        _output_map(flat, aliases, {q: k for k, q in enumerate(syms)}, psyms),
        relations, initial, report=report,
        dynamic=_dynamic(reduction, caus) if reduction.dynamic else None,
        meta={"n_all": len(syms), "causal": caus.causal,
              "assigned_names": [a.name for a, _ in assigned],
              "equation_names": EquationNames(system, caus.residual_eqs),
              "structural_zeros": sorted(zeros),
              "self_scaled": _self_scaled(system, z_syms, {syms[v] for v in caus.kept_for_fill}),
              "parameter_bounds": {p.name: (p.min, p.max) for p in params
                                   if p.min is not None or p.max is not None},
              "derived_bounds": _derived_bounds(reduced.parameters, psyms),
              "derived_parameters": dict(flat.derived),
              "free_parameters": {} if free is None else {
                  "index": free.index, "names": free.names, "start": free.start},
              "found_followers": followers(reduced.parameters, free, psyms, zeros),
              "value_types": _value_types(flat),
              "parameter_types": {p.name: _TYPE_NAME[p.type] for p in params
                                  if getattr(p, "type", float) is not float}})
    # the outputs nothing checks while integrating, checked at every output point
    out.meta["output_checks"] = output_checks(
        code.program, out.meta["assigned_names"],
        lambda k: system.equations[caus.assignments[k][1]].name(system))
    # the declared unit and description of every name of a result
    out.meta["units"], out.meta["descriptions"] = output_tables(
        {**{v.name: v.attrs.unit for v in flat.variables},
         **{p.name: p.unit for p in flat.parameters}},
        {**{v.name: v.attrs.description for v in flat.variables},
         **{p.name: p.description for p in flat.parameters}},
        list(out.outputs) + list(out.param_names))
    if delays:
        out.delays = delay_code(
            delays, delay_rows, delays_code, reduced.parameters, psyms,
            set(z_syms) | {a for a, _ in assigned} | set(inputs) | set(dsyms) | set(modes),
            feeds_back(system, delays))
    if model_inputs:
        out.inputs = InputCode([i.name for i in model_inputs], [i.type for i in model_inputs],
                               [i.start for i in model_inputs])
    if reduced.whens:
        out.whens = WhenCode(whens_code, len(when_layout["cond_owners"]), texts=[
            (f"when {sp.sstr(w.condition)}" if w.equation is None else w.equation)
            + f" [{w.origin or '(model)'} ({w.origin_class})]"
            for w in reduced.whens], **when_layout)
    return out


def _frozen(reduced, dsyms, assigned):
    """The symbols whose values change only at events: parameters, frozen and held values,
    Boolean and Integer variables, and the assigned variables computed from them alone.
    A relation of these that reads a Boolean, an Integer, a held value or initial() is
    evaluated where it is read, not an event (it cannot cross between events); a relation
    of parameters alone stays an item of the discrete state, as it always was."""
    typed = {v.symbol for v in reduced.variables
             if getattr(v.attrs, "type", float) is not float}
    discrete = typed | set(dsyms)
    if not discrete:
        return None
    frozen = {p.symbol for p in reduced.parameters} | discrete
    for a, e in assigned:
        if symbols_of(e) <= frozen:
            frozen.add(a)
            discrete.add(a)
    return FrozenSymbols(frozen, discrete)


_TYPE_NAME = {float: "Real", bool: "Boolean", int: "Integer"}


def _value_types(flat) -> dict:
    """The Boolean and Integer variables of a result, by name (aliases included)."""
    return {v.name: TYPE_NAMES[v.attrs.type] for v in flat.variables
            if getattr(v.attrs, "type", float) is not float}


def _type_names(flat, helds) -> list:
    held = {h.name for h in helds}
    types = {v.name: getattr(v.attrs, "type", float) for v in flat.variables
             if v.name in held}
    return [TYPE_NAMES[types.get(h.name, float)] for h in helds]


def _check_live_self_reference(system, e, x, expr) -> None:
    """An assignment may read its own variable only in a frozen relation (its value the
    discrete state's); one inside ``no_event`` is evaluated live, so the equation is a
    loop of itself with a jump, not an assignment: refused, naming it (its value was
    read before it was computed, so the run depended on what ran before)."""
    if x not in symbols_of(expr):
        return
    if any(x in symbols_of(n) for n in expr.atoms(no_event)):
        raise InvalidEquation(
            f"{shortened(system.equations[e].name(system))}: solved for {x}, it reads "
            f"{x} in a relation inside no_event(), evaluated without events, so the "
            f"equation jumps on its own solution; write the relation without no_event "
            f"(frozen between events, switched at them)")


def _relation_text(rel, k, origin, system, caus, assigned, init_text, reduced,
                   clauses=None) -> str:
    """The relation as written, with the equation it is part of (``clauses``: the number
    of initial rows, the when-clauses' layout and the held values, which tell a
    when-clause's condition from a Boolean's or Integer's equation)."""
    i = origin[k]
    n_a, n_r = len(assigned), len(caus.residual_eqs)
    if i < n_a:
        where = system.equations[caus.assignments[i][1]].name(system)
    elif i < n_a + n_r:
        where = system.equations[caus.residual_eqs[i - n_a]].name(system)
    elif i - n_a - n_r - (len(caus.z[: caus.n_states]) if caus.causal else 0) < len(init_text):
        where = "initial conditions"
    else:
        where = "a when-clause"
        if clauses is not None:
            n_init, layout, helds = clauses
            j = i - n_a - n_r - (caus.n_states if caus.causal else 0) - n_init
            a = j - len(layout["cond_owners"]) - len(layout["targets"])
            if 0 <= a < len(layout["assign_slots"]) and \
                    layout["assign_owners"][a] in set(layout["always"]):
                where = f"the equation of {helds[layout['assign_slots'][a]].name}"
    return f"{sp.sstr(rel)}  in {where}"


def _relation_nominal(system, g, assigned) -> float:
    """The largest nominal value among the variables a relation reads (1 if none is set):
    the scale below which its value counts as zero."""
    expr_of = dict(assigned)
    seen, stack, noms = set(), list(g.free_symbols), [1.0]
    while stack:
        q = stack.pop()
        if q in seen:
            continue
        seen.add(q)
        info = system.var_info.get(q)
        if info is not None and info.attrs.nominal:
            noms.append(abs(float(info.attrs.nominal)))
        if q in expr_of:
            stack.extend(expr_of[q].free_symbols)
    return max(noms)


def _time_linear(items, assigned, frozen) -> list:
    """Indices of the items (relations' lhs - rhs, floor arguments) that are functions of
    time alone, linear in it, with coefficients of parameters and frozen values: their
    next zero is known before the integrator gets there (exact time events)."""
    explicit = {}
    known = set(frozen) | {time}              # grows with explicit: one set, not one a row
    for a, e in assigned:                     # assignments that depend on time alone
        if symbols_of(e) <= known:
            explicit[a] = e.xreplace(explicit)
            known.add(a)
    out = []
    for k, g in enumerate(items):
        if not symbols_of(g) <= known:
            continue
        g = g.xreplace(explicit)
        if not g.has(time) or g.has(sp.Piecewise):
            continue
        slope = sp.diff(g, time)
        if not slope.has(time) and slope != 0:
            out.append(k)
    return out


def _inline_after_index_reduction(system, reduction) -> None:
    """User-defined functions replaced by their bodies once index reduction has
    differentiated them (Modelica's InlineAfterIndexReduction): an equation's incidence
    then holds the inputs the body reads, so the BLT orders it after them."""
    s = reduction.structure
    for e, eq in enumerate(system.equations):
        if has_calls(eq.residual):
            eq.residual = inline_functions(eq.residual)
            s.graph[e], s.coeff[e] = system.incidence(eq.residual)


def _dynamic(reduction, caus) -> DynamicSets:
    """The level blocks of the run-time choice of states, over the rows of F and the
    solver vector z (the full form, without its assigned definitions)."""
    s = reduction.structure
    sel = reduction.selection
    zpos = {v: k for k, v in enumerate(caus.z)}
    row = {e: k for k, e in enumerate(caus.residual_eqs)}
    level_rows = {r for rows, _ in sel.levels for r in rows}
    # level 1's columns of lower kinematic order are no candidates (compiler/states.py)
    excluded = set(getattr(sel, "excluded", ()))
    row_vars = {row[r]: [zpos[v] for v in s.graph[r] if s.diff_to_var[v] is not UNASSIGNED
                         and v not in excluded]
                for r in level_rows}

    def mapped(d):
        return -1 if d is UNASSIGNED else zpos[d]

    z = caus.z
    return DynamicSets([[row[r] for r in rows] for rows, _ in sel.levels], row_vars,
                       [mapped(s.var_to_diff[v]) for v in z],
                       [mapped(s.diff_to_var[v]) for v in z],
                       [s.state_priority[v] for v in z], [s.order(v) for v in z],
                       [s.var_names[v] for v in z])


def _fixed_definitions(system, reduction) -> list:
    """The intermediate quantities of the outline pass that the choice of states
    cannot involve -- their equation never differentiated, no derivative of theirs, in
    no row of a level block -- as ``(variable, equation)`` in an order that computes
    each after the others it reads: with dynamic state selection they are assigned,
    not unknowns of the solver (compiler/outline.py makes hundreds for a long law)."""
    s = reduction.structure
    level_vars = {v for rows, _ in reduction.selection.levels for r in rows
                  for v in s.graph[r]}
    found = {}
    for e, eq in enumerate(system.equations):
        sym = definition_of(eq)
        v = system.index.get(sym) if sym is not None else None
        if (v is not None and s.eq_to_diff[e] is UNASSIGNED
                and s.var_to_diff[v] is UNASSIGNED and v not in level_vars
                and s.coeff[e].get(v) == LINEAR_CONST):
            found[v] = e
    order, done = [], set()
    for v in sorted(found):               # depth first over what each reads, no recursion
        stack = [(v, False)]
        while stack:
            u, ready = stack.pop()
            if u in done:
                continue
            if ready:
                done.add(u)
                order.append((u, found[u]))
                continue
            stack.append((u, True))
            stack.extend((w, False) for w in s.graph[found[u]]
                         if w in found and w != u and w not in done)
    return order


def _nominal(system, k) -> float:
    if system.symbols[k] in system.var_info:
        nom = system.var_info[system.symbols[k]].attrs.nominal
        return float(nom) if nom else 1.0
    return 1.0


def _self_scaled(system, z_syms, kept) -> list:
    """Which solver unknowns the integrator judges through the others (solvers/base.py,
    item 6): derivatives without a declared nominal, and the variables kept for fill."""
    ders = set(system.derivatives.values())
    return [q in kept or q in ders and not (q in system.var_info and system.var_info[q]
                                            .attrs.nominal) for q in z_syms]


def _default_start(attrs) -> float:
    """A Real's start value where none is given (Modelica 3.6, sec. 4.8.7): 0, or the
    bound of [min, max] nearest to it."""
    lo, hi = getattr(attrs, "min", None), getattr(attrs, "max", None)
    x = 0.0
    if lo is not None and x < float(lo):
        x = float(lo)
    if hi is not None and x > float(hi):
        x = float(hi)
    return x


def _start(system, k) -> float:
    s = system.symbols[k]
    if s in system.var_info and system.var_info[s].attrs.start is not None:
        return float(system.var_info[s].attrs.start)
    return 0.0


def _output_map(flat, aliases, index, psyms) -> dict:
    """Every flat variable's name -> (sign, y index), or (None, f) with f(p) its constant
    value (a variable fixed to an expression of parameters)."""
    by_name = {s.name: k for s, k in index.items()}
    out, constant = {}, {}
    for v in flat.variables:
        if v.name in aliases.constants:
            value = sp.sympify(aliases.constants[v.name])
            if value.free_symbols:
                constant[v.name] = value
            else:
                out[v.name] = (None, float(value))
            continue
        sign, root = aliases.resolve(v.name)
        out[v.name] = (float(int(sign)), by_name[root])   # +-1 (sympy's float() is slow)
    if constant:
        out.update({name: (None, f) for name, f in parameter_functions(constant, psyms)})
    for s, k in index.items():
        out.setdefault(s.name, (1.0, k))
    return out


def _derived_bounds(parameters, psyms) -> list:
    """(name, min, max, f(p)) of every bounded parameter whose value is an expression of
    tunable ones (``Resistor(R=ac.ref("R"))``): tuning those must respect its bounds, as
    compiling with the same values does."""
    tunable = set(psyms)
    by_symbol = {q.symbol: q for q in parameters}
    derived = {}
    for q in parameters:
        if (q.min is None and q.max is None) or is_number(q.value):
            continue
        value = sp.sympify(q.value)
        if value in tunable and _within(by_symbol.get(value), q):
            continue          # a copy of a parameter whose own range is checked: implied
        if value.free_symbols and value.free_symbols <= tunable:
            derived[q.name] = (q, value)
    funcs = dict(parameter_functions({n: v for n, (_, v) in derived.items()}, psyms))
    return [(n, q.min, q.max, funcs[n]) for n, (q, _) in derived.items()]


def _within(p, q) -> bool:
    """Whether parameter ``p``'s range lies within ``q``'s (a value ``p`` may take, ``q``
    may take: ``T = T_ref``, both at least 0)."""
    return p is not None and (
        (q.min is None or (p.min is not None and p.min >= q.min))
        and (q.max is None or (p.max is not None and p.max <= q.max)))


def _initial_rows(system, reduced, reduction, caus):
    """Initial equations and fixed starts (mandatory), then a start-value row for every
    other state (optional: :func:`choose_initial_rows` keeps those that
    make the initial system structurally nonsingular)."""
    rows = [e.residual for e in reduced.initial_equations]
    text = [f"initial equation {e.text} [{e.where}]" for e in reduced.initial_equations]
    # the size of each of the user's conditions where it is known (|start| + nominal of
    # a fixed start value): the scale a redundant one is checked on (runtime/redundant.py)
    sizes = [0.0] * len(rows)
    fixed = set()
    for k, sym in enumerate(system.symbols):
        info = system.var_info.get(sym)
        if info is not None and info.attrs.fixed:
            # no start given: Modelica's default, 0 (or the bound nearest to it)
            start = info.attrs.start if info.attrs.start is not None else \
                _default_start(info.attrs)
            rows.append(sym - start)
            text.append(f"{sym.name} = {start} (fixed start value"
                        + ("" if info.attrs.start is not None else ", the default")
                        + f") [{info.where}]")
            sizes.append(abs(float(start)) + _nominal(system, k))
            fixed.add(k)
    n_mandatory = len(rows)
    for v in reduction.states:
        if v not in fixed:
            start = _start(system, v)
            # x - 0 is x (what sympy's subtraction returns, at a fraction of its cost)
            rows.append(system.symbols[v] if start == 0.0 else system.symbols[v] - start)
            text.append(f"{system.symbols[v].name} = {start} (start value of a state)")
    return rows, text, n_mandatory, sizes


# -- delays (compiler/frontend/delays.py made them inputs) ------------------------------
def feeds_back(system, delays) -> bool:
    """Whether a delayed value can reach a delayed expression (a loop through a delay),
    judged on the connectivity of the equations: symbols of one equation, and x with
    der(x), are connected.  Connectivity over-approximates dependence, so the answer
    errs towards True.  Without such a loop a discontinuity comes back through a delay
    once and stops (the runtime then follows one generation instead of six)."""
    parent = {}

    def find(q):
        parent.setdefault(q, q)
        while parent[q] is not q:
            parent[q] = parent[parent[q]]
            q = parent[q]
        return q

    def union(a, b):
        ra, rb = find(a), find(b)
        if ra is not rb:
            parent[ra] = rb

    for eq in system.equations:
        syms = list(eq.residual.free_symbols)
        for q in syms[1:]:
            union(syms[0], q)
    for x, dx in system.derivatives.items():
        union(x, dx)
    roots = {find(d.symbol) for d in delays}
    return any(find(q) in roots for d in delays for q in d.argument.free_symbols
               if q in parent)


def delay_code(delays, rows, code, parameters, psyms, known, feedback=True):
    """The :class:`~acausal.compiler.modelcode.DelayCode` of the model: ``code`` computes
    the delayed expressions (``rows``) from the unknowns; each delay time becomes a
    float or a function of the tunable parameters ``psyms``."""
    for d, row in zip(delays, rows):
        unknown = sorted(q.name for q in row.free_symbols if q not in known and q != time)
        if unknown:
            raise ModelError(f"{d.text} in {d.where}: the delayed expression reads "
                             f"{', '.join(unknown)}, which the compiled model does not "
                             "compute")
    values = {p.symbol: p for p in parameters}
    tunable = set(psyms)
    times, exprs = [], {}
    for d in delays:
        T = d.T
        for _ in range(100):                 # parameters bound to others, down to tunables
            bound = {q: sp.sympify(values[q].value) for q in T.free_symbols
                     if q in values and q not in tunable}
            if not bound:
                break
            T = T.xreplace(bound)
        if T.free_symbols:
            exprs[d.text] = T
            times.append(None)
        else:
            times.append(float(T))
    funcs = dict(parameter_functions(exprs, psyms)) if exprs else {}
    times = [funcs[d.text] if t is None else t for d, t in zip(delays, times)]
    return DelayCode(code, [d.text for d in delays], times, [d.where for d in delays],
                     feedback)
