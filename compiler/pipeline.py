"""The compiler pipeline: the passes by name, in order (as OpenModelica lists its modules).

    flatten -> units (dimensions checked) -> discrete (floor/mod frozen) -> sampled
            (discrete variables held, when-assignments checked) -> delays (delay() read
            from a history) -> alias -> balance -> conversion (Pryce's success test,
            exact; LC conversion of singular constant blocks) ->
            index_reduction (Pantelides) -> state_selection (dummy derivatives, exact
            rank on constant blocks) -> assemble (BLT, tearing checked numerically)
            -> codegen

Each pass is a function from one plain data structure to the next; the timings and
counts of every pass go into the index report.  The result is a
:class:`~acausal.compiler.modelcode.ModelCode`: generated code and name maps, run by
:class:`acausal.runtime.CompiledModel`.
"""
from __future__ import annotations

import gc as _gc
import sys as _sys
import time as _time
from dataclasses import replace

import numpy as np

from ..components.component import Component
from .gcpause import collect_after_pause
from .graph import UNASSIGNED
from .modelcode import DelayCode, DynamicSets, InitialCode, ModelCode, RelationInfo, WhenCode
from .report import EquationNames, IndexReport, mode_structures

# The passes and sympy are imported where they run: a model found in the compile cache
# is returned without importing either.

__all__ = ["PASSES", "compile_model"]

PASSES = ("flatten", "units", "discrete", "sampled", "delays", "alias", "balance",
          "conversion", "index_reduction", "state_selection", "assemble", "codegen")


def compile_model(model: Component, backend: str = "auto", cache=False,
                  check_units: str = "warn") -> ModelCode:
    """Compile a model instance to generated code and name maps (see the module docstring);
    :class:`acausal.runtime.CompiledModel` runs it.  ``backend``: ``"c"``, ``"numpy"`` or
    ``"auto"`` (:func:`acausal.compiler.cbackend.bind`).

    ``cache`` (:mod:`acausal.compiler.cache`): ``True`` loads an unchanged model from the
    compile cache by the key of its flat model -- exact: the flattened equations,
    variables and parameter values are what the passes read -- and stores a new one;
    ``"tree"`` first tries the key of the instance tree, which needs neither sympy nor
    flattening but cannot see what an ``equations()`` reads from outside the model's
    classes and modules at call time (a file, the environment, a mutable object), so it
    is only taken when asked for; ``False`` compiles afresh.  The report of a loaded
    model says so in a note, and its timings are those of the original compile plus
    ``cache_lookup``.

    ``check_units`` (:mod:`acausal.compiler.unitcheck`): ``"error"`` raises UnitError
    at a dimensionally inconsistent equation, ``"warn"`` warns, ``"off"`` skips the
    check; it runs on the flat model, so a model found by its instance tree
    (``cache="tree"``) is not checked again."""
    # Why the collector is paused: the passes allocate millions of sympy nodes that
    # live until the compile ends and form no garbage cycles worth finding; the
    # collector's full passes over that growing heap cost a quarter of a large build
    # (it is switched back on, as it was, however the compile ends).
    collecting = _gc.isenabled()
    _gc.disable()
    try:
        return _compile(model, backend, cache, check_units)
    finally:
        symbolic = _sys.modules.get(__package__ + ".symbolic")
        if symbolic is not None:     # what it keeps of this model's expressions
            symbolic.forget_expressions()
        if collecting:
            collect_after_pause()
            _gc.enable()


