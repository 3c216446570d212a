"""The public simulation driver: BDF steps, events, output and failure reports.

:func:`integrate` owns everything that is not a BDF step:

* consistent initialization (:mod:`acausal.solvers.initialization`, or the problem's
  own ``reinitialize`` after events, contract item 12);
* state events: after each accepted step the zero-crossing functions are compared with
  their signs at the previous point; a change is located on the BDF interpolant by the
  Illinois variant of regula falsi over all crossing functions at once, as IDA's
  ``IDARootfind`` (Hindmarsh et al. 2005), to a time tolerance of about
  1e-12 relative.  The event is then handled by ``problem.handle_event``, iterated
  while the discrete state changes and new crossings appear, the algebraic variables
  and y' are re-initialized, and the BDF restarts at order 1 as after any
  discontinuity (Brenan, Campbell & Petzold 1996, ch. 5), its first step sized by a
  trial step (IDA's heuristic alone makes it orders of magnitude too small at tight
  tolerances);
* time events (``problem.time_events`` and ``problem.next_time_event``): steps land
  exactly on them, then they are handled like state events with no crossing flagged.
  Only the signs of the zero-crossing functions at step ends are compared (as in
  IDA), so a function that changes sign twice within one step goes unseen; relations
  on time alone (pulses, samplers) should therefore be time events;
* chattering (Zeno) detection: event sequences whose spacing shrinks geometrically
  towards an accumulation point before ``t_end``, or very many events in a tiny
  window, stop the run with an explanation instead of creeping towards the
  accumulation point;
* output: every accepted step (plus the event points before and after), or the
  ``t_eval`` points by dense output;
* stiff restarts: a step that fails right after a restart, at round-off in an
  algebraic variable or in a transient faster than the time resolution, is recovered
  (:mod:`.recovery`: the algebraic components leave the error test; forced backward-Euler
  steps cross the transient), counted in ``stats.relaxed_components`` and
  ``stats.forced_steps``;
* failures: a :class:`SimulationError` naming the time, the variables that dominated
  the weighted error (or the singular block) and carrying the partial output;
* records: every reported event as a dict (``time``, ``kind`` "state" or "time", the
  indices of the zero-crossing functions that crossed, and the indices in
  ``discrete_states`` of the discrete state before and after it), in the output's
  ``event_log`` attribute; ``progress(t)`` (optional) is called after every accepted
  step with the time reached (so a progress display follows simulated time).
"""
from __future__ import annotations

import numpy as np

from .base import (DAEProblem, EventAction, InitializationFailed, SimulationError,
                   SolverOutput, SolverStats)
from .bdf import BDF, StepFailure
from .failures import failure_message
from .initialization import consistent_initial, reinitialize
from .recovery import passage, relax

__all__ = ["integrate"]

_ROOT_RTOL = 1e-12       # event-time tolerance, relative to max(|t|, t_end - t0)
_ZENO_INTERVALS = 10     # geometric shrinking over this many event intervals ...
_ZENO_RATIO = 0.95       # ... each at most this ratio of the one before ...
_ZENO_SPREAD = 1.15      # ... and nearly constant (max/min ratio) means Zeno
_BURST_EVENTS = 50       # this many state events ...
_BURST_WINDOW = 1e-6     # ... within this fraction of the span means chattering
_ECHO_TTOLS = 1e3        # an unchanged event this close (in ttol) to the last is the same


