"""compile() and simulate(): the two calls a user makes.

``simulate`` also turns the driver's event log into :class:`~acausal.result.Event`
records (which relations crossed, what changed, which when-clauses fired and what they
re-initialized) and shows progress in simulated time (``progress=``, a tqdm bar).
"""
from __future__ import annotations

import math
import sys
import time as _clock
import warnings
from typing import TYPE_CHECKING

import numpy as np

from .components.component import Component
from .result import Event, Result
from .errors import InvalidArgument, ModelError, SimulationError

if TYPE_CHECKING:
    from .runtime import CompiledModel

__all__ = ["compile", "simulate", "initial_values", "check_arguments"]


def compile(model: Component, backend: str = "auto", cache=True,  # noqa: A001
            check_units: str = "warn") -> CompiledModel:
    """Flatten, reduce and generate code for a model instance; see ``compiled.report``.

    ``backend``: ``"c"`` (generated C, compiled once per model into a cache; raises
    BackendError without a working C compiler), ``"numpy"`` (generated Python), or
    ``"auto"`` (C when a compiler works, else numpy; ``compiled.backend`` says which).
    ``cache``: ``True`` (default) takes an unchanged model from the compile cache in
    ``$ACAUSAL_CACHE`` or ``~/.cache/acausal``, found by its flattened equations and
    parameter values; ``"tree"`` also by its instance tree, without flattening or
    importing sympy (for models whose equations read nothing but their classes, modules
    and parameters); ``False`` always compiles (see :mod:`acausal.compiler.cache.entries`).
    ``check_units``: ``"warn"`` (default) warns (``UnitWarning``) at an equation whose
    terms have different dimensions, ``"error"`` raises ``UnitError``, ``"off"`` skips
    the check (:mod:`acausal.compiler.frontend.unitcheck`); ``compiled.report.units`` says what
    was checked and lists the variables declared without a unit."""
    # imported here: the runtime brings scipy, the compiler sympy (with its passes some
    # 0.3 s to import), which importing acausal does not need; a model found in the
    # compile cache by its instance tree needs neither sympy nor the passes
    from .compiler import cache as compile_cache
    from .runtime import CompiledModel
    if isinstance(model, CompiledModel):
        return model
    if not isinstance(model, Component):
        raise ModelError(f"acausal compiles Components, got {model!r} ({type(model).__name__})")
    if cache == "tree" and compile_cache.enabled():
        found, _ = compile_cache.find_by_tree(model, backend)
        if found is not None:
            _declare_units(found, model)
            return CompiledModel(found)
    from .compiler.pipeline import compile_model
    mc = compile_model(model, backend, cache=cache, check_units=check_units)
    _declare_units(mc, model)
    return CompiledModel(mc)


def _declare_units(mc, model) -> None:
    """``meta["units"]`` and ``meta["descriptions"]`` by output and parameter name, as
    the component tree declares them, unless the compiler put them there already."""
    if "units" in mc.meta and "descriptions" in mc.meta:
        return
    from .components.units import output_tables
    from .results_io import declared_attributes
    units, descriptions = output_tables(*declared_attributes(model),
                                        list(mc.outputs) + list(mc.param_names))
    mc.meta.setdefault("units", units)
    mc.meta.setdefault("descriptions", descriptions)


def initial_values(compiled: CompiledModel, t0: float = 0.0) -> np.ndarray:
    """Consistent z(t0): the model's equations plus its initial conditions, the relations
    settled (:mod:`acausal.runtime.initial`, the one initialization path)."""
    return compiled.initialize(float(t0))[0]