def _compile(model, backend, cache, check_units) -> ModelCode:
    if cache not in (True, False, "tree"):
        raise ValueError(f"cache must be True, False or 'tree', got {cache!r}")
    from ..components.units import MODES
    if check_units not in MODES:
        raise ValueError(f"check_units must be one of {MODES}, got {check_units!r}")
    from . import cache as store
    use_cache = bool(cache) and store.enabled()
    t0 = _time.perf_counter()
    tree = store.tree_key(model, backend) if use_cache and cache == "tree" else None
    if tree is not None:
        found = store.lookup(tree=tree)
        if found is not None:
            model._bind("")     # the instance named as a compile leaves it (no sympy)
            return _from_cache(found, _time.perf_counter() - t0, "its instance tree")
    t_tree = _time.perf_counter() - t0
    from .alias import eliminate_aliases
    from .balance import check_balance
    from .conversion import convert_model
    from .delays import extract_delays
    from .discrete import freeze_integer_functions
    from .sampled import declare_discrete_variables, explain_overdetermined, pre_after_aliases
    from .flatten import flatten
    from .reduction import as_written, reduce_index
    report = IndexReport(model_name=type(model).__name__)
    clock = _Clock(report)
    flat = clock("flatten", flatten, model)
    report.modes = mode_structures(model)
    from .unitcheck import check_units as unit_check
    report.derived_parameters = dict(flat.derived)
    key = None
    if use_cache:
        t1 = _time.perf_counter()
        key = store.flat_key(flat, backend)
        found = store.lookup(key) if key is not None else None
        if found is not None:
            if tree is not None:
                store.store_index(tree, key)
            found[0].report.units = unit_check(flat, check_units, found[0].report.units)
            lookup = _time.perf_counter() - t1 + report.timings["flatten"] + t_tree
            return _from_cache(found, lookup, "its flat model")
        report.timings["cache_key"] = _time.perf_counter() - t1 + t_tree
    report.units = clock("units", unit_check, flat, check_units)
    discretes = clock("discrete", freeze_integer_functions, flat)
    helds = clock("sampled", declare_discrete_variables, flat)
    delays = clock("delays", extract_delays, flat)
    if delays:
        report.notes.append(
            f"{len(delays)} delay(s), read from a history of their expressions; the "
            "integrator's step is limited to the shortest delay time: "
            + "; ".join(f"{d.text} in {d.where}" for d in delays[:10])
            + (" ..." if len(delays) > 10 else ""))
    _reinit_targets_are_states(flat)
    report.count("flatten", equations=len(flat.equations), variables=len(flat.variables))
    if helds:
        report.notes.append("discrete variables, held between events and assigned in "
                            "when-clauses: " + ", ".join(h.name for h in helds[:20])
                            + (" ..." if len(helds) > 20 else ""))
    if flat.structural_zeros:
        report.notes.append("parameters equal to 0 were evaluated as structural zeros (set a "
                            "non-zero value to keep them tunable): "
                            + ", ".join(flat.structural_zeros[:20])
                            + (" ..." if len(flat.structural_zeros) > 20 else ""))
    reduced, aliases = clock("alias", eliminate_aliases, flat)
    _resolve_aliases_in(list(discretes) + list(delays), flat, aliases)
    pre_after_aliases(reduced, aliases, helds)
    report.aliases = aliases
    report.count("alias", equations=len(reduced.equations), variables=len(reduced.variables))
    system, structure = clock("structure", _symbolic_system, reduced, discretes, helds,
                              delays)
    try:
        clock("balance", check_balance, system, structure, reduced, aliases,
              (len(flat.equations), len(flat.variables)))
    except Exception as err:
        explain_overdetermined(err, helds)
        raise
    report.sigma = clock("index_as_written", as_written, flat)
    report.conversion = clock("conversion", convert_model, system, structure, reduced)
    reduction = clock("index_reduction", reduce_index, system, report.conversion.structure,
                      report.conversion.coefficient)
    report.reduction = reduction
    report.count("index_reduction", equations=len(system.equations),
                 variables=len(system.symbols))
    out = clock("codegen", _assemble, system, reduction, reduced, flat, aliases, report,
                discretes, helds, delays)
    clock("report", report.fill, system, reduction, out)
    from .cbackend import bind
    clock("c_backend", bind, out, backend, report)
    if key is not None:
        t2 = _time.perf_counter()
        store.store(key, out, tree)
        report.timings["cache_store"] = _time.perf_counter() - t2    # not in the entry
    return out


