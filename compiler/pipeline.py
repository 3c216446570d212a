"""The compiler pipeline: the passes by name, in order (as OpenModelica lists its modules).

:data:`PASSES` is the compile.  :func:`compile_model` makes a :class:`Compilation` (what
the passes have made so far) and runs each pass on it in this order, timing it into the
index report, until one has made the ModelCode (a model found in the compile cache) or
the pass named by ``until`` has run::

    flatten -> cache_lookup -> outline -> units -> discrete -> sampled -> delays -> reinit_states
    -> alias -> alias_resolution -> structure -> balance -> conversion -> index_reduction
    -> state_selection -> assemble -> codegen -> index_as_written -> report -> c_backend
    -> cache_store

The rooms of the compiler do the work: ``frontend/`` (the language to the flat model),
``algebra/`` (the sympy side), ``structure/`` (integers only), ``index/`` (numeric checks
of the structural decisions), ``backends/`` (the generated code) and ``cache/``.  A pass
here only takes what it reads from the Compilation and puts back what it makes.

The result is a :class:`~acausal.compiler.modelcode.ModelCode`: generated code and name
maps, run by :class:`acausal.runtime.CompiledModel`.
"""
from __future__ import annotations

import gc
import time as _time
from dataclasses import dataclass, field
from functools import partial
from typing import Callable

from .. import native
from ..components.component import Component
from ..components.declarations import TYPE_NAMES
from ..components.logic import INITIAL
from ..components.units import MODES
from . import cache as compile_cache
from .algebra.symbolic import SymbolicSystem, forget_expressions
from .assemble import assemble, model_code
from .backends.cbackend import BACKENDS, bind, prepare
from .flatmodel import FlatModel
from .frontend.alias import eliminate_aliases, resolve_aliases_in
from .frontend.delays import extract_delays
from .frontend.discrete import freeze_integer_functions
from .frontend.flatten import flatten
from .frontend.outline import outline_expressions
from .frontend.sampled import (declare_discrete_variables, explain_overdetermined,
                               pre_after_aliases, reinit_targets_are_states)
from .frontend.unitcheck import check_units
from .index.balance import check_balance
from .index.conversion import convert_model
from .index.reduction import as_written, differentiate, select
from .modelcode import ModelCode
from .report import IndexReport, mode_structures

__all__ = ["PASSES", "Pass", "Compilation", "compile_model"]


@dataclass
class Compilation:
    """What the passes of one compile have made so far: each pass reads fields set before
    it and sets its own (the names of the passes that set them are in the comments)."""

    model: Component
    backend: str = "auto"
    check_units: str = "warn"
    cache: object = False              # False, True or "tree" (see compile_model)
    report: IndexReport = None
    tree: str | None = None            # the cache key of the instance tree
    flat: FlatModel = None             # flatten (then discrete, sampled, delays)
    key: str | None = None             # cache_lookup: the cache key of the flat model
    discretes: list = field(default_factory=list)   # discrete: frozen floor values
    helds: list = field(default_factory=list)       # sampled: discrete variables
    delays: list = field(default_factory=list)      # delays: delay() values
    reduced: FlatModel = None          # alias
    aliases: object = None             # alias: the AliasTable
    system: SymbolicSystem = None      # structure (then index_reduction adds to it)
    structure: object = None          # structure: the integer Structure
    n_equations: int = 0               # structure: equations before differentiation
    differentiated: object = None      # index_reduction: Pantelides' result
    reduction: object = None           # state_selection: the IndexReduction
    causal: object = None              # assemble: the form the solver sees
    building: object = None            # codegen: the C library being compiled
    code: ModelCode = None             # codegen, or cache_lookup from the cache


@dataclass(frozen=True)
class Pass:
    """One pass of the pipeline: ``run(compilation)`` reads and extends it."""

    name: str
    run: Callable[[Compilation], None]
    doc: str = ""

    def __str__(self) -> str:
        return self.name