def simulate(model, t_end: float, *, t_start: float = 0.0, rtol: float = 1e-6,
             atol: float | None = None, t_eval=None, n_points: int | None = None,
             max_step: float = np.inf, parameters: dict | None = None,
             max_order: int = 5, raise_on_failure: bool = False,
             backend: str = "auto", progress: bool | None = None,
             step_loop: str = "auto", check_units: str = "warn",
             nonfinite: str = "stop", outputs=None, store=None,
             inputs: dict | None = None, error_test: str = "all") -> Result:
    """Simulate a model (a Component, or a CompiledModel) from t_start to t_end.

    ``rtol``/``atol``: error tolerances (atol scaled by each variable's nominal value;
    default atol = rtol).  ``t_eval`` (sorted times within [t_start, t_end]) or
    ``n_points`` (>= 2, evenly spaced): output times (default: every accepted step and
    the points just before and after each event).  ``parameters``: {"R1.R": 5.0} changes
    parameter values for this run, without recompiling (the compiled model keeps its own;
    ``CompiledModel.set_parameters`` changes those).  A run that fails returns what it
    computed with ``success=False`` and the reason in ``message`` (and warns), or raises
    SimulationError if ``raise_on_failure``.  ``max_order`` caps the BDF order (DASSL's
    maxord: 2 helps on weakly damped high-frequency modes that only need to stay bounded).
    ``backend``: how a Component is compiled (see :func:`compile`).  ``progress``: a
    progress bar in simulated time (tqdm, the ``progress`` extra; a widget in notebooks);
    None shows it only when stderr is a terminal and the run takes more than 2 s.
    ``step_loop``: where the BDF steps run: "auto" (the compiled loop when the model
    qualifies and the loop's library is built, on either backend, see
    :mod:`acausal.solvers.cbdf`), "c" or "python".
    ``check_units``: as in :func:`compile`, for a Component compiled here.
    ``nonfinite``: a variable that is NaN or inf at an output point ends the run with
    ``success=False``, naming the variable, its equation and the time (``"stop"``), or
    only warns and the run goes on (``"warn"``).
    ``outputs``: the variables to keep (default: every one, each computed when first
    read); the result holds the states' values and these.  ``store``: a file
    (``"run.h5"``, HDF5) the run writes as it goes, a block of points at a time, instead
    of holding its points: the result returned reads its variables from the file when
    asked (:mod:`acausal.results_store`; with ``outputs``, only those are written).
    ``inputs``: how the model's top-level inputs (input ports of the model itself that
    nothing in it drives, ``compiled.input_names``) are driven, by name: a number, a
    function of time, a table ``(times, values)`` or a ``CombiTimeTable`` (its times
    are time events); every input must be given (``ac.MissingInput`` names those that
    are not), see :mod:`acausal.runtime.inputs`.
    ``error_test``: what the integrator's local error test covers: "all" (every unknown)
    or "states" (the states alone, as the state-space form; :mod:`acausal.solvers.bdf`).
    """
    check_arguments(t_end, t_start, rtol, atol, n_points)
    t_start, t_end, rtol = _time("t_start", t_start), _time("t_end", t_end), float(rtol)
    max_step = _positive("max_step", max_step, allow_inf=True)
    if isinstance(max_order, bool) or not isinstance(max_order, (int, np.integer)) \
            or not 1 <= max_order <= 5:
        raise InvalidArgument(f"simulate: max_order must be an integer from 1 to 5, "
                              f"got {max_order!r}")
    from .solvers.driver import NONFINITE
    if error_test not in ("all", "states"):
        raise InvalidArgument(f"simulate: error_test must be 'all' or 'states', "
                              f"got {error_test!r}")
    if nonfinite not in NONFINITE:
        raise InvalidArgument(f"simulate: nonfinite must be one of "
                              f"{', '.join(map(repr, NONFINITE))}, got {nonfinite!r}")
    if parameters is not None and not isinstance(parameters, dict):
        raise InvalidArgument(f"simulate: parameters must be a dict {{name: value}}, "
                              f"got {type(parameters).__name__}")
    t_eval = _output_times(t_eval, n_points, t_start, t_end)
    compiled = compile(model, backend, check_units=check_units)
    atol = _absolute_tolerance(compiled, atol, rtol)
    # the values hold for this run only (as in sweeps and estimation): a later run of the
    # same compiled model starts again from the values it had before
    saved = compiled.p.copy()
    keeping = None
    try:
        if parameters:
            compiled.set_parameters(parameters)
        compiled.drive_inputs(inputs)
        from .results_io import Keeping
        keeping = Keeping.make(compiled, outputs, store)
        return _run(compiled, t_start, t_end, rtol, atol, t_eval, max_step, max_order,
                    raise_on_failure, progress, step_loop, nonfinite, keeping,
                    error_test)
    finally:
        if keeping is not None:
            keeping.abandon()          # a run that raised: the file is closed
        compiled.p[:] = saved
        compiled.release_inputs()