def integrate(problem: DAEProblem, t_span, y0, yp0=None, *, rtol: float = 1e-6,
              atol=1e-8, t_eval=None, max_step: float = np.inf,
              first_step: float | None = None, suppress_alg: bool = False,
              max_steps: int = 500000, initialize: bool = True,
              max_event_iterations: int = 20, max_order: int = 5,
              stald: bool = False, progress=None, step_loop: str = "auto") -> SolverOutput:
    """Integrate the DAE ``problem`` over ``t_span`` with the variable-order BDF.

    Parameters
    ----------
    problem : DAEProblem
        The system (see :mod:`acausal.solvers.base`).
    t_span : (float, float)
        Start and end time, ``t_end > t0``.
    y0, yp0 : array_like
        Initial values and derivatives (``yp0=None``: zeros, to be computed).
    rtol : float
        Relative tolerance.
    atol : float or array_like
        Absolute tolerance (scaled by ``problem.nominal``).
    t_eval : array_like or None
        Output times (sorted, within ``t_span``); None gives every accepted step and
        the points just before and after each event.
    max_step : float
        Largest step size.
    first_step : float or None
        Initial step (None: IDA's heuristic).
    suppress_alg : bool
        Leave algebraic variables out of the local error test.
    max_steps : int
        Limit on accepted steps.
    initialize : bool
        Compute consistent initial values first (else y0, yp0 must be consistent).
    max_event_iterations : int
        Limit on event iterations at one time instant.
    max_order : int
        Highest BDF order (1-5; DASSL's ``maxord``).  Orders 1 and 2 are A-stable and
        damp weakly damped high-frequency modes that orders 3-5 may not.
    stald : bool
        BDF stability limit detection (Hindmarsh's STALD, see
        :mod:`acausal.solvers.stald`): caps the order when the step is limited by
        stability on such a mode rather than by accuracy.
    progress : callable or None
        ``progress(t)`` after every accepted step (it should be cheap: it is on the
        step loop; with the compiled loop, after every return to Python).
    step_loop : {"auto", "c", "python"}
        Where the BDF steps run: "auto" is the compiled loop
        (:mod:`acausal.solvers.cbdf`) when the problem qualifies (a compiled model on
        the C backend, at most 200 unknowns, no delay, no ``stald``)
        and a C compiler works, else the Python loop; "c" and "python" force one.

    Returns
    -------
    SolverOutput
        ``success`` is False only when the problem asked to stop (``EventAction.stop``);
        the message then says why.

    Raises
    ------
    SimulationError
        On step-size underflow, repeated error-test or corrector failures, a singular
        iteration matrix, chattering, ``max_steps`` or a failed re-initialization;
        ``partial`` holds the output up to the failure.
    InitializationFailed
        If no consistent initial values are found.
    """
    run = _Run(problem, t_span, t_eval, rtol, atol, max_step, suppress_alg, max_steps,
               max_event_iterations)
    run.bdf_options = {"max_order": max_order, "stald": stald}
    from .cbdf import choose_step_loop
    run.mode = choose_step_loop(problem, step_loop, stald)
    run.progress = progress
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        return run.go(y0, yp0, first_step, initialize)