# -- the passes ---------------------------------------------------------------------------
def _flatten(c: Compilation) -> None:
    c.flat = flatten(c.model)
    c.report.derived_parameters = dict(c.flat.derived)
    zeros = c.flat.structural_zeros
    if zeros:
        c.report.notes.append("parameters equal to 0 were evaluated as structural zeros (set "
                              "a non-zero value to keep them tunable): "
                              + ", ".join(zeros[:20]) + (" ..." if len(zeros) > 20 else ""))


def _cache_lookup(c: Compilation) -> None:
    if not (c.cache and compile_cache.enabled()):
        return
    t0 = _time.perf_counter()
    c.key = compile_cache.flat_key(c.flat, c.backend)
    found = compile_cache.lookup(c.key) if c.key is not None else None
    if found is None:
        return
    if c.tree is not None:
        compile_cache.store_index(c.tree, c.key)
    code = found[0]
    # the flat key covers what the unit check reads: its findings are the entry's
    code.report.units = check_units(c.flat, c.check_units, code.report.units)
    seconds = _time.perf_counter() - t0 + c.report.timings.get("flatten", 0.0)
    c.code = compile_cache.from_cache(found, seconds, "its flat model")


def _outline(c: Compilation) -> None:
    made = outline_expressions(c.flat)
    if made:
        c.report.notes.append(f"{made} intermediate quantities named in long expressions "
                              "(compiler/frontend/outline.py): the passes after flattening "
                              "work on small equations")


def _units(c: Compilation) -> None:
    c.report.units = check_units(c.flat, c.check_units)


def _discrete(c: Compilation) -> None:
    c.discretes = freeze_integer_functions(c.flat)


def _sampled(c: Compilation) -> None:
    c.helds = declare_discrete_variables(c.flat)
    if c.helds:
        types = {v.name: TYPE_NAMES[getattr(v.attrs, "type", float)] for v in c.flat.variables}
        c.report.discrete = [{"name": h.name, "type": types.get(h.name, "Real"),
                              "set_by": h.clause} for h in c.helds]


def _delays(c: Compilation) -> None:
    c.delays = extract_delays(c.flat)
    if c.delays:
        c.report.notes.append(
            f"{len(c.delays)} delay(s), read from a history of their expressions; the "
            "integrator's step is limited to the shortest delay time: "
            + "; ".join(f"{d.text} in {d.where}" for d in c.delays[:10])
            + (" ..." if len(c.delays) > 10 else ""))


def _reinit_states(c: Compilation) -> None:
    reinit_targets_are_states(c.flat)


def _alias(c: Compilation) -> None:
    c.report.count("flatten", equations=len(c.flat.equations),
                   variables=len(c.flat.variables))
    c.reduced, c.aliases = eliminate_aliases(c.flat)
    c.report.aliases = c.aliases
    c.report.count("alias", equations=len(c.reduced.equations),
                   variables=len(c.reduced.variables))


def _alias_resolution(c: Compilation) -> None:
    resolve_aliases_in(c.discretes + c.delays, c.flat, c.aliases)
    pre_after_aliases(c.reduced, c.aliases, c.helds)


def _structure(c: Compilation) -> None:
    system = SymbolicSystem.from_flat(c.reduced)
    system.parameters |= {d.symbol for d in c.discretes}     # constant between events
    system.parameters |= {s for h in c.helds for s in (h.symbol, h.pre)}
    system.parameters.add(INITIAL)                           # initial(): constant in a run
    system.delays = {d.symbol: d for d in c.delays}          # inputs that vary
    system.delays.update({i.symbol: i for i in getattr(c.reduced, "inputs", ())})
    c.system, c.structure = system, system.structure()
    c.n_equations = len(system.equations)


def _balance(c: Compilation) -> None:
    try:
        check_balance(c.system, c.structure, c.reduced, c.aliases,
                      (len(c.flat.equations), len(c.flat.variables)))
    except Exception as err:
        explain_overdetermined(err, c.helds)
        raise