def _run(compiled, t_start, t_end, rtol, atol, t_eval, max_step, max_order,
         raise_on_failure, progress, step_loop, nonfinite="stop", keeping=None,
         error_test=None) -> Result:
    """One run of a compiled model at its current parameter values (``keeping``: what
    it keeps, :class:`acausal.results_io.Keeping`)."""
    if keeping is None:
        from .results_io import Keeping
        keeping = Keeping()
    y0, yp0 = compiled.initialize(t_start)
    from .runtime.clocked import has_discrete_events, run_between_events
    if compiled.n == 0 and has_discrete_events(compiled):
        # nothing to integrate, but held values change at events (runtime/clocked.py)
        marks = _log_marks(compiled)
        out = run_between_events(compiled, t_start, t_end, t_eval)
        events, _ = _event_records(compiled, out, marks)
        return keeping.result(compiled, out.t, np.zeros((len(out.t), 0)), out.stats, events,
                              True, "no states: run from event to event", out.point_states,
                              list(range(len(out.t))), delayed=_input_values(compiled, out.t))
    if compiled.n == 0:
        # nothing to integrate: every variable is an explicit function of time, and each
        # point is evaluated with the relations as they hold there
        t = t_eval if t_eval is not None else np.linspace(t_start, t_end, 501)
        delayed = ()
        if compiled.delays is not None:
            from .runtime.delays import explicit_values
            delayed = explicit_values(compiled, compiled.delays, t)
        if compiled.inputs_vary:
            varied = _input_values(compiled, t)
            delayed = np.column_stack([delayed, varied]) if len(delayed) else varied
        success, message = True, "no states: evaluated explicitly"
        bad = _first_nonfinite(compiled, t) if compiled.delays is None else None
        if bad is not None:       # a variable undefined there (runtime contract item 11)
            k, what = bad
            message = f"a value is not finite at an output point: {what}"
            if nonfinite == "stop":
                success, t = False, t[:k]
                delayed = delayed[:k] if len(delayed) else delayed
            warnings.warn(f"simulate: {message}", RuntimeWarning, stacklevel=3)
        return keeping.result(compiled, t, np.zeros((len(t), 0)), {"steps": 0}, [], success,
                              message, delayed=delayed)
    from .solvers import integrate
    marks = _log_marks(compiled)
    bar = _Progress.make(progress, t_start, t_end)
    try:
        out = integrate(compiled, (t_start, t_end), y0, yp0, rtol=rtol, atol=atol,
                        t_eval=t_eval, max_step=max_step, max_order=int(max_order),
                        initialize=False, progress=bar, step_loop=step_loop,
                        nonfinite=nonfinite, sink=keeping.sink, error_test=error_test)
    except SimulationError as err:
        partial = err.partial
        start = _singular_start(compiled, t_start)
        if start and start not in str(err):
            # what failed first: the structure found at compile time does not hold here
            err.args = (f"{err}; {start}",)
            err.reason = str(err)
        res = _result(compiled, partial, False, str(err), marks, keeping) \
            if partial is not None and getattr(partial, "points", len(partial.t)) else None
        if raise_on_failure or res is None:
            err.partial = res
            raise
        warnings.warn(f"simulation stopped early: {err}", RuntimeWarning, stacklevel=2)
        return res
    finally:
        if bar is not None:
            bar.close()
    message = out.message
    start = _singular_start(compiled, t_start) if not out.success else None
    if start and start not in message:
        message = f"{message}; {start}"
    if getattr(out, "nonfinite", None):
        message = f"{message}; {out.nonfinite} (the run went on: nonfinite='warn')"
        warnings.warn(f"simulate: {out.nonfinite}", RuntimeWarning, stacklevel=3)
    missed = out.stats.interpolated_outputs
    if missed:
        # the algebraic values there could not be solved from the states: said, not hidden
        message = (f"{message}; at {missed} requested output time(s) the algebraic "
                   "unknowns without an error bound are interpolated, not solved")
        warnings.warn(f"simulate: {message}", RuntimeWarning, stacklevel=3)
    relaxed = _relaxed(out.stats)
    if relaxed:
        message = f"{message}; {relaxed}"
        warnings.warn(f"simulate: {relaxed}", RuntimeWarning, stacklevel=3)
    return _result(compiled, out, out.success, message, marks, keeping)


