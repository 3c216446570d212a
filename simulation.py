"""compile() and simulate(): the two calls a user makes."""
from __future__ import annotations

import math
import warnings
from typing import TYPE_CHECKING

import numpy as np

from .components.component import Component, ModelError
from .errors import SimulationError
from .result import Result

if TYPE_CHECKING:
    from .runtime import CompiledModel

__all__ = ["compile", "simulate", "initial_values"]


def compile(model: Component, backend: str = "auto") -> CompiledModel:  # noqa: A001
    """Flatten, reduce and generate code for a model instance; see ``compiled.report``.

    ``backend``: ``"c"`` (generated C, compiled once per model into a cache; raises
    BackendError without a working C compiler), ``"numpy"`` (generated Python), or
    ``"auto"`` (C when a compiler works, else numpy; ``compiled.backend`` says which)."""
    # imported here: the compiler brings sympy and the runtime scipy, which importing
    # acausal (or this module, for its names) does not need
    from .compiler.pipeline import compile_model
    from .runtime import CompiledModel
    if isinstance(model, CompiledModel):
        return model
    if not isinstance(model, Component):
        raise ModelError(f"acausal compiles Components, got {model!r} ({type(model).__name__})")
    return CompiledModel(compile_model(model, backend))


def initial_values(compiled: CompiledModel, t0: float = 0.0) -> np.ndarray:
    """Consistent z(t0): the model's equations plus its initial conditions, the relations
    settled (:mod:`acausal.runtime.initial`, the one initialization path)."""
    return compiled.initialize(float(t0))[0]


def simulate(model, t_end: float, *, t_start: float = 0.0, rtol: float = 1e-6,
             atol: float | None = None, t_eval=None, n_points: int | None = None,
             max_step: float = np.inf, parameters: dict | None = None,
             max_order: int = 5, raise_on_failure: bool = False,
             backend: str = "auto") -> Result:
    """Simulate a model (a Component, or a CompiledModel) from t_start to t_end.

    ``rtol``/``atol``: error tolerances (atol scaled by each variable's nominal value;
    default atol = rtol).  ``t_eval`` (sorted times within [t_start, t_end]) or
    ``n_points`` (>= 2, evenly spaced): output times (default: every accepted step and
    the points just before and after each event).  ``parameters``: {"R1.R": 5.0} changes
    parameter values without recompiling.  A run that fails returns what it computed with
    ``success=False`` and the reason in ``message`` (and warns), or raises
    SimulationError if ``raise_on_failure``.  ``max_order`` caps the BDF order (DASSL's
    maxord: 2 helps on weakly damped high-frequency modes that only need to stay bounded).
    ``backend``: how a Component is compiled (see :func:`compile`).
    """
    t_start, t_end = _time("t_start", t_start), _time("t_end", t_end)
    if not t_end > t_start:
        raise ValueError(f"simulate: t_end = {t_end} must be after t_start = {t_start}")
    rtol = _positive("rtol", rtol)
    atol = rtol if atol is None else _positive("atol", atol, allow_zero=True)
    max_step = _positive("max_step", max_step, allow_inf=True)
    if isinstance(max_order, bool) or not isinstance(max_order, (int, np.integer)) \
            or not 1 <= max_order <= 5:
        raise ValueError(f"simulate: max_order must be an integer from 1 to 5, got {max_order!r}")
    t_eval = _output_times(t_eval, n_points, t_start, t_end)
    compiled = compile(model, backend)
    if parameters:
        if not isinstance(parameters, dict):
            raise ValueError("simulate: parameters must be a dict {name: value}")
        compiled.set_parameters(parameters)
    y0, yp0 = compiled.initialize(t_start)
    if compiled.n == 0:
        # nothing to integrate: every variable is an explicit function of time, and each
        # point is evaluated with the relations as they hold there
        t = t_eval if t_eval is not None else np.linspace(t_start, t_end, 501)
        return Result(compiled, t, np.zeros((len(t), 0)), {"steps": 0}, [], True,
                      "no states: evaluated explicitly")
    from .solvers import integrate
    try:
        out = integrate(compiled, (t_start, t_end), y0, yp0, rtol=rtol, atol=atol,
                        t_eval=t_eval, max_step=max_step, max_order=int(max_order),
                        initialize=False)
    except SimulationError as err:
        partial = err.partial
        res = _result(compiled, partial, False, str(err)) \
            if partial is not None and len(partial.t) else None
        if raise_on_failure or res is None:
            err.partial = res
            raise
        warnings.warn(f"simulation stopped early: {err}", RuntimeWarning, stacklevel=2)
        return res
    return _result(compiled, out, out.success, out.message)


def _result(compiled, out, success, message) -> Result:
    return Result(compiled, out.t, out.y, out.stats, out.event_times, success, message,
                  out.discrete_states, out.discrete_index)


def _time(name, value) -> float:
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"simulate: {name} must be a number, got {value!r}") from None
    if not math.isfinite(x):
        raise ValueError(f"simulate: {name} must be finite, got {value!r}")
    return x


def _positive(name, value, allow_zero=False, allow_inf=False) -> float:
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"simulate: {name} must be a number, got {value!r}") from None
    if math.isnan(x) or (math.isinf(x) and not allow_inf) or x < 0 or (x == 0 and not allow_zero):
        raise ValueError(f"simulate: {name} must be {'>= 0' if allow_zero else '> 0'}"
                         f"{'' if allow_inf else ' and finite'}, got {value!r}")
    return x


def _output_times(t_eval, n_points, t_start, t_end):
    """The requested output times, checked: nothing is dropped silently."""
    if t_eval is not None and n_points is not None:
        raise ValueError("simulate: give t_eval or n_points, not both")
    if n_points is not None:
        if isinstance(n_points, bool) or not isinstance(n_points, (int, np.integer)) \
                or n_points < 2:
            raise ValueError(f"simulate: n_points must be an integer >= 2, got {n_points!r}")
        return np.linspace(t_start, t_end, int(n_points))
    if t_eval is None:
        return None
    try:
        te = np.asarray(t_eval, dtype=float).ravel()
    except (TypeError, ValueError):
        raise ValueError("simulate: t_eval must be a sequence of numbers") from None
    if te.size == 0:
        raise ValueError("simulate: t_eval is empty")
    if not np.all(np.isfinite(te)):
        raise ValueError(f"simulate: t_eval has non-finite entries at positions "
                         f"{np.flatnonzero(~np.isfinite(te))[:5].tolist()}")
    if np.any(np.diff(te) < 0):
        k = int(np.flatnonzero(np.diff(te) < 0)[0])
        raise ValueError(f"simulate: t_eval must be sorted (t_eval[{k}] = {te[k]} > "
                         f"t_eval[{k + 1}] = {te[k + 1]})")
    outside = (te < t_start) | (te > t_end)
    if outside.any():
        raise ValueError(f"simulate: t_eval has {int(outside.sum())} time(s) outside "
                         f"[t_start, t_end] = [{t_start}, {t_end}], e.g. {te[outside][0]}")
    return te
