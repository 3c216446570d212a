"""Zero crossings and events of a run of :func:`acausal.solvers.driver.integrate`: the
reference signs of the problem's oriented root functions, a crossing located on the
step's interpolant by the Illinois method to a time tolerance, the event handled by the
problem (solver contract item 8) and iterated until its discrete state settles, the
state re-initialized, and Zeno and chattering behaviour detected and refused in words.

:class:`EventHandling` is the part of the driver's run (``_Run``) that does this; it
reads and writes the run's state (the solver, the problem, the output lists)."""
from __future__ import annotations

import numpy as np

from .base import EventAction, InitializationFailed, root_label
from .initialization import reinitialize

__all__ = ["EventHandling"]

_ROOT_RTOL = 1e-12       # event-time tolerance, relative to max(|t|, t_end - t0)
_ZENO_INTERVALS = 10     # geometric shrinking over this many event intervals ...
_ZENO_RATIO = 0.95       # ... each at most this ratio of the one before ...
_ZENO_SPREAD = 1.15      # ... and nearly constant (max/min ratio) means Zeno
_BURST_EVENTS = 50       # this many state events ...
_BURST_WINDOW = 1e-6     # ... within this fraction of the span means chattering
_ECHO_TTOLS = 1e3        # an unchanged event this close (in ttol) to the last is the same


class EventHandling:
    """Zero crossings and events of a run (see the module docstring)."""

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

    def _interpolated(self, t):
        """y, y' at ``t`` inside the last step: the interpolant, its algebraic
        unknowns solved from the interpolated states where the error test leaves them
        out (their interpolant is not bounded: solver contract item 17), as a crossing
        of a function of them is located on their values, not on their interpolant."""
        s = self.solver
        y, yp = s.interpolate(t)
        if self.output_point is not None and s.self_scaled.any():
            z = self.output_point(float(t), y, self.rtol, every=True)
            if z is not None:
                y = z
        return y, yp

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
            smid = self._signed_roots(tmid, *self._interpolated(tmid)) * ref
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
        y, yp = self._interpolated(t_e)
        t_prev = s.t_prev
        if self.commit is not None:          # the solution up to the event, old modes
            self.commit(t_prev, t_e, s.interpolate, rtol=self.rtol)
        before = len(self.snapshots) - 1
        if self.t_eval is not None:
            # the requested times before the event, completed (output_point) in the
            # discrete state before it, which the event iteration is about to change
            self._emit_step(t_prev, t_e, y, yp, snapshot=before, before_event=True)
        y_new, yp_new, action, changed = self._iterate_event(t_e, y, yp, crossed)
        # A relation flipping straight back after the previous event (a ball leaving
        # the floor, a heater's threshold left behind) changes nothing: it is the same
        # instant, handled, but not reported as another event.
        echo = (not changed and not action.stop and bool(self.event_times)
                and t_e - self.event_times[-1] <= _ECHO_TTOLS * self._ttol(t_e))
        if self.t_eval is None and not echo:
            self._emit_step(t_prev, t_e, y, yp, snapshot=before, before_event=True)
        if changed:
            # only events that change something can chatter
            self.state_event_times.append(t_e)
            self.state_event_roots.append(np.flatnonzero(crossed).tolist())
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

    def _chattering_relations(self, n_events: int) -> str:
        """The relations that crossed in the last ``n_events`` state events, the most
        frequent first (at most three), in the model's words."""
        counts: dict = {}
        for roots in self.state_event_roots[-n_events:]:
            for k in roots:
                counts[k] = counts.get(k, 0) + 1
        if not counts:
            return ""
        ranked = sorted(counts, key=lambda k: (-counts[k], k))[:3]
        return "; relations switching: " + "; ".join(
            f"{root_label(self.problem, k)} ({counts[k]} times)" for k in ranked)

    def _check_zeno(self, t_e) -> None:
        """Stop on chattering: a burst of events, or a geometric accumulation."""
        times = self.state_event_times
        if len(times) >= _BURST_EVENTS and \
                times[-1] - times[-_BURST_EVENTS] <= _BURST_WINDOW * self.span:
            raise self._error(
                f"chattering: {_BURST_EVENTS} state events within "
                f"{times[-1] - times[-_BURST_EVENTS]:.3g} s at t={t_e:.10g}"
                f"{self._chattering_relations(_BURST_EVENTS)}; the model "
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
                f"t≈{t_acc:.6g}, before t_end={self.tf:.6g}"
                f"{self._chattering_relations(m + 1)}; the model needs a "
                f"regularization there (e.g. a resting mode or hysteresis)", t_e, ())