def _relaxed(stats) -> str:
    """What the run says when a restart was recovered by taking algebraic unknowns out of
    the error test (:mod:`acausal.solvers.recovery`): from then on their accuracy is the
    states' tolerance times their gain on the states, not their own tolerance."""
    names = getattr(stats, "relaxed_names", None)
    if not names:
        return ""
    from .words import listed
    return (f"from t = {stats.relaxed_at:.6g} the algebraic unknown(s) {listed(names)} "
            "were left out of the error test (steps at round-off after an event): their "
            "accuracy from there on follows the states' tolerance through the equations")


def _input_values(compiled, t):
    """The varying inputs' values at the points t (recorded with a result), or ()."""
    if not compiled.inputs_vary:
        return ()
    return np.array([compiled.inputs.values_at(tk) for tk in t]).reshape(len(t), -1)


def _singular_start(compiled, t_start) -> str | None:
    """The initialization's note that the structural analysis fails at t_start (the
    algebraic Jacobian is singular there), or None."""
    head = f"structural analysis fails at t = {t_start:.6g}"
    report = getattr(compiled, "report", None)
    for note in getattr(report, "notes", ()):
        if note.startswith(head):
            return note
    return None


def _result(compiled, out, success, message, marks=(0, 0, ""), keeping=None) -> Result:
    events, switches = _event_records(compiled, out, marks)
    if keeping is None:
        from .results_io import Keeping
        keeping = Keeping()
    return keeping.result(compiled, out.t, out.y, out.stats, events, success, message,
                          out.discrete_states, out.discrete_index, switches,
                          getattr(out, "point_values", ()))


def _log_marks(compiled) -> tuple:
    """Where this run's entries start in the model's when-clause and state-switch logs."""
    whens = len(compiled.whens.log) if compiled.whens is not None else 0
    switches = len(compiled.dynamic.switches) if compiled.dynamic is not None else 0
    dummies = ", ".join(sorted(compiled.names[d] for d in compiled.dummies))
    return whens, switches, dummies