def _conversion(c: Compilation) -> None:
    c.report.conversion = convert_model(c.system, c.structure, c.reduced)


def _index_reduction(c: Compilation) -> None:
    c.differentiated = differentiate(c.system, c.report.conversion.structure)


def _state_selection(c: Compilation) -> None:
    c.reduction = select(c.system, c.differentiated, c.n_equations,
                         c.report.conversion.coefficient)
    c.report.reduction = c.reduction
    c.report.count("index_reduction", equations=len(c.system.equations),
                   variables=len(c.system.symbols))


def _assemble(c: Compilation) -> None:
    c.causal = assemble(c.system, c.reduction, c.reduced, c.report, c.discretes, c.helds)


def _codegen(c: Compilation) -> None:
    # the C library is printed as soon as the Programs are made, and its compiler runs
    # while the rest of this pass and the report are made (cbackend.prepare); the
    # printing is timed with the c_backend pass
    early = c.backend != "numpy" and native.find_compiler() is not None
    printing = []

    def programs_made(progs):
        t0 = _time.perf_counter()
        c.building = prepare(progs)
        printing.append(_time.perf_counter() - t0)

    c.code = model_code(c.system, c.reduction, c.causal, c.reduced, c.flat, c.aliases,
                        c.report, c.discretes, c.helds, c.delays,
                        programs_made if early else None)
    if printing:
        c.report.timings["c_backend"] = printing[0]
        c.report.timings["codegen"] = -printing[0]     # _run adds the pass's own time


def _index_as_written(c: Compilation) -> None:
    # for the report only, computed when it is first read (most reports never are): from
    # the flat model as the front passes left it (the balance pass has found the system
    # regular)
    c.report.written_by(partial(as_written, c.flat, checked=True))


def _report(c: Compilation) -> None:
    c.report.fill(c.system, c.reduction, c.code)
    c.report.modes = mode_structures(c.model)


def _c_backend(c: Compilation) -> None:
    building, c.building = c.building, None
    bind(c.code, c.backend, c.report, building)


def _cache_store(c: Compilation) -> None:
    if c.key is not None:
        compile_cache.store(c.key, c.code, c.tree)


PASSES = (
    Pass("flatten", _flatten, "instance tree -> flat model (connections resolved)"),
    Pass("cache_lookup", _cache_lookup, "an unchanged model from the compile cache"),
    Pass("outline", _outline, "long expressions split into intermediate quantities"),
    Pass("units", _units, "every equation checked for dimensional consistency"),
    Pass("discrete", _discrete, "floor/mod frozen between events"),
    Pass("sampled", _sampled, "discrete variables held, when-assignments checked"),
    Pass("delays", _delays, "delay() read from a history"),
    Pass("reinit_states", _reinit_states, "a re-initialized variable is always a state"),
    Pass("alias", _alias, "a = b, a = -b, a = constant removed"),
    Pass("alias_resolution", _alias_resolution, "values found before alias elimination"),
    Pass("structure", _structure, "the symbolic system and its integer structure"),
    Pass("balance", _balance, "Dulmage-Mendelsohn: as many equations as unknowns"),
    Pass("conversion", _conversion, "Pryce's success test, exact; LC conversion"),
    Pass("index_reduction", _index_reduction, "Pantelides: which equations to differentiate"),
    Pass("state_selection", _state_selection, "dummy derivatives"),
    Pass("assemble", _assemble, "BLT and tearing: what the solver vector holds"),
    Pass("codegen", _codegen, "residual, Jacobian, outputs and events as code"),
    Pass("index_as_written", _index_as_written,
         "the index of the equations as written (computed when the report is read)"),
    Pass("report", _report, "what the compiler did, in the user's names"),
    Pass("c_backend", _c_backend, "the generated C compiled and loaded, or numpy"),
    Pass("cache_store", _cache_store, "the compiled model kept in the compile cache"),
)
_NAMES = [p.name for p in PASSES]