def _from_cache(found, seconds, how) -> ModelCode:
    from .cache import load_notes
    mc, _ = found
    report = mc.report
    report.timings["cache_lookup"] = seconds
    report.notes += load_notes(mc)
    report.notes.append(f"came from the compile cache (found by {how}, loaded in "
                        f"{seconds * 1e3:.1f} ms); the other timings are those of the "
                        "original compile")
    return mc


def _resolve_aliases_in(discretes, flat, aliases) -> None:
    """The frozen floor values and the delays were found before alias elimination: their
    arguments get the same substitution as the equations (``mod(u, 1)`` of a ``u`` that
    is an alias of the state ``x`` reads ``x``)."""
    if not discretes:
        return
    import sympy as sp
    by_name = {v.name: v.symbol for v in flat.variables}
    subs = {}
    for v in flat.variables:
        if v.name in aliases.constants:
            subs[v.symbol] = sp.sympify(aliases.constants[v.name])
            continue
        sign, root = aliases.resolve(v.name)
        if root != v.name and root in by_name:
            subs[v.symbol] = sign * by_name[root]
    for d in discretes:
        if d.argument.free_symbols & subs.keys():
            d.argument = d.argument.xreplace(subs)


def _symbolic_system(reduced, discretes, helds=(), delays=()):
    from .symbolic import SymbolicSystem
    system = SymbolicSystem.from_flat(reduced)
    system.parameters |= {d.symbol for d in discretes}   # constant between events
    system.parameters |= {s for h in helds for s in (h.symbol, h.pre)}
    system.delays = {d.symbol: d for d in delays}        # inputs that vary: never constant
    return system, system.structure()


class _Clock:
    def __init__(self, report):
        self.report = report

    def __call__(self, name, fn, *args):
        t0 = _time.perf_counter()
        out = fn(*args)
        self.report.timings[name] = _time.perf_counter() - t0
        return out


def _reinit_targets_are_states(flat) -> None:
    """A variable that a when-clause re-initializes must be a state (Modelica 3.6, sec.
    8.3.6: tools treat it as stateSelect = always), so state selection keeps it one,
    wherever index reduction could otherwise put the states (the motor side of a gear)."""
    from ..components.component import ModelError
    from ..components.symbols import Reinit
    targets = {act.variable for w in flat.whens for act in w.actions
               if isinstance(act, Reinit)}
    for k, v in enumerate(flat.variables):
        if v.symbol in targets:
            if v.attrs.state_select == "never":
                raise ModelError(f"reinit({v.name}) in {v.where}: the variable has "
                                 "state_select='never', but only a state can be re-initialized")
            flat.variables[k] = replace(v, attrs=replace(v.attrs, state_select="always"))


