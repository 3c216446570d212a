"""The compiler pipeline: the passes by name, in order (as OpenModelica lists its modules).

    flatten -> outline (long expressions split into intermediate quantities) ->
            units (dimensions checked) -> discrete (floor/mod frozen) -> sampled
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

import functools
import gc as _gc
import sys as _sys
import time as _time
from dataclasses import replace

from ..components.component import Component
from . import sidejobs
from .gcpause import collect_after_pause
from .modelcode import ModelCode
from .report import IndexReport, mode_structures

# The passes and sympy are imported where they run: a model found in the compile cache
# is returned without importing either.

__all__ = ["PASSES", "compile_model"]

# flat equations from which a compile forks its side jobs (sidejobs): below, forking
# costs more than the work it moves (the index as written of 2000 equations: ~20 ms)
SIDE_JOBS_FROM = 2000

PASSES = ("flatten", "outline", "units", "discrete", "sampled", "delays", "alias", "balance",
          "conversion", "index_reduction", "state_selection", "assemble", "codegen")


def compile_model(model: Component, backend: str = "auto", cache=False,
                  check_units: str = "warn") -> ModelCode:
    """Compile a model instance to generated code and name maps (see the module docstring);
    :class:`acausal.runtime.CompiledModel` runs it.  ``backend``: ``"c"``, ``"numpy"`` or
    ``"auto"`` (:func:`acausal.compiler.backends.cbackend.bind`).

    ``cache`` (:mod:`acausal.compiler.cache.entries`): ``True`` loads an unchanged model from the
    compile cache by the key of its flat model -- exact: the flattened equations,
    variables and parameter values are what the passes read -- and stores a new one;
    ``"tree"`` first tries the key of the instance tree, which needs neither sympy nor
    flattening but cannot see what an ``equations()`` reads from outside the model's
    classes and modules at call time (a file, the environment, a mutable object), so it
    is only taken when asked for; ``False`` compiles afresh.  The report of a loaded
    model says so in a note, and its timings are those of the original compile plus
    ``cache_lookup``.

    ``check_units`` (:mod:`acausal.compiler.frontend.unitcheck`): ``"error"`` raises UnitError
    at a dimensionally inconsistent equation, ``"warn"`` warns, ``"off"`` skips the
    check; it runs on the flat model, so a model found by its instance tree
    (``cache="tree"``) is not checked again."""
    # Why the collector is paused: the passes allocate millions of sympy nodes that
    # live until the compile ends and form no garbage cycles worth finding; the
    # collector's full passes over that growing heap cost a quarter of a large build
    # (it is switched back on, as it was, however the compile ends).
    collecting = _gc.isenabled()
    _gc.disable()
    stores = []
    try:
        try:
            out = _compile(model, backend, cache, check_units, stores)
        finally:
            symbolic = _sys.modules.get(__package__ + ".algebra.symbolic")
            if symbolic is not None:     # what it keeps of this model's expressions
                symbolic.forget_expressions()
            if collecting:
                collect_after_pause()
        # the cache entry is written last, once what the compile made and no longer
        # needs is freed: a large model's is written in a forked child, and every page
        # the parent writes while the child lives (freeing an object writes to it) is
        # copied first -- the caches forgotten above took 31-48 ms after the fork, 10-20
        # before it, on the 1000-section ladder
        for store in stores:
            store()
        return out
    finally:
        if collecting:
            _gc.enable()


def _compile(model, backend, cache, check_units, stores) -> ModelCode:
    """The compile; ``stores`` receives the writing of the cache entry, for the caller
    to run at the end."""
    if cache not in (True, False, "tree"):
        raise ValueError(f"cache must be True, False or 'tree', got {cache!r}")
    from ..components.units import MODES
    if check_units not in MODES:
        raise ValueError(f"check_units must be one of {MODES}, got {check_units!r}")
    from .cache import entries as store
    use_cache = bool(cache) and store.enabled()
    t0 = _time.perf_counter()
    tree = store.tree_key(model, backend) if use_cache and cache == "tree" else None
    if tree is not None:
        found = store.lookup(tree=tree)
        if found is not None:
            model._bind("")     # the instance named as a compile leaves it (no sympy)
            return _from_cache(found, _time.perf_counter() - t0, "its instance tree")
    t_tree = _time.perf_counter() - t0
    from .frontend.flatten import flatten
    from .index.reduction import as_written
    report = IndexReport(model_name=type(model).__name__)
    clock = _Clock(report)
    flat = clock("flatten", flatten, model)
    from .frontend.outline import outline_expressions
    made = clock("outline", outline_expressions, flat)
    if made:
        report.notes.append(f"{made} intermediate quantities named in long expressions "
                            "(compiler/frontend/outline.py): the passes after flattening "
                            "work on small equations")
    from .frontend.unitcheck import check_units as unit_check
    from .frontend.unitcheck import complain
    report.derived_parameters = dict(flat.derived)
    front = None         # what the passes before alias elimination found, once run
    key = units = aliased = None
    if use_cache:
        # a large model's key is hashed, and its units checked, beside the first passes
        # and alias elimination, which a hit wastes (in time the compile would mostly
        # have waited) and a miss needs
        t1 = _time.perf_counter()
        if _large(flat) and sidejobs.available():
            job = sidejobs.Beside(_key_and_units, flat, backend, check_units, model)
        else:
            job = sidejobs.Beside(_key_alone, flat, backend, fork=False)
        try:
            if job.running:
                front, aliased = _ahead(clock, report, flat, job, check_units)
            else:
                report.modes = mode_structures(model)
            t_front = _time.perf_counter() - t1 if front is not None else 0.0
            key, units, modes = job.result()
        finally:
            job.cancel()
        if modes is not None:
            report.modes = modes
        found = store.lookup(key) if key is not None else None
        if found is not None:
            if tree is not None:
                store.store_index(tree, key)
            if units is not None:
                found[0].report.units = complain(units, check_units)
            else:
                found[0].report.units = report.units if front is not None else \
                    unit_check(flat, check_units, found[0].report.units)
            lookup = _time.perf_counter() - t1 + report.timings["flatten"] + t_tree
            return _from_cache(found, lookup, "its flat model")
        # the time the key cost beyond the passes that ran beside it (timed themselves)
        report.timings["cache_key"] = _time.perf_counter() - t1 - t_front + t_tree
        if units is not None:
            report.units = complain(units, check_units)
            report.timings["units"] = units.seconds
            if check_units != "off":
                report.notes.append(f"the units were checked in a second process, beside "
                                    f"the passes up to alias elimination "
                                    f"({units.seconds:.2f} s)")
    else:
        report.modes = mode_structures(model)
    discretes, helds, delays = front or _front(clock, report, flat,
                                               None if units is not None else check_units)
    # the index as written reads the flat model as it is now; on a large model it is
    # computed beside the passes that follow (sidejobs), its result taken below
    beside = sidejobs.Beside(as_written, flat, fork=_large(flat))
    try:
        out = _passes(clock, report, flat, discretes, helds, delays, backend, beside,
                      aliased)
    finally:
        beside.cancel()
    if key is not None:
        stores.append(functools.partial(_store, report, key, out, tree, _large(flat)))
    return out


def _store(report, key, out, tree, large: bool) -> None:
    from .cache import entries as store
    t0 = _time.perf_counter()
    if not (large and sidejobs.detach(store.store, key, out, tree)):
        store.store(key, out, tree)
    report.timings["cache_store"] = _time.perf_counter() - t0    # not in the entry


def _key_and_units(flat, backend, check_units, model) -> tuple:
    """The side job of a large compile: the cache key of ``flat``, its unit check (whose
    findings the parent reports, :func:`acausal.compiler.frontend.unitcheck.complain`) and the
    report's table of the components' modes (10-60 ms for 6000 components)."""
    from .cache import entries as store
    from .frontend.unitcheck import check_units as unit_check
    return (store.flat_key(flat, backend), unit_check(flat, check_units, quiet=True),
            mode_structures(model))


def _key_alone(flat, backend) -> tuple:
    from .cache import entries as store
    return store.flat_key(flat, backend), None, None


def _ahead(clock, report, flat, job, check_units) -> tuple:
    """While ``job`` hashes the key and checks the units: the front passes, and alias
    elimination if the key is not ready after them; returns (front, aliased or None).
    An error of these passes is raised after the units' verdict, as in a compile that
    checks the units first."""
    from .frontend.alias import eliminate_aliases
    try:
        front = _front(clock, report, flat, None)
        aliased = None if job.ready() else clock("alias", eliminate_aliases, flat)
        return front, aliased
    except Exception:
        _, units, _ = job.result()
        from .frontend.unitcheck import complain
        complain(units, check_units)
        raise


def _front(clock, report, flat, check_units) -> tuple:
    """The passes before alias elimination: units, discrete, sampled, delays (the last
    three change ``flat``); returns what alias elimination needs of them."""
    from .frontend.delays import extract_delays
    from .frontend.discrete import freeze_integer_functions
    from .frontend.sampled import declare_discrete_variables
    from .frontend.unitcheck import check_units as unit_check
    if check_units is not None:         # None: checked in a side job (_ahead)
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
        from ..components.declarations import TYPE_NAMES
        types = {v.name: TYPE_NAMES[getattr(v.attrs, "type", float)] for v in flat.variables}
        report.discrete = [{"name": h.name, "type": types.get(h.name, "Real"),
                            "set_by": h.clause} for h in helds]
    if flat.structural_zeros:
        report.notes.append("parameters equal to 0 were evaluated as structural zeros (set a "
                            "non-zero value to keep them tunable): "
                            + ", ".join(flat.structural_zeros[:20])
                            + (" ..." if len(flat.structural_zeros) > 20 else ""))
    return discretes, helds, delays


def _large(flat) -> bool:
    return len(flat.equations) >= SIDE_JOBS_FROM


def _passes(clock, report, flat, discretes, helds, delays, backend, beside, aliased=None):
    from .frontend.alias import eliminate_aliases
    from .index.balance import check_balance
    from .index.conversion import convert_model
    from .index.reduction import reduce_index
    from .frontend.sampled import explain_overdetermined, pre_after_aliases
    # aliased: alias elimination taken while the cache key was hashed (_ahead)
    reduced, aliases = aliased or clock("alias", eliminate_aliases, flat)
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
    report.conversion = clock("conversion", convert_model, system, structure, reduced)
    reduction = clock("index_reduction", reduce_index, system, report.conversion.structure,
                      report.conversion.coefficient)
    report.reduction = reduction
    report.count("index_reduction", equations=len(system.equations),
                 variables=len(system.symbols))
    # the C library is printed as soon as the Programs are made, and compiled while
    # the rest of the codegen and report passes run (cbackend.prepare); the printing
    # is timed as part of the c_backend pass
    prepared, printing = [], []

    def programs_made(progs):
        from .backends.cbackend import prepare
        t0 = _time.perf_counter()
        prepared.append(prepare(progs))
        printing.append(_time.perf_counter() - t0)

    early = backend != "numpy" and _compiler_found()
    out = clock("codegen", _assemble, system, reduction, reduced, flat, aliases, report,
                discretes, helds, delays, programs_made if early else None)
    # the index as written is read for the report only: taken last, its side job has
    # had every pass since the front ones to finish (on a random network of 100k
    # equations it takes as long as alias elimination and the passes up to balance)
    report.sigma = clock("index_as_written", beside.result)
    if beside.forked:
        report.notes.append(f"the index as written was found in a second process, beside "
                            f"the passes from alias elimination on ({beside.seconds:.2f} s)")
    clock("report", report.fill, system, reduction, out)
    from .backends.cbackend import bind
    clock("c_backend", bind, out, backend, report, prepared[0] if prepared else None)
    if printing:
        report.timings["codegen"] -= printing[0]
        report.timings["c_backend"] += printing[0]
    return out


def _compiler_found() -> bool:
    """A C compiler is on the path (else the C backend's printing is left to bind,
    which says why it cannot build)."""
    from .backends.cbackend import compiler_available
    return compiler_available() is not None


def _from_cache(found, seconds, how) -> ModelCode:
    from .cache.entries import load_notes
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
    from .algebra.symbolic import SymbolicSystem
    system = SymbolicSystem.from_flat(reduced)
    system.parameters |= {d.symbol for d in discretes}   # constant between events
    system.parameters |= {s for h in helds for s in (h.symbol, h.pre)}
    from ..components.logic import INITIAL
    system.parameters.add(INITIAL)                   # initial(): constant while it runs
    system.delays = {d.symbol: d for d in delays}        # inputs that vary: never constant
    system.delays.update({i.symbol: i for i in getattr(reduced, "inputs", ())})
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


def _assemble(*args) -> ModelCode:
    from .assemble import assemble
    return assemble(*args)