# -- the compile --------------------------------------------------------------------------
def compile_model(model: Component, backend: str = "auto", cache=False,
                  check_units: str = "warn", until: str | None = None) -> ModelCode:
    """Compile a model instance to generated code and name maps (see the module
    docstring); :class:`acausal.runtime.CompiledModel` runs it.  ``backend``: ``"c"``,
    ``"numpy"`` or ``"auto"`` (:func:`acausal.compiler.backends.cbackend.bind`).

    ``cache`` (:mod:`acausal.compiler.cache`): ``True`` loads an unchanged model from the
    compile cache by the key of its flat model -- exact: the flattened equations,
    variables and parameter values are what the passes read -- and stores a new one;
    ``"tree"`` first tries the key of the instance tree, which needs neither sympy nor
    flattening but cannot see what an ``equations()`` reads from outside the model's
    classes and modules at call time (a file, the environment, a mutable object), so it
    is only taken when asked for; ``False`` compiles afresh.  The report of a loaded
    model says so in a note, and its timings are those of the original compile plus
    ``cache_lookup``.

    ``check_units`` (:mod:`acausal.compiler.frontend.unitcheck`): ``"error"`` raises
    UnitError at a dimensionally inconsistent equation, ``"warn"`` warns, ``"off"``
    skips the check.

    ``until``: the name of a pass; the compile stops after it and returns the
    :class:`Compilation` (what the passes made so far) instead of the ModelCode."""
    if cache not in (True, False, "tree"):
        raise ValueError(f"cache must be True, False or 'tree', got {cache!r}")
    if check_units not in MODES:
        raise ValueError(f"check_units must be one of {MODES}, got {check_units!r}")
    if backend not in BACKENDS:
        raise ValueError(f"backend must be one of {', '.join(map(repr, BACKENDS))}, "
                         f"got {backend!r}")
    if until is not None and until not in _NAMES:
        raise ValueError(f"until must name a pass ({', '.join(_NAMES)}), got {until!r}")
    c = Compilation(model, backend, check_units, cache,
                    IndexReport(model_name=type(model).__name__))
    if cache == "tree" and until is None and compile_cache.enabled():
        code, c.tree = compile_cache.find_by_tree(model, backend)
        if code is not None:
            return code
    out = _run(c, until)
    return out if until is not None else out.code


def _run(c: Compilation, until: str | None) -> Compilation:
    """The passes on ``c`` in order, the cyclic garbage collector paused meanwhile.

    Why paused: the passes allocate millions of sympy nodes that live until the compile
    ends and form no garbage cycles worth finding; the collector's walks over that
    growing heap cost a quarter of a large build.  It is switched back on, as it was,
    however the compile ends; after a large one, one full collection walks what the
    compile left, once (:func:`_collect_after`)."""
    collecting = gc.isenabled()
    gc.disable()
    try:
        for p in PASSES:
            t0 = _time.perf_counter()
            p.run(c)
            c.report.timings[p.name] = (c.report.timings.get(p.name, 0.0)
                                        + _time.perf_counter() - t0)
            if p.name == until or (c.code is not None and p.name == "cache_lookup"):
                break
        return c
    finally:
        if c.building is not None:        # a C compiler still running: stopped
            c.building.cancel()
            c.building = None
        forget_expressions()
        if collecting:
            _collect_after()
            gc.enable()


# below this many new objects the collector's own schedule costs little
_YOUNG_ENOUGH = 100_000


def _collect_after() -> None:
    """A full collection now, when the objects made while the collector was paused are
    so many that CPython's schedule would soon run one anyway (more than a quarter of
    the old objects).  What a large compile keeps would otherwise be walked three times
    once the collector runs again: by the young collection, by the middle one its
    survivors move to, and by the full one that follows (a 100 000-equation model keeps
    about 4 million objects, 4-6 s of walks)."""
    young = gc.get_count()[0]
    if young > _YOUNG_ENOUGH and 4 * young > len(gc.get_objects(generation=2)):
        gc.collect()