def _assemble(system, reduction, reduced, flat, aliases, report, discretes,
              helds=(), delays=()) -> ModelCode:
    import sympy as sp
    from types import SimpleNamespace
    from .causalize import causalize, full_form
    from .codegen import extract_relations, generate
    from .numeric import CoefficientValues
    from .sampled import when_rows as clause_rows
    syms = system.symbols
    if reduction.dynamic:
        caus = full_form(reduction, len(syms), len(system.equations))
    else:
        held_items = [SimpleNamespace(symbol=s) for h in helds for s in (h.symbol, h.pre)]
        values = CoefficientValues(system, reduced.parameters, list(discretes) + held_items)
        caus = causalize(reduction, values)
        untorn = [b for b in caus.blocks if b.get("not_torn")]
        for b in untorn[:5]:
            report.notes.append(f"algebraic block of {b['size']} equations not torn "
                                f"({b['not_torn']}), e.g. {syms[b['variables'][0]].name}")
    report.blocks = caus.blocks
    report.kept_for_fill = [syms[v].name for v in caus.kept_for_fill]
    z_syms = [syms[v] for v in caus.z]
    assigned = [(syms[v], solve_linear(system.equations[e].residual, syms[v]))
                for v, e in caus.assignments]
    rows = [system.equations[e].residual for e in caus.residual_eqs]
    n_res = len(rows)
    s = reduction.structure
    if caus.causal:   # der(s) of every state, computed by the assignments
        rows += [syms[s.var_to_diff[v]] for v in caus.z[: caus.n_states]]
        state_z, pairs, dummies = list(range(caus.n_states)), [], []
    else:
        state_z, pairs, dummies = [], reduction.pairs, reduction.dummies
    init_rows, init_text, n_mandatory = _initial_rows(system, reduced, reduction, caus)
    when_rows, when_layout = clause_rows(reduced.whens, z_syms, caus, pairs, helds, assigned)
    delay_rows = [d.argument for d in delays]
    sizes = [len(assigned), len(rows), len(init_rows), len(when_rows), len(delay_rows)]
    exprs, crossings, modes, origin = extract_relations(
        [e for _, e in assigned] + rows + init_rows + when_rows + delay_rows)
    parts = np.split(np.array(exprs, dtype=object), np.cumsum(sizes)[:-1])
    assigned = [(a, e) for (a, _), e in zip(assigned, parts[0])]
    rows, init_rows, when_rows = list(parts[1]), list(parts[2]), list(parts[3])
    delay_rows = list(parts[4])
    zeros = set(reduced.structural_zeros)
    params = [p for p in reduced.parameters if _is_number(p.value) and p.name not in zeros]
    psyms = [p.symbol for p in params]
    # m: relation values, floor values, then held(y) and pre(y) of the discrete variables
    dsyms = [d.symbol for d in discretes] + [h.symbol for h in helds] + [h.pre for h in helds]
    # the delayed values are read from p after the tunable parameters (runtime/delays.py)
    inputs = psyms + [d.symbol for d in delays]
    rel_list = list(modes.values())
    code = generate(rows, z_syms, inputs, len(modes),
                    crossings + [d.argument for d in discretes], assigned, outputs=syms,
                    discretes=dsyms, scales=[sp.Abs(r.lhs) + sp.Abs(r.rhs) for r in rel_list])
    init_code = generate(init_rows, z_syms, inputs, len(modes), None, assigned,
                         discretes=dsyms)
    names = [q.name for q in z_syms]
    relations = RelationInfo(
        ops=[type(r).__name__ for r in rel_list],
        texts=[_relation_text(r, k, origin, system, caus, assigned, init_text, reduced)
               for k, r in enumerate(rel_list)],
        nominal=[_relation_nominal(system, g, assigned) for g in crossings],
        discrete_texts=[d.text for d in discretes],
        held_names=[h.name for h in helds], held_start=[h.start for h in helds],
        time_linear=_time_linear(crossings + [d.argument for d in discretes], assigned,
                                 set(psyms) | set(dsyms)))
    initial = InitialCode(init_code, init_text, choose_initial_rows(
        code, init_code, n_res, n_mandatory, reduction.n_states, len(z_syms), init_text))
    out = ModelCode(
        code, names, [p.name for p in params], [float(p.value) for p in params], n_res,
        state_z, pairs, dummies, [_nominal(system, v) for v in caus.z],
        [_start(system, v) for v in caus.z],
        _output_map(flat, aliases, {q: k for k, q in enumerate(syms)}, psyms),
        relations, initial, report=report,
        dynamic=_dynamic(reduction) if reduction.dynamic else None,
        meta={"n_all": len(syms), "causal": caus.causal,
              "assigned_names": [a.name for a, _ in assigned],
              "equation_names": EquationNames(system, caus.residual_eqs),
              "structural_zeros": sorted(zeros),
              "self_scaled": _self_scaled(system, z_syms, {syms[v] for v in caus.kept_for_fill}),
              "parameter_bounds": {p.name: (p.min, p.max) for p in params
                                   if p.min is not None or p.max is not None},
              "derived_bounds": _derived_bounds(reduced.parameters, psyms),
              "derived_parameters": dict(flat.derived)})
    if delays:
        from .delays import delay_code, feeds_back
        out.delays = delay_code(delays, delay_rows, generate(
            delay_rows, z_syms, inputs, len(modes), None, assigned, discretes=dsyms),
            reduced.parameters, psyms, set(z_syms) | {a for a, _ in assigned} | set(inputs)
            | set(dsyms) | set(modes), feeds_back(system, delays))
    if reduced.whens:
        out.whens = WhenCode(generate(when_rows, z_syms, inputs, len(modes), None, assigned,
                                      discretes=dsyms),
                             len(reduced.whens), texts=[
                                 f"when {sp.sstr(w.condition)} [{w.origin or '(model)'} "
                                 f"({w.origin_class})]" for w in reduced.whens],
                             **when_layout)
    return out


