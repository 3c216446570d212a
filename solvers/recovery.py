"""Recovery from a step that fails right after a restart at a stiff event
(:mod:`acausal.solvers.driver`).

After an ideal switch opens or closes, the new mode can be arbitrarily stiff: a diode's
``Goff = 1e-9`` or a switch's ``Ron = 1e-9`` puts time constants of 1e-15 s into a
network whose other time constants are milliseconds.  Two things then stop a BDF whose
tolerance is tight, neither of them a property of the solution:

* **round-off in an algebraic variable**: an algebraic unknown that the states determine
  through a factor ``1/Goff = 1e9`` carries their round-off times 1e9, which no step can
  bring under a tolerance of 1e-11.  :func:`relax` takes the algebraic components out of
  the error test (they are judged through the states that determine them, as the
  ``self_scaled`` ones of contract item 6 are, and as IDA's ``suppressalg`` option does)
  and restarts at order 1 from the last accepted point.  It also answers a run that does
  not fail but crawls on such an unknown (the BDF's ``"crawl"``, :mod:`.bdf`) at steps
  below :data:`PASSAGE_SPAN` of the time scale (a pressure-compensated valve whose
  compensator pressure, with a high gain on the states, holds the steps at 2e-6 of the
  time scale near zero flow needs them: taken out of the test it lets a relation on it
  chatter);
* **a transient faster than the time resolution**: after a switch closes across charged
  capacitors through ``Ron = 1e-9`` the charge moves in ~1e-15 s, while at t = 2e-4 the
  smallest step double precision can represent is ~1e-19 s, and the first step an error
  test at rtol 1e-8 accepts is smaller still.  :func:`passage` crosses it with
  backward-Euler steps accepted without the error test, from a few time resolutions and
  doubling, until the test would pass by itself.  Backward Euler is L-stable: a decaying
  mode is damped however large h/tau, and linear invariants (the charge on a node, a
  momentum) are kept exactly, so it lands on the slow solution the transient leads to;
  what it does not resolve is the transient's shape inside a few time resolutions.  It
  applies from the first step after a restart at an event on (and goes on while steps
  the error test accepts alternate with failing ones in the transient), it stops (and
  the run fails as it would have) after :data:`PASSAGE_STEPS` forced steps or where a forced
  step would exceed :data:`PASSAGE_SPAN` of the time scale, and the forced steps are
  counted (``stats.forced_steps``).  A passage belongs to the restart: a step that fails
  later than four :data:`PASSAGE_SPAN` after it is not forced.
"""
from __future__ import annotations

import numpy as np

from .bdf import BDF, StepFailure

__all__ = ["PASSAGE_SPAN", "PASSAGE_STEPS", "passage", "relax"]

PASSAGE_STEPS = 64      # forced steps in one passage at most
PASSAGE_SPAN = 1e-6     # and none longer than this fraction of max(|t|, the interval)


def relax(run, s, exc: StepFailure) -> bool:
    """Take the algebraic components out of the error test and restart (module
    docstring), where the step failed at a small step size after an event and the
    largest weighted error is an algebraic component's, or where the steps crawl on
    algebraic components alone (kind ``"crawl"``); False where that does not apply
    (before any event a failing algebraic component says the structure the compiler
    found does not hold there, which the run must say, not hide)."""
    if exc.kind not in ("step_size", "error_test", "crawl") or not run.event_times:
        return False     # only a mode an event switched to: not a structure that fails
    if exc.kind == "crawl" and exc.h > PASSAGE_SPAN * max(abs(exc.t), run.span):
        return False     # steps the time scale resolves: the unknowns need them
    alg = np.asarray(s.alg, bool)
    free = alg & ~np.asarray(s.self_scaled, bool)
    if not free.any():
        return False
    w = exc.weighted
    if w is not None:
        w = np.nan_to_num(np.abs(np.asarray(w, float)), nan=np.inf)
        if w.size != alg.size or not w.any() or not alg[int(np.argmax(w))]:
            return False
    new = free if s.relaxed is None else free & ~s.relaxed
    s.relax(free)
    run.stats.relaxed_components = int(np.count_nonzero(s.relaxed))
    if run.stats.relaxed_at is None:
        run.stats.relaxed_at = float(s.t)
    run.stats.relaxed_names += [run.problem.names[i] for i in np.flatnonzero(new)]
    s.restart(s.t, s.y, s.yp, t_stop=run._next_stop(s.t), probe=True)
    run._arm_roots(s.t, s.y, s.yp)
    return True


def passage(run, s, exc: StepFailure) -> bool:
    """One forced backward-Euler step (module docstring), twice as long as the previous
    forced one (the first a few time resolutions); False where a passage does not apply
    or has gone as far as it may."""
    if exc.kind not in ("step_size", "error_test") or not (s.nst == 0 or s.forced) \
            or not run.event_times:
        return False     # a restart at an event only, as relax()
    scale = PASSAGE_SPAN * max(abs(s.t), run.span)
    if s.forced >= PASSAGE_STEPS or s.t - s.t_restart > 4.0 * scale:
        return False
    hmin = s._hmin()
    h = max(2.0 * s.forced_h, s.hused, 4.0 * hmin)
    if h > scale:
        return False
    if s.nst == 0:
        s._shrink(h / s.hh)      # the first step's phi[1] = h y' follows h
    else:
        s.hh = h
    try:
        BDF.step(s, forced=True)
    except StepFailure:
        return False
    s.forced_h = h
    run.stats.forced_steps += 1
    return True
