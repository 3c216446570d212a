"""The compiler pipeline: the passes by name, in order (as OpenModelica lists its modules).

    flatten -> alias -> balance -> index_reduction (Pantelides) -> state_selection
            (dummy derivatives) -> assemble (+ BLT report) -> codegen

Each pass is a function from one plain data structure to the next; the timings and
counts of every pass go into the index report.
"""
from __future__ import annotations

import time as _time

import numpy as np
import sympy as sp

from ..components.component import Component
from .alias import eliminate_aliases
from .balance import check_balance
from .codegen import extract_relations, generate
from .derivative import partial
from .graph import UNASSIGNED
from .flatten import flatten
from .initial import InitialConditions
from .causalize import causalize, full_form
from .model import CompiledModel, DynamicStateSelection
from .reduction import as_written, reduce_index
from .report import IndexReport
from .symbolic import SymbolicSystem

__all__ = ["PASSES", "compile_model"]

PASSES = ("flatten", "alias", "balance", "index_reduction", "state_selection",
          "assemble", "codegen")


def compile_model(model: Component) -> CompiledModel:
    """Compile a model instance to a CompiledModel (see the module docstring)."""
    report = IndexReport(model_name=type(model).__name__)
    clock = _Clock(report)
    flat = clock("flatten", flatten, model)
    report.count("flatten", equations=len(flat.equations), variables=len(flat.variables))
    if flat.structural_zeros:
        report.notes.append("parameters equal to 0 were evaluated as structural zeros (set a "
                            "non-zero value to keep them tunable): "
                            + ", ".join(flat.structural_zeros[:20])
                            + (" ..." if len(flat.structural_zeros) > 20 else ""))
    reduced, aliases = clock("alias", eliminate_aliases, flat)
    report.aliases = aliases
    report.count("alias", equations=len(reduced.equations), variables=len(reduced.variables))
    system = SymbolicSystem.from_flat(reduced)
    structure = system.structure()
    clock("balance", check_balance, system, structure, reduced, aliases,
          (len(flat.equations), len(flat.variables)))
    report.sigma = clock("index_as_written", as_written, flat)
    reduction = clock("index_reduction", reduce_index, system, structure)
    report.reduction = reduction
    report.count("index_reduction", equations=len(system.equations),
                 variables=len(system.symbols))
    compiled = clock("codegen", _assemble, system, reduction, reduced, flat, aliases, report)
    report.fill(system, reduction, compiled)
    return compiled


class _Clock:
    def __init__(self, report):
        self.report = report

    def __call__(self, name, fn, *args):
        t0 = _time.perf_counter()
        out = fn(*args)
        self.report.timings[name] = _time.perf_counter() - t0
        return out


def _assemble(system, reduction, reduced, flat, aliases, report) -> CompiledModel:
    syms = system.symbols
    caus = full_form(reduction, len(syms), len(system.equations)) if reduction.dynamic \
        else causalize(reduction)
    report.blocks = caus.blocks
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
    when_rows, targets, owners = _when_rows(reduced.whens, z_syms, caus, pairs)
    sizes = [len(assigned), len(rows), len(init_rows), len(when_rows)]
    exprs, crossings, modes = extract_relations([e for _, e in assigned] + rows + init_rows
                                                + when_rows)
    parts = np.split(np.array(exprs, dtype=object), np.cumsum(sizes)[:-1])
    assigned = [(a, e) for (a, _), e in zip(assigned, parts[0])]
    rows, init_rows, when_rows = list(parts[1]), list(parts[2]), list(parts[3])
    relation_ops = [type(r).__name__ for r in modes.values()]
    zeros = set(reduced.structural_zeros)
    params = [p for p in reduced.parameters if _is_number(p.value) and p.name not in zeros]
    psyms = [p.symbol for p in params]
    code = generate(rows, z_syms, psyms, len(modes), crossings, assigned, outputs=syms)
    init_code = generate(init_rows, z_syms, psyms, len(modes), None, assigned)
    nominal = [_nominal(system, v) for v in caus.z]
    cm = CompiledModel(code, [q.name for q in z_syms], [p.name for p in params],
                       [float(p.value) for p in params], n_res, state_z, pairs, dummies,
                       _dynamic(reduction) if reduction.dynamic else None, nominal,
                       report=report,
                       meta={"relations": relation_ops, "n_all": len(syms),
                             "equation_names": [system.equations[e].name(system)
                                                for e in caus.residual_eqs],
                             "modes": modes, "causal": caus.causal,
                             "structural_zeros": sorted(zeros)})
    cm.outputs = _output_map(flat, aliases, {q: k for k, q in enumerate(syms)}, psyms)
    cm.start = np.array([_start(system, v) for v in caus.z])
    cm.initial_conditions = InitialConditions(init_code, init_text)
    cm.initial_conditions.choose_rows(code, n_res, n_mandatory, reduction.n_states, cm.n)
    cm.set_time_relations(*_time_relations(crossings, psyms))
    if reduced.whens:
        cm.set_whens(generate(when_rows, z_syms, psyms, len(modes), None, assigned),
                     len(reduced.whens), targets, owners)
    return cm


