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

from .base import DAEProblem, SimulationError, SolverOutput, SolverStats
from .bdf import BDF, StepFailure
from .cbdf import R_FAIL, R_FULL, R_SPECIAL, CompiledBDF, choose_step_loop
from .crossings import EventHandling
from .failures import failure_message
from .initialization import consistent_initial
from .recovery import passage, relax

__all__ = ["integrate", "NONFINITE"]

NONFINITE = ("stop", "warn")     # what a NaN or inf at an output point does
_SINK_BLOCK = 4096               # output points held before they go to a sink



def integrate(problem: DAEProblem, t_span, y0, yp0=None, *, rtol: float = 1e-6,
              atol=1e-8, t_eval=None, max_step: float = np.inf,
              first_step: float | None = None, suppress_alg: bool = False,
              max_steps: int = 500000, initialize: bool = True,
              max_event_iterations: int = 20, max_order: int = 5,
              stald: bool = False, progress=None, step_loop: str = "auto",
              nonfinite: str = "stop", sink=None, error_test: str | None = None
              ) -> SolverOutput:
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
    error_test : {"all", "states"} or None
        What the local error test covers (:mod:`acausal.solvers.bdf`); None: the
        problem's ``error_test`` (contract item 6), else "all".  ``stats.error_test``
        says which ran.
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
    nonfinite : {"stop", "warn"}
        A NaN or inf at an output point -- in y, or in what the problem computes from it
        (``problem.check_point``, contract item 19) -- ends the run as a failure naming
        it ("stop"), or is said in the output's ``nonfinite`` (the first such point)
        while the run goes on ("warn").
    sink : optional
        Where the output points go as the run makes them, in blocks, instead of the
        output (a file: ``simulate(..., store=)``): ``sink.add(t, y, index, values,
        snapshots)`` with the points' times, y (a row each), the discrete state of
        each (``snapshots[index[k]]``) and the values recorded with each (item 16);
        y' is not kept.  The output then holds no points (``points`` counts them).

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
    if nonfinite not in NONFINITE:
        raise ValueError(f"nonfinite must be one of {', '.join(map(repr, NONFINITE))}, "
                         f"got {nonfinite!r}")
    run = _Run(problem, t_span, t_eval, rtol, atol, max_step, suppress_alg, max_steps,
               max_event_iterations)
    run.nonfinite = nonfinite
    run.sink = sink
    run.bdf_options = {"max_order": max_order, "stald": stald,
                       "error_test": error_test or getattr(problem, "error_test", "all")}
    run.mode = choose_step_loop(problem, step_loop, stald)
    run.progress = progress
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        return run.go(y0, yp0, first_step, initialize)


def _finite_sum(y) -> bool:
    """Whether y is finite, from its sum (NaN and inf propagate; an overflow of a
    finite sum only sends the caller to the exact test)."""
    s = float(np.add.reduce(y, axis=None)) if len(y) else 0.0
    return s - s == 0.0