def _relation_text(rel, k, origin, system, caus, assigned, init_text, reduced) -> str:
    """The relation as written, with the equation it is part of."""
    import sympy as sp
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
    import sympy as sp
    from ..components.symbols import time
    from .symbolic import symbols_of
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


def choose_initial_rows(model_code, init_code, n_res, n_mandatory, n_states, n_z,
                        descriptions) -> np.ndarray:
    """The mandatory initial rows, then those optional start-value rows (in state order)
    that complete a perfect matching of [G; initial rows] onto z (Modelica's rule: start
    values fix the states that nothing else determines)."""
    from ..errors import InitializationFailed
    from .structure import _match
    keep = model_code.jac_rows < n_res
    adj = _adjacency(model_code.jac_rows[keep], model_code.jac_cols[keep], n_res)
    i_adj = _adjacency(init_code.jac_rows, init_code.jac_cols, init_code.n_rows)
    adj += i_adj[:n_mandatory]
    l2r, r2l = _match(adj, n_z)
    if min(l2r, default=0) < 0:
        bad = [descriptions[k - n_res] for k, v in enumerate(l2r) if v < 0 and k >= n_res]
        raise InitializationFailed(
            "the initial conditions contradict the model equations structurally "
            "(they determine the same variables twice): " + "; ".join(bad or ["(model)"]))
    chosen = list(range(n_mandatory))
    for k in range(n_mandatory, init_code.n_rows):
        if len(chosen) == n_states:
            break
        adj.append(i_adj[k])
        l2r.append(-1)
        if _augment(len(adj) - 1, adj, l2r, r2l):
            chosen.append(k)
        else:
            adj.pop()
            l2r.pop()
    return np.array(chosen, dtype=np.int64)


def _augment(root, adj, l2r, r2l) -> bool:
    """One augmenting path from row ``root`` (iterative Kuhn search); flips it if found."""
    seen, stack, parent = {root}, [(root, iter(adj[root]))], {}
    while stack:
        u, it = stack[-1]
        v = next(it, None)
        if v is None:
            stack.pop()
            continue
        w = r2l[v]
        if w < 0:
            while True:             # flip the path back to the root
                prev = l2r[u]
                l2r[u], r2l[v] = v, u
                if u == root:
                    return True
                u, v = parent[u], prev
        if w not in seen:
            seen.add(w)
            parent[w] = u
            stack.append((w, iter(adj[w])))
    return False


def _adjacency(rows, cols, n_rows) -> list:
    adj = [[] for _ in range(n_rows)]
    for r, c in zip(rows.tolist(), cols.tolist()):
        adj[r].append(c)
    return [sorted(set(a)) for a in adj]


def solve_linear(residual, x):
    """x from residual(x) = 0 when x enters linearly (:func:`acausal.compiler.derivative.solve_linear`)."""
    from .derivative import solve_linear as solve
    return solve(residual, x)