class _Run:
    """State of one integration (kept out of :func:`integrate` to keep functions short)."""

    def __init__(self, problem, t_span, t_eval, rtol, atol, max_step, suppress_alg,
                 max_steps, max_event_iterations):
        self.problem = problem
        self.t0, self.tf = float(t_span[0]), float(t_span[1])
        if not self.tf > self.t0:
            raise ValueError("t_span must be increasing: (t0, t_end) with t_end > t0")
        if not (rtol > 0 and np.all(np.asarray(atol) >= 0) and max_step > 0):
            raise ValueError("need rtol > 0, atol >= 0 and max_step > 0")
        self.span = self.tf - self.t0
        self.rtol, self.atol = rtol, atol
        # a problem may limit the step itself (item 14: delays read from the past)
        max_step = min(max_step, float(getattr(problem, "max_step", np.inf)))
        self.max_step, self.suppress_alg = max_step, suppress_alg
        self.max_steps, self.max_event_iterations = max_steps, max_event_iterations
        self.t_eval = None if t_eval is None else np.asarray(t_eval, float)
        self.i_eval = 0
        self.stats = SolverStats()
        self.ts, self.ys, self.yps, self.event_times = [], [], [], []
        self.state_event_times = []
        self.event_log = []
        self.progress = None
        te = sorted({float(x) for x in getattr(problem, "time_events", ()) or ()})
        self.time_events = [x for x in te if self.t0 < x < self.tf]
        self.n_roots = int(getattr(problem, "n_roots", 0) or 0)
        self.oriented = bool(getattr(problem, "oriented_roots", False))
        self.bdf_options = {}
        self.mode = None          # the compiled step loop's mode, None: the Python loop
        # the discrete state of every output point (contract item 13): snapshots taken
        # when it may have changed, and for each point the snapshot it was computed in
        self.keeps_discrete = callable(getattr(problem, "discrete_state", None))
        self.snapshots, self.snapshot_of = [], []
        # the accepted solution (item 15) and values recorded per output point (item 16)
        self.commit = getattr(problem, "commit", None)
        self.point_values = getattr(problem, "point_values", None)
        self.output_point = getattr(problem, "output_point", None)      # item 17
        self.values = []

    # ------------------------------------------------------------------ main loop
    def go(self, y0, yp0, first_step, initialize) -> SolverOutput:
        p = self.problem
        y = np.array(y0, dtype=float)
        yp = np.zeros(p.n) if yp0 is None else np.array(yp0, dtype=float)
        hook = getattr(p, "tolerances", None)          # contract item 18
        if hook is not None:
            hook(self.rtol, self.atol)
        if initialize:
            y, yp = consistent_initial(p, self.t0, y, yp, rtol=self.rtol, atol=self.atol)
        self._snapshot()
        self._emit_point(self.t0, y, yp)
        self._arm_roots(self.t0, y, yp)
        options = dict(rtol=self.rtol, atol=self.atol, max_step=self.max_step,
                       first_step=first_step, suppress_alg=self.suppress_alg,
                       t_stop=self._next_stop(self.t0), stats=self.stats,
                       **self.bdf_options)
        if self.mode is None:
            self.solver = BDF(p, self.t0, y, yp, **options)
            advance = self._advance
        else:
            from .cbdf import CompiledBDF
            self.solver = CompiledBDF(p, self.t0, y, yp, mode=self.mode, **options)
            self.stats.step_loop = "c"
            advance = self._advance_compiled
        tick = self.progress
        while self.solver.t < self.tf:
            stop = advance()
            if stop is not None:
                return self._output(False, stop)
            if tick is not None:
                tick(self.solver.t)
        self._emit_eval_rest()
        return self._output(True, "reached t_end")

    def _next_stop(self, t: float) -> float:
        """The next time event after t (listed or from ``next_time_event``), or t_end."""
        stop = self.tf
        for te in self.time_events:
            if te > t:
                stop = te
                break
        hook = getattr(self.problem, "next_time_event", None)
        if hook is not None:
            te = hook(t)
            if te is not None and t < te < stop:
                stop = float(te)
        return stop

    def _advance(self):
        """One accepted step and whatever happens in it; a message if the run stops."""
        s = self.solver
        if self.stats.steps >= self.max_steps:
            raise self._error(f"maximum number of steps ({self.max_steps}) reached at "
                              f"t={s.t:.10g} before t_end={self.tf:.10g}", s.t, ())
        try:
            s.step()
        except StepFailure as exc:
            then = self._recover(s, exc)
            if then is not False:
                return then
            raise self._step_failure(exc) from None
        return self._accepted(s)

    def _advance_compiled(self):
        """Steps in the compiled loop (:mod:`acausal.solvers.cbdf`) up to the next thing
        that needs Python; that step, if any, then goes on as in :meth:`_advance`."""
        from .cbdf import R_FAIL, R_FULL, R_SPECIAL
        s = self.solver
        if self.stats.steps >= self.max_steps:
            raise self._error(f"maximum number of steps ({self.max_steps}) reached at "
                              f"t={s.t:.10g} before t_end={self.tf:.10g}", s.t, ())
        if self.n_roots:
            self.sign_ref = np.array(self.sign_ref, float)
            self.g_prev = np.array(self.g_prev, float)
        code = s.run(self.max_steps - self.stats.steps, self.t_eval, self.i_eval,
                     getattr(self, "sign_ref", None), getattr(self, "g_prev", None))
        ts, ys, yps = s.points
        if self.t_eval is not None:
            self.i_eval = s.i_eval
            for k in range(len(ts)):       # interpolated in C, in this discrete state
                ys[k] = self._consistent(ts[k], ys[k])
        if len(ts):
            # a block of points as one (k, n) array: _output stacks blocks and rows
            self.ts.extend(ts.tolist())
            self.ys.append(ys)
            self.yps.append(yps)
        if self.keeps_discrete:
            self.snapshot_of.extend([len(self.snapshots) - 1] * len(ts))
        if code == R_FAIL:
            exc = s.failure()
            then = self._recover(s, exc)
            if then is not False:
                return then
            raise self._step_failure(exc)
        if code == R_FULL and s.pending:
            self._emit_step(s.t_prev, s.t, s.y, s.yp)
        if code == R_SPECIAL:
            return self._accepted(s)
        if s.reselect:        # the loop found the choice of states degraded
            self._after_step(s)
        return None

    def _recover(self, s, exc):
        """A failed step right after a stiff restart (:mod:`.recovery`): False if the
        run must fail, else what the driver does after an accepted step (None when the
        BDF only restarted)."""
        if relax(self, s, exc):
            return None
        if passage(self, s, exc):
            return self._accepted(s)
        return False

    def _accepted(self, s):
        """After an accepted step: events, output, the problem's after-step hook."""
        if self.n_roots:
            hit = self._find_crossing()
            if hit is not None:
                return self._state_event(*hit)
        if self.commit is not None:
            self.commit(s.t_prev, s.t, s.interpolate, rtol=self.rtol)
        at_event = s.t < self.tf and s.t == s.t_stop
        self._emit_step(s.t_prev, s.t, s.y, s.yp, before_event=at_event)
        if at_event:
            return self._time_event(s.t)
        self._after_step(s)
        return None

    def _after_step(self, s) -> None:
        """Let the problem change its formulation after an accepted step (dynamic state
        selection: a different choice of states).  The point already satisfies the
        equations both formulations share, and y means the same, so the BDF keeps its
        history (:meth:`BDF.reformulate`) instead of restarting at order 1 as after an
        event (a pendulum going round switches nine times in 3 s; the restarts cost
        ~140 of its ~520 steps at rtol 1e-6)."""
        hook = getattr(self.problem, "after_step", None)
        if hook is not None and hook(s.t, s.y, s.yp):
            s.reformulate()
            self._arm_roots(s.t, s.y, s.yp)

    # ------------------------------------------------------------------ output
    def _emit_point(self, t, y, yp) -> None:
        if self.t_eval is None:
            self._append(t, y, yp)
        else:
            ev = self.t_eval
            while self.i_eval < ev.size and ev[self.i_eval] <= t:
                if ev[self.i_eval] == t:
                    self._append(t, y, yp)
                self.i_eval += 1

    def _emit_step(self, t_lo, t_hi, y_hi, yp_hi, snapshot=None, before_event=False) -> None:
        """Output for the accepted interval (t_lo, t_hi] (computed in ``snapshot``,
        default the current discrete state).  A requested time exactly at an event that
        ends the interval is left for the point after the event (results are
        right-continuous, as a relation ``time >= t_e`` says)."""
        if self.t_eval is None:
            self._append(t_hi, y_hi, yp_hi, snapshot)
            return
        ev, s = self.t_eval, self.solver
        while self.i_eval < ev.size and (ev[self.i_eval] < t_hi or (
                ev[self.i_eval] == t_hi and not before_event)):
            if ev[self.i_eval] >= t_lo:
                t = ev[self.i_eval]
                y, yp = s.interpolate(t)
                self._append(t, self._consistent(t, y), yp, snapshot)
            self.i_eval += 1

    def _consistent(self, t, y):
        """y at an output time between steps, as the problem completes it (item 17)."""
        if self.output_point is None:
            return y
        z = self.output_point(float(t), y, self.rtol)
        if z is None:
            self.stats.interpolated_outputs += 1
            return y
        return z

    def _emit_eval_rest(self) -> None:
        """t_eval points equal to t_end after rounding."""
        if self.t_eval is not None:
            while self.i_eval < self.t_eval.size and self.t_eval[self.i_eval] <= self.tf:
                self._append(self.t_eval[self.i_eval], self.solver.y, self.solver.yp)
                self.i_eval += 1

    def _append(self, t, y, yp, snapshot=None) -> None:
        # the solver hands out fresh arrays for every point, so no copies are needed
        self.ts.append(float(t))
        self.ys.append(y)
        self.yps.append(yp)
        if self.keeps_discrete:
            self.snapshot_of.append(len(self.snapshots) - 1 if snapshot is None else snapshot)
        if self.point_values is not None:
            v = self.point_values(float(t))
            if v is not None:
                self.values.append(v)

    def _snapshot(self) -> None:
        """Record the problem's discrete state (it may have changed at an event)."""
        if self.keeps_discrete:
            state = self.problem.discrete_state()
            if not self.snapshots or not np.array_equal(self.snapshots[-1], state):
                self.snapshots.append(state)

    def _output(self, success: bool, message: str) -> SolverOutput:
        n = self.problem.n
        lin = getattr(getattr(self, "solver", None), "lin", None)
        if self.stats.step_loop == "c":
            self.stats.linear_solver = "sparse" if self.solver.sparse else "dense"
        elif lin is not None and lin.sparse is not None:
            self.stats.linear_solver = "sparse" if lin.sparse else "dense"
        y = np.vstack(self.ys) if self.ys else np.empty((0, n))
        yp = np.vstack(self.yps) if self.yps else np.empty((0, n))
        out = SolverOutput(np.array(self.ts), y, yp, success, message, self.stats,
                           list(self.event_times), list(self.snapshots),
                           list(self.snapshot_of))
        out.event_log = list(self.event_log)
        out.point_values = list(self.values)
        return out

    # ------------------------------------------------------------------ failures
    def _error(self, message, t, variables) -> SimulationError:
        partial = self._output(False, message)
        return SimulationError(message, t=t, variables=list(variables), partial=partial)

    def _step_failure(self, exc: StepFailure) -> SimulationError:
        return self._error(*failure_message(self.problem, getattr(self, "solver", None), exc))

    # ------------------------------------------------------------------ roots
    def _signed_roots(self, t, y, yp) -> np.ndarray:
        return np.asarray(self.problem.roots(t, y, yp), float)

    def _arm_roots(self, t, y, yp) -> None:
        """Reference signs after a (re)start.

        Oriented functions (contract item 13) are >= 0 while the problem's discrete state
        holds, so every one is armed with reference sign +1, also where it is zero.
        Otherwise a function that is exactly zero stays unarmed until a step ends where
        it is not.  A function that has just crossed sits a little beyond zero (the event
        is placed at the far end of the final bracket), so if the new dynamics take it
        straight back, that is a genuine crossing and is reported as such, as a
        relation changing back would be in Modelica semantics.
        """
        if not self.n_roots:
            return
        arm = getattr(self.problem, "arm", None)
        if arm is not None:
            arm(t, y, yp, self._ttol(t))
        g0 = self._signed_roots(t, y, yp)
        self.sign_ref = np.ones_like(g0) if self.oriented else np.sign(g0)
        self.g_prev = g0

    def _ttol(self, t: float) -> float:
        return max(_ROOT_RTOL * max(abs(t), self.span), 4 * np.finfo(float).eps * abs(t))

    def _find_crossing(self):
        """(t_event, crossed mask) of the first crossing in the last step, or None."""
        s = self.solver
        g = self._signed_roots(s.t, s.y, s.yp)
        armed = self.sign_ref != 0
        shi = g * self.sign_ref
        if not np.any(armed & (shi <= 0)):
            self._rearm(g)
            return None
        slo = np.where(armed, np.maximum(self.g_prev * self.sign_ref, 0.0), 1.0)
        return self._illinois(s.t_prev, slo, s.t, shi, armed)

    def _rearm(self, g) -> None:
        unarmed = self.sign_ref == 0
        if np.any(unarmed):
            self.sign_ref[unarmed] = np.sign(g[unarmed])
        self.g_prev = g

    def _illinois(self, tlo, slo, thi, shi, armed):
        """Multi-function Illinois on the interpolant (IDA's IDARootfind)."""
        s, ref = self.solver, self.sign_ref
        ttol = self._ttol(thi)
        alph, side, sideprev = 1.0, 0, -1
        while thi - tlo > ttol:
            crossed = armed & (shi <= 0)
            frac = np.where(crossed, -shi / np.maximum(alph * slo - shi, 1e-300), -1.0)
            tmid = thi - (thi - tlo) * frac.max()
            tmid = min(max(tmid, tlo + 0.5 * ttol), thi - 0.5 * ttol)
            smid = self._signed_roots(tmid, *s.interpolate(tmid)) * ref
            sideprev = side
            if np.any(armed & (smid <= 0)):
                thi, shi, side = tmid, smid, 1
            else:
                tlo, slo, side = tmid, np.where(armed, smid, 1.0), 2
            alph = (alph * (0.5 if side == 1 else 2.0)) if side == sideprev else 1.0
        return thi, armed & (shi <= 0)

    # ------------------------------------------------------------------ events
    def _state_event(self, t_e, crossed):
        s = self.solver
        y, yp = s.interpolate(t_e)
        t_prev = s.t_prev
        if self.commit is not None:          # the solution up to the event, old modes
            self.commit(t_prev, t_e, s.interpolate, rtol=self.rtol)
        before = len(self.snapshots) - 1
        y_new, yp_new, action, changed = self._iterate_event(t_e, y, yp, crossed)
        # A relation flipping straight back after the previous event (a ball leaving
        # the floor, a heater's threshold left behind) changes nothing: it is the same
        # instant, handled, but not reported as another event.
        echo = (not changed and not action.stop and bool(self.event_times)
                and t_e - self.event_times[-1] <= _ECHO_TTOLS * self._ttol(t_e))
        if not (echo and self.t_eval is None):
            self._emit_step(t_prev, t_e, y, yp, snapshot=before, before_event=True)
        if changed:
            # only events that change something can chatter
            self.state_event_times.append(t_e)
            self._check_zeno(t_e)
        entry = {"time": t_e, "kind": "state", "crossed": np.flatnonzero(crossed).tolist(),
                 "before": before}
        return self._finish_event(t_e, y_new, yp_new, action, record=not echo, entry=entry)

    def _time_event(self, t_e):
        before = len(self.snapshots) - 1
        y, yp, action, _ = self._iterate_event(t_e, self.solver.y, self.solver.yp,
                                               np.zeros(self.n_roots, bool))
        entry = {"time": t_e, "kind": "time", "crossed": [], "before": before}
        return self._finish_event(t_e, y, yp, action, entry=entry)

    def _finish_event(self, t_e, y, yp, action, record=True, entry=None):
        """Record the event, then stop or restart the BDF at order 1."""
        if record:
            self.stats.events += 1
            self.event_times.append(t_e)
            if entry is not None:
                entry["after"] = len(self.snapshots) - 1
                self.event_log.append(entry)
            if self.t_eval is None:
                self._append(t_e, y, yp)
        if self.t_eval is not None:          # requested times at the event: after it
            while self.i_eval < self.t_eval.size and self.t_eval[self.i_eval] <= t_e:
                self._append(self.t_eval[self.i_eval], y, yp)
                self.i_eval += 1
        if action.stop:
            return action.message or f"stopped by the model at t={t_e:.10g}"
        self.solver.restart(t_e, y, yp, t_stop=self._next_stop(t_e), probe=True)
        self._arm_roots(t_e, y, yp)
        return None

    def _iterate_event(self, t, y, yp, crossed):
        p = self.problem
        g_before = self._signed_roots(t, y, yp) if self.n_roots else None
        any_change = False
        for _ in range(self.max_event_iterations):
            try:
                action = p.handle_event(t, y, yp, crossed) or EventAction()
            except InitializationFailed as exc:     # no consistent discrete state
                raise self._error(str(exc), t, exc.variables) from None
            changed = action.changed or action.y is not None
            any_change |= changed
            if action.y is not None:
                y = np.array(action.y, dtype=float)
            if changed:
                y, yp = self._reinit(t, y, yp)
                self._snapshot()
            # a problem with oriented roots does its own event iteration (item 13)
            if action.stop or not changed or not self.n_roots or self.oriented:
                return y, yp, action, any_change
            g_after = self._signed_roots(t, y, yp)
            crossed = (np.sign(g_after) != np.sign(g_before)) & (g_before != 0)
            if not crossed.any():
                return y, yp, action, any_change
            g_before = g_after
        raise self._error(f"event iteration at t={t:.10g} did not settle after "
                          f"{self.max_event_iterations} iterations (the discrete "
                          f"state keeps changing)", t, ())

    def _reinit(self, t, y, yp):
        own = getattr(self.problem, "reinitialize", None)
        try:
            if own is not None:
                return own(t, y, yp, rtol=self.rtol, atol=self.atol)
            return reinitialize(self.problem, t, y, yp, rtol=self.rtol, atol=self.atol)
        except InitializationFailed as exc:
            raise self._error(f"re-initialization after the event at t={t:.10g} "
                              f"failed: {exc}", t, exc.variables) from None

    def _check_zeno(self, t_e) -> None:
        """Stop on chattering: a burst of events, or a geometric accumulation."""
        times = self.state_event_times
        if len(times) >= _BURST_EVENTS and \
                times[-1] - times[-_BURST_EVENTS] <= _BURST_WINDOW * self.span:
            raise self._error(
                f"chattering: {_BURST_EVENTS} state events within "
                f"{times[-1] - times[-_BURST_EVENTS]:.3g} s at t={t_e:.10g}; the model "
                f"switches back and forth (a sliding mode); add hysteresis or a "
                f"sliding-mode formulation", t_e, ())
        m = _ZENO_INTERVALS
        if len(times) < m + 1:
            return
        d = np.diff(times[-(m + 1):])
        if np.any(d <= 0):
            return
        r = d[1:] / d[:-1]
        if r.max() > _ZENO_RATIO or r.max() > _ZENO_SPREAD * r.min():
            return
        ratio = float(np.exp(np.mean(np.log(r))))
        t_acc = t_e + d[-1] * ratio / (1.0 - ratio)
        if t_acc < self.tf:
            raise self._error(
                f"chattering (Zeno behaviour): the last {m + 1} state events are "
                f"spaced ever closer (ratio {ratio:.3f}) and accumulate at "
                f"t≈{t_acc:.6g}, before t_end={self.tf:.6g}; the model needs a "
                f"regularization there (e.g. a resting mode or hysteresis)", t_e, ())
