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
from .graph import UNASSIGNED
from .flatten import flatten
from .initial import InitialConditions
from .model import CompiledModel, DynamicStateSelection
from .reduction import reduce_index
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
    reduced, aliases = clock("alias", eliminate_aliases, flat)
    report.aliases = aliases
    report.count("alias", equations=len(reduced.equations), variables=len(reduced.variables))
    system = SymbolicSystem.from_flat(reduced)
    structure = system.structure()
    clock("balance", check_balance, system, structure, reduced, aliases,
          (len(flat.equations), len(flat.variables)))
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
    y_syms = list(system.symbols)
    index = {s: k for k, s in enumerate(y_syms)}
    params = [p for p in reduced.parameters if _is_number(p.value)]
    residuals = [eq.residual for eq in system.equations]
    residuals, crossings, modes = extract_relations(residuals)
    greater = np.array([isinstance(r, (sp.StrictGreaterThan, sp.GreaterThan))
                        for r in modes.values()], dtype=bool)
    code = generate(residuals, y_syms, [p.symbol for p in params], len(modes), crossings)
    nominal = [_nominal(system, k) for k in range(len(y_syms))]
    cm = CompiledModel(code, [s.name for s in y_syms], [p.name for p in params],
                       [float(p.value) for p in params], reduction.pairs, reduction.dummies,
                       _dynamic(reduction) if reduction.dynamic else None, nominal,
                       report=report,
                       meta={"relation_greater": greater,
                             "equation_names": [e.name(system) for e in system.equations],
                             "modes": modes})
    cm.outputs = _output_map(flat, aliases, index)
    cm.start = np.array([_start(system, k) for k in range(len(y_syms))])
    cm.initial_conditions = _initial_conditions(system, reduced, reduction, y_syms, params, cm)
    return cm


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


def _output_map(flat, aliases, index) -> dict:
    """Every flat variable's name -> (sign, y index) or (None, constant value)."""
    out = {}
    for v in flat.variables:
        if v.name in aliases.constants:
            out[v.name] = (None, float(aliases.constants[v.name]))
            continue
        sign, root = aliases.resolve(v.name)
        out[v.name] = (float(sign), index[sp.Symbol(root, real=True)])
    for s, k in index.items():
        out.setdefault(s.name, (1.0, k))
    return out


def _initial_conditions(system, reduced, reduction, y_syms, params, cm):
    """Initial equations, fixed starts, then free states' starts (see compiler.initial)."""
    init_res = [e.residual for e in reduced.initial_equations]
    descriptions = [f"initial equation {e.text} [{e.where}]" for e in reduced.initial_equations]
    init_res, _, _ = extract_relations(init_res)
    code = generate(init_res, y_syms, [p.symbol for p in params])
    n_needed = len(cm.link_s)
    fixed_idx, fixed_val = [], []
    for k, s in enumerate(y_syms):
        info = system.var_info.get(s)
        if info is not None and info.attrs.fixed and info.attrs.start is not None:
            fixed_idx.append(k)
            fixed_val.append(float(info.attrs.start))
            descriptions.append(f"{s.name} = {info.attrs.start} (fixed start value)")
    free = n_needed - len(init_res) - len(fixed_idx)
    if free < 0:
        from .initial import InitializationFailed
        raise InitializationFailed(
            f"the initial problem is over-specified: {len(init_res) + len(fixed_idx)} "
            f"initial conditions for {n_needed} states ({', '.join(y_syms[k].name for k in cm.link_s)}); "
            "conditions: " + "; ".join(descriptions))
    for k in _free_state_order(cm, system, fixed_idx):
        if free == 0:
            break
        fixed_idx.append(k)
        fixed_val.append(cm.start[k])
        descriptions.append(f"{y_syms[k].name} = {cm.start[k]} (start value of a state)")
        free -= 1
    return InitialConditions(code, fixed_idx, fixed_val, descriptions)


def _free_state_order(cm, system, fixed_idx):
    """The selected states, in order: their start values fill the free initial conditions."""
    taken = set(fixed_idx)
    return [k for k in cm.link_s if k not in taken]