def _dynamic(reduction) -> DynamicSets:
    s = reduction.structure
    sel = reduction.selection
    level_rows = {r for rows, _ in sel.levels for r in rows}
    row_vars = {r: [v for v in s.graph[r] if s.diff_to_var[v] is not UNASSIGNED]
                for r in level_rows}
    priority = list(s.state_priority)
    return DynamicSets([list(rows) for rows, _ in sel.levels], row_vars,
                       [(-1 if d is UNASSIGNED else d) for d in s.var_to_diff],
                       [(-1 if d is UNASSIGNED else d) for d in s.diff_to_var],
                       priority, [s.order(v) for v in range(s.n_vars)], s.var_names)


def _is_number(value) -> bool:
    try:
        float(value)
        return True
    except (TypeError, ValueError):
        return False


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


def _start(system, k) -> float:
    s = system.symbols[k]
    if s in system.var_info and system.var_info[s].attrs.start is not None:
        return float(system.var_info[s].attrs.start)
    return 0.0


def _output_map(flat, aliases, index, psyms) -> dict:
    """Every flat variable's name -> (sign, y index), or (None, f) with f(p) its constant
    value (a variable fixed to an expression of parameters)."""
    import sympy as sp
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
        out[v.name] = (float(sign), by_name[root])
    if constant:
        out.update({name: (None, f) for name, f in _parameter_functions(constant, psyms)})
    for s, k in index.items():
        out.setdefault(s.name, (1.0, k))
    return out


def _derived_bounds(parameters, psyms) -> list:
    """(name, min, max, f(p)) of every bounded parameter whose value is an expression of
    tunable ones (``Resistor(R=ac.ref("R"))``): tuning those must respect its bounds, as
    compiling with the same values does."""
    import sympy as sp
    tunable = set(psyms)
    derived = {}
    for q in parameters:
        if (q.min is None and q.max is None) or _is_number(q.value):
            continue
        value = sp.sympify(q.value)
        if value.free_symbols and value.free_symbols <= tunable:
            derived[q.name] = (q, value)
    funcs = dict(_parameter_functions({n: v for n, (_, v) in derived.items()}, psyms))
    return [(n, q.min, q.max, funcs[n]) for n, (q, _) in derived.items()]


def _parameter_functions(exprs: dict, psyms):
    """f(p) for each expression of parameters, each from its own generated source (a
    :class:`~acausal.compiler.cache.ParameterFunction`: picklable)."""
    from .cache import ParameterFunction
    from .emit import Emitter
    pos = {q: k for k, q in enumerate(psyms)}
    em = Emitter("py", lambda q: f"p[{pos[q]}]")
    out = []
    for name, e in exprs.items():
        lines = ["def f(p):"] + ["    " + ln for ln in em.assign("_v", e)] + ["    return _v"]
        out.append((name, ParameterFunction("\n".join(lines) + "\n", "f")))
    return out


def _initial_rows(system, reduced, reduction, caus):
    """Initial equations and fixed starts (mandatory), then a start-value row for every
    other state (optional: :func:`choose_initial_rows` keeps those that
    make the initial system structurally nonsingular)."""
    rows = [e.residual for e in reduced.initial_equations]
    text = [f"initial equation {e.text} [{e.where}]" for e in reduced.initial_equations]
    needed = reduction.n_states
    fixed = set()
    for k, sym in enumerate(system.symbols):
        info = system.var_info.get(sym)
        if info is not None and info.attrs.fixed and info.attrs.start is not None:
            rows.append(sym - info.attrs.start)
            text.append(f"{sym.name} = {info.attrs.start} (fixed start value) [{info.where}]")
            fixed.add(k)
    if len(rows) > needed:
        from ..errors import InitializationFailed
        raise InitializationFailed(
            f"the initial problem is over-specified: {len(rows)} initial conditions for "
            f"{needed} states ({', '.join(system.symbols[v].name for v in reduction.states)}); "
            "conditions: " + "; ".join(text))
    n_mandatory = len(rows)
    for v in reduction.states:
        if v not in fixed:
            start = _start(system, v)
            rows.append(system.symbols[v] - start)
            text.append(f"{system.symbols[v].name} = {start} (start value of a state)")
    return rows, text, n_mandatory
