"""compile() and simulate(): the two calls a user makes."""
from __future__ import annotations

import warnings

import numpy as np

from .compiler.initial import solve_initial
from .compiler.model import CompiledModel
from .compiler.pipeline import compile_model
from .components.component import Component
from .result import Result

from .solvers.base import SimulationError

__all__ = ["compile", "simulate", "initial_values"]


def compile(model: Component) -> CompiledModel:  # noqa: A001  (the public name is compile)
    """Flatten, reduce and generate code for a model instance; see ``compiled.report``."""
    return compile_model(model)


def initial_values(compiled: CompiledModel, t0: float = 0.0) -> np.ndarray:
    """Consistent y(t0): the model's equations plus its initial conditions (compiler.initial)."""
    y = compiled.start.copy()
    compiled.init_modes(t0, y)
    if compiled.dynamic is not None:
        compiled.dynamic.switches = []      # the log is per simulation
        compiled.reselect_states(t0, y, hysteresis=1.0)
    y = solve_initial(compiled, compiled.initial_conditions, t0, y)
    compiled.init_modes(t0, y)
    for _ in range(3):
        # a relation that sits exactly at zero (sign(v) with v(0) = 0) takes the value it
        # has just after t0; the initial values are then recomputed in that mode
        before = compiled.m.copy()
        compiled.settle_modes(t0, y)
        if np.array_equal(before, compiled.m):
            break
        y = solve_initial(compiled, compiled.initial_conditions, t0, y)
    return y


def simulate(model, t_end: float, *, t_start: float = 0.0, rtol: float = 1e-6,
             atol: float | None = None, t_eval=None, n_points: int | None = None,
             max_step: float = np.inf, parameters: dict | None = None,
             max_order: int = 5, raise_on_failure: bool = False) -> Result:
    """Simulate a model (a Component, or a CompiledModel) from t_start to t_end.

    ``rtol``/``atol``: error tolerances (atol scaled by each variable's nominal value;
    default atol = rtol).  ``t_eval`` or ``n_points``: output times (default: every
    accepted step).  ``parameters``: {"R1.R": 5.0} changes parameter values without
    recompiling.  A run that fails returns what it computed with ``success=False`` and
    the reason in ``message`` (and warns), or raises SimulationError if
    ``raise_on_failure``.  ``max_order`` caps the BDF order (DASSL's maxord: 2 helps on
    weakly damped high-frequency modes that only need to stay bounded).
    """
    compiled = model if isinstance(model, CompiledModel) else compile(model)
    if parameters:
        compiled.set_parameters(parameters)
    if n_points is not None and t_eval is None:
        t_eval = np.linspace(t_start, t_end, n_points)
    y0 = initial_values(compiled, t_start)
    if compiled.n == 0:   # nothing to integrate: every variable is an explicit function of time
        t = np.asarray(t_eval if t_eval is not None else np.linspace(t_start, t_end, 501))
        return Result(compiled, t, np.zeros((len(t), 0)), {"steps": 0}, [], True,
                      "no states: evaluated explicitly")
    yp0 = np.zeros_like(y0)
    yp0[compiled.state_index] = compiled.state_derivatives(t_start, y0)
    atol = rtol if atol is None else atol
    compiled.time_events = compiled.scan_time_events(t_start, t_end)
    from .solvers import integrate
    try:
        out = integrate(compiled, (t_start, t_end), y0, yp0, rtol=rtol, atol=atol,
                        t_eval=t_eval, max_step=max_step, max_order=max_order)
    except SimulationError as err:
        partial = err.partial
        res = Result(compiled, partial.t, partial.y, partial.stats,
                     getattr(partial, "event_times", []), False, str(err)) \
            if partial is not None and len(partial.t) else None
        if raise_on_failure or res is None:
            err.partial = res
            raise
        warnings.warn(f"simulation stopped early: {err}", RuntimeWarning, stacklevel=2)
        return res
    return Result(compiled, out.t, out.y, out.stats, out.event_times, out.success, out.message)
