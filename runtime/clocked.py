"""A model without continuous states whose discrete variables change at events.

A sampler behind a signal source has nothing to integrate, but its output changes at
every tick: the run goes from time event to time event (clock ticks and the switching
times of relations of time, :meth:`CompiledModel.next_time_event`), settles each one
as an integrated run does (:func:`acausal.runtime.events.iterate_event`), and keeps
the discrete state after it.  Relations that are not linear in time (a Boolean that
says whether a sine is positive) are watched on a grid between time events, of the
output times and at least 1000 intervals over the run: where one is contradicted at
the end of an interval, its crossing is located by bisection (a function of time
alone, z being empty) to within 1e-12 of the time's scale and handled there.  Every
output point is evaluated in the discrete state in force there (results are
right-continuous at an event; without ``t_eval`` each event gives a point before and
a point after it), with its relations taken at the point.
"""
from __future__ import annotations

from types import SimpleNamespace

import numpy as np

__all__ = ["has_discrete_events", "run_between_events"]


def has_discrete_events(compiled) -> bool:
    """True if the model has discrete variables or clocks."""
    w = compiled.whens
    return bool(compiled.discrete.n_held or (w is not None and len(w.clocks)))


def run_between_events(compiled, t_start: float, t_end: float, t_eval=None):
    """The run of a model without states from t_start (already initialized) to t_end;
    returns a record with ``t``, ``point_states`` (the discrete state of each point),
    ``stats`` and, as a SolverOutput has them, ``event_log``, ``event_times`` and
    ``discrete_states`` (the snapshots the log's entries index)."""
    z = np.zeros(0)
    no_roots = np.zeros(compiled.n_roots, dtype=bool)
    snaps, times, kinds, crossings, t = [compiled.discrete_state()], [], [], [], t_start
    grid = _watch_grid(compiled, t_start, t_end, t_eval)
    while t < t_end:
        te = compiled.next_time_event(t)
        stop = t_end if te is None or te > t_end else te
        found = _first_crossing(compiled, t, stop, grid)
        if found is not None:
            tc, crossed = found
            _handle(compiled, tc, crossed)
            kinds.append("state")
            crossings.append(np.flatnonzero(crossed).tolist())
        elif te is None or te > t_end:
            break
        else:
            tc = te
            _handle(compiled, te, no_roots)
            kinds.append("time")
            crossings.append([])
        snaps.append(compiled.discrete_state())
        times.append(tc)
        t = tc
    final = snaps[-1]
    if t_eval is None:
        grid = np.linspace(t_start, t_end, 501)
        points = [(tk, int(np.searchsorted(times, tk, side="right"))) for tk in grid]
        points += [(te, j + side) for j, te in enumerate(times) for side in (0, 1)]
        points.sort()
    else:
        points = [(tk, int(np.searchsorted(times, tk, side="right"))) for tk in t_eval]
    states = []
    try:
        for tk, j in points:
            compiled.set_discrete_state(snaps[j])
            compiled.init_modes(tk, z)          # relations as they hold at the point
            states.append(compiled.discrete_state())
    finally:
        compiled.set_discrete_state(final)
    log = [{"time": te, "kind": kind, "crossed": crossed, "before": j, "after": j + 1}
           for j, (te, kind, crossed) in enumerate(zip(times, kinds, crossings))]
    return SimpleNamespace(
        t=np.array([tk for tk, _ in points], dtype=float), point_states=states,
        event_log=log, event_times=times, discrete_states=snaps,
        stats={"steps": 0, "events": len(times)})


def _handle(compiled, t, crossed) -> None:
    """The event at t; a discrete state that does not settle stops the run."""
    from ..errors import InitializationFailed, SimulationError
    z = np.zeros(0)
    try:
        compiled.handle_event(t, z, z, crossed)
    except InitializationFailed as exc:
        raise SimulationError(str(exc), t, exc.variables) from None


def _watch_grid(compiled, t_start, t_end, t_eval) -> np.ndarray:
    """Where relations that are not linear in time are checked: the output times and at
    least 1000 intervals over the run (none if every relation is a time event)."""
    timed = set(np.asarray(compiled.discrete.time_linear).tolist())
    if all(k in timed for k in range(compiled.discrete.n_rel + compiled.discrete.n_disc)):
        return np.zeros(0)
    grid = np.linspace(t_start, t_end, 1001)
    if t_eval is not None:
        grid = np.union1d(grid, np.asarray(t_eval, dtype=float))
    return grid[(grid > t_start) & (grid <= t_end)]


def _first_crossing(compiled, t, stop, grid):
    """(time, crossed) of the first crossing of an oriented zero-crossing function in
    (t, stop], located by bisection to 1e-12 of the time's scale, or None."""
    if not grid.size:
        return None
    z = np.zeros(0)
    if not stop > t:
        return None
    points = grid[(grid > t) & (grid < stop)]
    points = np.append(points, stop)
    lo = t
    for hi in points:
        r = compiled.roots(hi, z, z)
        if np.all(r >= 0):
            lo = hi
            continue
        tol = 1e-12 * max(1.0, abs(hi))
        while hi - lo > tol:
            mid = 0.5 * (lo + hi)
            if np.all(compiled.roots(mid, z, z) >= 0):
                lo = mid
            else:
                hi = mid
        compiled.resolution = hi - lo
        return hi, compiled.roots(hi, z, z) < 0
    return None