def _event_records(compiled, out, marks) -> tuple[list, list]:
    """(events, state switches) of one run as :class:`Event` records, from the driver's
    event log, the discrete state snapshots and the when-clause log."""
    log = getattr(out, "event_log", None)
    if log is None:
        return list(out.event_times), []
    fired = {}
    if compiled.whens is not None:
        for entry in compiled.whens.log[marks[0]:]:
            fired.setdefault(entry[0], []).append(entry)
        del compiled.whens.log[marks[0]:]        # read once: the log must not grow per run
    snaps, n_rel = out.discrete_states, compiled.discrete.n_rel
    events = []
    for e in log:
        changes = []
        if snaps and e["before"] >= 0:
            m0, m1 = snaps[e["before"]], snaps[e["after"]]
            changes = [(compiled.relation_text(k), float(m0[k]), float(m1[k]))
                       for k in np.flatnonzero(m0 != m1)
                       if k < compiled.discrete.pre.start]   # pre(y) repeats held(y)
        # oriented roots: one per relation, then two per frozen integer value
        items = sorted({k if k < n_rel else n_rel + (k - n_rel) // 2 for k in e["crossed"]})
        relations = [compiled.relation_text(k) for k in items]
        whens, reinits = [], []
        for _, clauses, targets, before, after in fired.get(e["time"], ()):
            whens += [compiled.whens.texts[c] for c in clauses]
            reinits += [(compiled.names[i], b, a) for i, b, a in zip(targets, before, after)]
        kind = "when" if whens else ("relation" if e["kind"] == "state" else "time")
        events.append(Event(e["time"], kind, relations, changes, whens, reinits))
    switches = []
    if compiled.dynamic is not None:
        previous = marks[2]
        for t, dummies in compiled.dynamic.switches[marks[1]:]:
            now = ", ".join(dummies)
            switches.append(Event(t, "state switch", changes=[("dummy derivatives",
                                                               previous, now)]))
            previous = now
    return events, switches


class _Progress:
    """A tqdm bar in simulated time, called by the driver after every step.  The wall
    clock is read on every call (~50 ns) and the bar redrawn at most every 0.1 s, so
    the bar costs nothing measurable next to a BDF step."""

    _EVERY = 0.1          # s of wall time between redraws
    _AUTO_AFTER = 2.0     # progress=None: a bar only for runs longer than this

    @classmethod
    def make(cls, progress, t0, tf):
        if progress is False:
            return None
        if progress is None and not (hasattr(sys.stderr, "isatty") and sys.stderr.isatty()):
            return None
        return cls(t0, tf, delay=0.0 if progress else cls._AUTO_AFTER)

    def __init__(self, t0, tf, delay=0.0):
        self.t0, self.tf = t0, tf
        self.bar, self.shown = None, t0
        self.next = _clock.perf_counter() + delay
        if delay == 0.0:
            self._open()

    def _open(self):
        try:
            from tqdm.auto import tqdm
        except ImportError as err:
            raise ImportError("progress bars need tqdm: pip install 'acausal[progress]'") \
                from err
        self.bar = tqdm(total=self.tf - self.t0, unit="s", unit_scale=False,
                        desc="simulated time", leave=False,
                        bar_format="{desc}: {percentage:3.0f}%|{bar}| t = {postfix} "
                                   "[{elapsed}<{remaining}]")
        self.bar.set_postfix_str(f"{self.t0:.4g}", refresh=False)

    def __call__(self, t):
        now = _clock.perf_counter()
        if now < self.next:
            return
        self.next = now + self._EVERY
        if self.bar is None:
            self._open()
        self.bar.update(t - self.shown)
        self.bar.set_postfix_str(f"{t:.4g}", refresh=False)
        self.shown = t

    def close(self):
        if self.bar is not None:
            self.bar.close()


def _first_nonfinite(compiled, t):
    """(k, what) of the first time of ``t`` at which a checked output of a model without
    states is not finite (runtime contract item 11), or None."""
    check = getattr(compiled, "check_point", None)
    if check is None:
        return None
    z = np.zeros(0)
    with np.errstate(all="ignore"):
        for k, tk in enumerate(t):
            if k and not check.every_point:
                break
            compiled.init_modes(tk, z)
            what = check(float(tk), z, every=k == 0)
            if what is not None:
                return k, what
    return None


def check_arguments(t_end, t_start=0.0, rtol=1e-6, atol=None, n_points=None) -> None:
    """The checks :func:`simulate` makes of these arguments before anything is compiled
    (the command line makes them before it loads the model): InvalidArgument."""
    t_start, t_end = _time("t_start", t_start), _time("t_end", t_end)
    if not t_end > t_start:
        raise InvalidArgument(f"simulate: t_end = {t_end} must be after t_start = {t_start}")
    _tolerance(rtol)
    if atol is not None and not isinstance(atol, dict):
        _positive("atol", atol)
    _output_times(None, n_points, t_start, t_end)


def _number(name, value) -> float:
    if isinstance(value, bool) or value is None:
        raise InvalidArgument(f"simulate: {name} must be a number, got {value!r}")
    try:
        return float(value)
    except (TypeError, ValueError):
        raise InvalidArgument(f"simulate: {name} must be a number, got {value!r}") from None


def _time(name, value) -> float:
    x = _number(name, value)
    if not math.isfinite(x):
        raise InvalidArgument(f"simulate: {name} must be finite, got {value!r}")
    return x


def _positive(name, value, allow_inf=False) -> float:
    x = _number(name, value)
    if math.isnan(x) or (math.isinf(x) and not allow_inf) or x <= 0:
        raise InvalidArgument(f"simulate: {name} must be > 0"
                              f"{'' if allow_inf else ' and finite'}, got {value!r}")
    return x


def _tolerance(rtol) -> float:
    """rtol, a fraction: in (0, 1) (a relative error of 1 or more bounds nothing)."""
    x = _number("rtol", rtol)
    if not 0.0 < x < 1.0:
        raise InvalidArgument(f"simulate: rtol is a relative error and must be in (0, 1), "
                              f"e.g. 1e-6; got {rtol!r}")
    return x


def _absolute_tolerance(compiled, atol, rtol):
    """atol > 0 as the integrator takes it (scaled by each unknown's nominal value): a
    number, or ``{name: atol}`` for some of the unknowns the integrator controls (the
    others take rtol), as an array in their order."""
    if atol is None:
        return rtol
    if not isinstance(atol, dict):
        return _positive("atol", atol)
    out = np.full(compiled.n, rtol)
    index = {n: k for k, n in enumerate(compiled.names)}
    for name, value in atol.items():
        x = _positive(f"atol[{name!r}]", value)
        if name in index:
            out[index[name]] = x
            continue
        from .words import listed, suggestion
        if name in compiled.outputs:
            raise InvalidArgument(
                f"simulate: atol[{name!r}]: {name} is computed from the unknowns the "
                f"integrator controls, which are {listed(compiled.names)}")
        raise InvalidArgument(f"simulate: atol[{name!r}]: the model has no variable "
                              f"{name!r}{suggestion(name, compiled.outputs)}")
    return out


def _output_times(t_eval, n_points, t_start, t_end):
    """The requested output times, checked: nothing is dropped silently."""
    if t_eval is not None and n_points is not None:
        raise InvalidArgument("simulate: give t_eval or n_points, not both")
    if n_points is not None:
        if isinstance(n_points, bool) or not isinstance(n_points, (int, np.integer)) \
                or n_points < 2:
            raise InvalidArgument(f"simulate: n_points must be an integer >= 2, "
                                  f"got {n_points!r}")
        return np.linspace(t_start, t_end, int(n_points))
    if t_eval is None:
        return None
    try:
        te = np.asarray(t_eval, dtype=float).ravel()
    except (TypeError, ValueError):
        raise InvalidArgument("simulate: t_eval must be a sequence of numbers") from None
    if te.size == 0:
        raise InvalidArgument("simulate: t_eval is empty")
    if not np.all(np.isfinite(te)):
        raise InvalidArgument(f"simulate: t_eval has non-finite entries at positions "
                         f"{np.flatnonzero(~np.isfinite(te))[:5].tolist()}")
    if np.any(np.diff(te) < 0):
        k = int(np.flatnonzero(np.diff(te) < 0)[0])
        raise InvalidArgument(f"simulate: t_eval must be sorted (t_eval[{k}] = {te[k]} > "
                         f"t_eval[{k + 1}] = {te[k + 1]})")
    outside = (te < t_start) | (te > t_end)
    if outside.any():
        raise InvalidArgument(f"simulate: t_eval has {int(outside.sum())} time(s) outside "
                         f"[t_start, t_end] = [{t_start}, {t_end}], e.g. {te[outside][0]}")
    return te
