"""A model without continuous states whose discrete variables change at events.

A sampler behind a signal source has nothing to integrate, but its output changes at
every tick: the run goes from time event to time event (clock ticks and the switching
times of relations of time, :meth:`CompiledModel.next_time_event`), settles each one
as an integrated run does (:func:`acausal.runtime.events.iterate_event`), and keeps
the discrete state after it.  Every output point is evaluated in the discrete state in
force there (results are right-continuous at an event; without ``t_eval`` each event
gives a point before and a point after it), with its relations taken at the point.
Relations that are not linear in time switch only at the output points: with no
states there is no integrator to locate their crossings.
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
    snaps, times, t = [compiled.discrete_state()], [], t_start
    while True:
        te = compiled.next_time_event(t)
        if te is None or te > t_end:
            break
        compiled.handle_event(te, z, z, no_roots)
        snaps.append(compiled.discrete_state())
        times.append(te)
        t = te
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
    log = [{"time": te, "kind": "time", "crossed": [], "before": j, "after": j + 1}
           for j, te in enumerate(times)]
    return SimpleNamespace(
        t=np.array([tk for tk, _ in points], dtype=float), point_states=states,
        event_log=log, event_times=times, discrete_states=snaps,
        stats={"steps": 0, "events": len(times)})