def _time_relations(crossings, psyms):
    """Zero-crossing functions of time and parameters only (steps, ramps, pulses), as one
    vectorized numpy function f(t_array, p) -> rows: their events are known in advance."""
    from ..components.symbols import time
    allowed = set(psyms) | {time}
    idx = [k for k, g in enumerate(crossings) if g.free_symbols <= allowed and g.has(time)]
    if not idx:
        return [], None
    f = sp.lambdify([time, psyms], [crossings[k] + 0 * time for k in idx], modules="numpy")
    return idx, f


def _when_rows(whens, z_syms, caus, pairs):
    """Rows: each when-condition as 1/0, then each reinit value (pre(x) is x here)."""
    from ..components.component import ModelError
    from ..components.symbols import pre
    z_index = {s: k for k, s in enumerate(z_syms)}
    states = set(range(caus.n_states)) if caus.causal else {a for a, _ in pairs}
    conds, values, targets, owners = [], [], [], []
    for w_i, w in enumerate(whens):
        conds.append(sp.Piecewise((1, w.condition), (0, True)))
        for act in w.actions:
            k = z_index.get(act.variable)
            if k is None or k not in states:
                raise ModelError(f"reinit({act.variable.name}, ...) in {w.origin or '(model)'} "
                                 f"({w.origin_class}): {act.variable.name} is not a state of "
                                 "the model, so it cannot be re-initialized")
            values.append(act.value.replace(lambda e: isinstance(e, pre), lambda e: e.args[0]))
            targets.append(k)
            owners.append(w_i)
    return conds + values, targets, owners


def solve_linear(residual, x):
    """x from residual(x) = 0 when x enters linearly:  x = -r(x=0) / (dr/dx)."""
    c = partial(residual, x)
    return -residual.xreplace({x: 0}) / c


def _dynamic(reduction) -> DynamicStateSelection:
    s = reduction.structure
    sel = reduction.selection
    level_rows = {r for rows, _ in sel.levels for r in rows}
    row_vars = {r: [v for v in s.graph[r] if s.diff_to_var[v] is not UNASSIGNED]
                for r in level_rows}
    weights = [_SELECT_WEIGHT[s.state_priority[s.diff_to_var[v]]]
               if s.diff_to_var[v] is not UNASSIGNED else 1.0 for v in range(s.n_vars)]
    return DynamicStateSelection(sel.levels, row_vars, list(s.var_to_diff),
                                 list(s.diff_to_var), weights, s.var_names)


# Column weights for the runtime choice of dummies: a large weight makes a column (the
# derivative of a variable the user would rather not have as a state) a likely pivot.
_SELECT_WEIGHT = {0: 1e6, 1: 1e2, 2: 1.0, 3: 1e-2, 4: 0.0}


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


def _start(system, k) -> float:
    s = system.symbols[k]
    if s in system.var_info and system.var_info[s].attrs.start is not None:
        return float(system.var_info[s].attrs.start)
    return 0.0


def _output_map(flat, aliases, index, psyms) -> dict:
    """Every flat variable's name -> (sign, y index), or (None, f) with f(p) its constant
    value (a variable fixed to an expression of parameters)."""
    out = {}
    for v in flat.variables:
        if v.name in aliases.constants:
            value = sp.sympify(aliases.constants[v.name])
            out[v.name] = (None, sp.lambdify([psyms], value, modules="math")
                           if value.free_symbols else float(value))
            continue
        sign, root = aliases.resolve(v.name)
        out[v.name] = (float(sign), index[sp.Symbol(root, real=True)])
    for s, k in index.items():
        out.setdefault(s.name, (1.0, k))
    return out


def _initial_rows(system, reduced, reduction, caus):
    """Initial equations and fixed starts (mandatory), then a start-value row for every
    other state (optional: :func:`acausal.compiler.initial.choose_rows` keeps those that
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
        from .initial import InitializationFailed
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