class _Run(EventHandling):
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
        self.state_event_times, self.state_event_roots = [], []
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
        self.check_point = getattr(problem, "check_point", None)        # item 19
        self.nonfinite, self.nonfinite_seen = "stop", None
        self.sink, self.flushed = None, 0     # where the points go, and how many went
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
            self.solver = CompiledBDF(p, self.t0, y, yp, mode=self.mode, **options)
            self.stats.step_loop = "c"
            advance = self._advance_compiled
        self.stats.error_test = self.solver.error_test
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
        bad = self._nonfinite_block(ts, ys)
        if bad is not None:                # the points before it are kept
            k, bad = bad
            self._keep_block(ts[:k], ys[:k], yps[:k])
            raise self._error(*bad)
        self._keep_block(ts, ys, yps)
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

    def _keep_block(self, ts, ys, yps) -> None:
        """The output points of a return of the compiled loop, in this discrete state."""
        if len(ts):
            # a block of points as one (k, n) array: _output stacks blocks and rows
            self.ts.extend(ts.tolist())
            self.ys.append(ys)
            if self.sink is None:
                self.yps.append(yps)
        if self.keeps_discrete:
            self.snapshot_of.extend([len(self.snapshots) - 1] * len(ts))
        if self.sink is not None and len(self.ts) >= _SINK_BLOCK:
            self._flush()

    def _flush(self) -> None:
        """Hand the points held to the sink (``integrate(..., sink=)``) and let them go."""
        if self.ts:
            self.sink.add(np.array(self.ts), np.vstack(self.ys), self.snapshot_of,
                          self.values, self.snapshots)
            self.flushed += len(self.ts)
            self.ts, self.ys, self.yps, self.snapshot_of, self.values = [], [], [], [], []

    def _recover(self, s, exc):
        """A failed step right after a stiff restart (:mod:`.recovery`): False if the
        run must fail, else what the driver does after an accepted step (None when the
        BDF only restarted)."""
        if relax(self, s, exc):
            return None
        if exc.kind == "crawl":
            return None      # no recovery applies: the steps go on as they were
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
        z = self.output_point(float(t), y, self.rtol,
                              every=bool(self.solver.self_scaled.any()))
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

    def _nonfinite(self, t, y, snapshot=None):
        """None, or (message, t, variables) for a NaN or inf at the output point (t, y):
        in y itself, or in what the problem computes from it (item 19; at the first
        point all of it).  With ``nonfinite="warn"`` the first is kept for the output,
        and None returned."""
        what, variables = None, []
        check = self.check_point
        first = not self.ts and not self.flushed
        if (check is None or not (getattr(check, "every_point", True) or first)) \
                and _finite_sum(y):
            return None                   # the common case, in a microsecond
        if not np.all(np.isfinite(y)):
            variables = [self.problem.names[i] for i in np.flatnonzero(~np.isfinite(y))]
            what = (f"{', '.join(variables[:3])}{' ...' if len(variables) > 3 else ''} "
                    f"not finite at t = {t:.10g}")
        elif self.check_point is not None:
            m = None
            if snapshot is not None and self.keeps_discrete:
                m = self.snapshots[snapshot]
            what = self.check_point(float(t), y, m, every=first)
        if what is None:
            return None
        message = f"a value is not finite at an output point: {what}"
        if self.nonfinite == "warn":
            if self.nonfinite_seen is None:
                self.nonfinite_seen = message
            return None
        return message, float(t), variables

    def _nonfinite_block(self, ts, ys):
        """(k, (message, t, variables)) for the first output point of a block at which
        :meth:`_nonfinite` stops the run, or None (y is tested for the whole block at
        once; the problem's own check, where it has one, point by point)."""
        if not len(ts):
            return None
        if self.check_point is None or not getattr(self.check_point, "every_point", True):
            finite = np.isfinite(ys).all(axis=1)
            if finite.all():
                return None
            k = int(np.argmin(finite))
            bad = self._nonfinite(ts[k], ys[k])
            return None if bad is None else (k, bad)
        for k in range(len(ts)):
            bad = self._nonfinite(ts[k], ys[k])
            if bad is not None:
                return k, bad
        return None

    def _append(self, t, y, yp, snapshot=None) -> None:
        bad = self._nonfinite(t, y, snapshot)
        if bad is not None:
            raise self._error(*bad)
        # the solver hands out fresh arrays for every point, so no copies are needed
        self.ts.append(float(t))
        self.ys.append(y)
        if self.sink is None:
            self.yps.append(yp)
        if self.keeps_discrete:
            self.snapshot_of.append(len(self.snapshots) - 1 if snapshot is None else snapshot)
        if self.point_values is not None:
            v = self.point_values(float(t))
            if v is not None:
                self.values.append(v)
        if self.sink is not None and len(self.ts) >= _SINK_BLOCK:
            self._flush()

    def _snapshot(self) -> None:
        """Record the problem's discrete state (it may have changed at an event)."""
        if self.keeps_discrete:
            state = self.problem.discrete_state()
            if not self.snapshots or not np.array_equal(self.snapshots[-1], state):
                self.snapshots.append(state)

    def _output(self, success: bool, message: str) -> SolverOutput:
        n = self.problem.n
        if self.sink is not None:     # every point went there; the output holds none
            self._flush()
        lin = getattr(getattr(self, "solver", None), "lin", None)
        if self.stats.step_loop == "c":
            self.stats.linear_solver = "sparse" if self.solver.sparse else "dense"
            self.stats.lu = "compiled"
        elif lin is not None and lin.sparse is not None:
            self.stats.linear_solver = "sparse" if lin.sparse else "dense"
            self.stats.lu = lin.kind
        y = np.vstack(self.ys) if self.ys else np.empty((0, n))
        yp = np.vstack(self.yps) if self.yps else np.empty((0, n))
        out = SolverOutput(np.array(self.ts), y, yp, success, message, self.stats,
                           list(self.event_times), list(self.snapshots),
                           list(self.snapshot_of))
        out.event_log = list(self.event_log)
        out.point_values = list(self.values)
        out.nonfinite = self.nonfinite_seen
        out.points = self.flushed + len(self.ts)
        return out

    # ------------------------------------------------------------------ failures
    def _error(self, message, t, variables) -> SimulationError:
        partial = self._output(False, message)
        return SimulationError(message, t=t, variables=list(variables), partial=partial)

    def _step_failure(self, exc: StepFailure) -> SimulationError:
        return self._error(*failure_message(self.problem, getattr(self, "solver", None), exc))
