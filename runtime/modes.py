"""The discrete state between events: relation values and frozen floor values.

Modelica semantics (Modelica Language Specification 3.6, sec. 8.5): a relation in an
if-expression keeps the value it had at the last event while the integrator steps; it
changes only at an event, located where its zero-crossing function ``g = lhs - rhs``
crosses zero.  The same holds for ``floor(u)`` (:mod:`acausal.compiler.frontend.discrete`), held at
an integer ``n`` until ``u`` leaves ``[n, n+1)``.

Each relation is judged on its *own* scale, never on another one's: its value is "at zero"
when ``|g| <= ZERO_RTOL (|lhs| + |rhs|) + ZERO_NOMINAL nominal``, with ``nominal`` the
largest nominal value of the variables it reads.  A spool position of 1e-3 m next to
pressures of 1e7 Pa is judged on millimetres.

The functions handed to the integrator are *oriented*: for relation k

    r_k = s_k g_k + h_k,     s_k = +1 if the frozen value holds for g > 0, else -1,

so ``r_k >= 0`` exactly while the frozen value agrees with the sign of g, up to ``h_k``,
the zero tolerance above evaluated where r is (a relation's scale near its crossing is
not the one it had far from it).  ``h_k > 0`` where the frozen value holds on a closed
side (``x >= 0`` holding, ``x > 0`` not holding): a value sitting at exactly zero is no
event, leaving it by more than the tolerance is.  ``h_k < 0`` on an open side (``x > 0``
holding): the switch comes when x gets within the tolerance of zero, as it must for a
value that only touches zero (``p -> 1`` under ``p < 1`` with ``p' = sqrt(1 - p)``).  The
integrator looks for ``r_k`` becoming negative.  A relation that sits at zero when it is
armed therefore still watches the side it is frozen on: if the solution leaves zero to
the other side, that is an event (a spool that starts at exactly 0 and then moves).  For
a floor value ``n``: ``u - n + h`` and ``n + 1 - u + h``.

At an event the relations that crossed take the value they have just after it: the sign
of g where it is clearly non-zero, else the sign of its rate dg/dt along the solution
(the side the dynamics choose; a rate below the item's tolerance per unit of time is
round-off), else the value of the relation at exactly zero.

Chattering on round-off.  A relation whose both sides agree where it switches (a drain
current that is 0 on both sides of vds = 0) may sit at zero as the solution converges
there: its value then changes sign with the solver's noise, an event each time.  The
solver does not know a variable better than its absolute tolerance, so a relation that
switches back within ``_CHATTER_WINDOW`` event resolutions of its last switch gets a
hysteresis ``h_k`` (first ``_FIRST_HYSTERESIS`` atol x its nominal, doubled at each such
switch, at most atol x nominal): r_k = s_k g_k + side tolerance + h_k, so it switches
again only when g leaves zero by more than h_k on the other side.  A relation that
switches after a quiet spell loses its hysteresis.  A genuine sliding mode still
chatters, on the scale of atol, and the driver stops it as before.
"""
from __future__ import annotations

import math

import numpy as np

from .diagnostics import DOMAIN_ERRORS

__all__ = ["DiscreteState", "ZERO_RTOL", "ZERO_NOMINAL"]

ZERO_RTOL = 1e-10        # at zero: within this fraction of the relation's |lhs| + |rhs| ...
ZERO_NOMINAL = 1e-12     # ... plus this fraction of the nominal of the variables it reads
_CHATTER_WINDOW = 1e3    # a switch back within this many event resolutions is chattering
_FIRST_HYSTERESIS = 1e-3  # a chattering relation's hysteresis starts at this of atol ...

_UPWARD = {"StrictGreaterThan": True, "GreaterThan": True,
           "StrictLessThan": False, "LessThan": False}
_STRICT = {"StrictGreaterThan": True, "GreaterThan": False,
           "StrictLessThan": True, "LessThan": False}


class DiscreteState:
    """Relation values and floor values of one model, with their zero-crossing functions.

    Parameters
    ----------
    info : acausal.compiler.modelcode.RelationInfo
    roots, scales : generated functions ``f(t, z, p, m, out)`` (relations' g, then the
        floor arguments u; and the relations' magnitudes |lhs| + |rhs|).
    """

    def __init__(self, info, roots, scales):
        self.info = info
        self.n_rel, self.n_disc = info.n_relations, info.n_discrete
        # held(y) then pre(y) of the discrete variables follow the items in m
        self.n_held = getattr(info, "n_held", 0)
        self.held_start = np.asarray(getattr(info, "held_start", []), dtype=float)
        # initial() follows them where the model reads it: 1.0 while initializing
        self.has_initial = bool(getattr(info, "has_initial", False))
        types = list(getattr(info, "held_types", [])) or ["Real"] * self.n_held
        self.held_types = types
        self._boolean = np.array([t == "Boolean" for t in types], dtype=bool)
        self._integer = np.array([t == "Integer" for t in types], dtype=bool)
        self.upward = np.array([_UPWARD[op] for op in info.ops], dtype=bool)
        self.strict = np.array([_STRICT[op] for op in info.ops], dtype=bool)
        self.nominal = np.asarray(info.nominal, dtype=float)
        self._roots, self._scales = roots, scales
        self.m = np.zeros(self.n_rel + self.n_disc + 2 * self.n_held + self.has_initial)
        self.reset_held()
        self.offset = np.zeros(self.n_rel + 2 * self.n_disc)
        # chattering on round-off (module docstring): per relation its hysteresis and
        # the time of its last switch; atol is the run's (set by the driver)
        self.hysteresis = np.zeros(self.n_rel)
        self.last_switch = np.full(self.n_rel, -np.inf)
        self.atol = 0.0
        self.time_linear = np.asarray(info.time_linear, dtype=np.int64)
        # items whose switching time is predicted exactly (time events) are only a
        # safety net in the zero-crossing search: they never switch ahead of that time
        self._timed = np.zeros(self.n_rel + self.n_disc, dtype=bool)
        self._timed[self.time_linear] = True
        self._orientation_key = None
        # the band within which the last event found each item at zero (its location
        # is that uncertain): the next arming allows at least that much (see arm)
        self.event_band = None

    @property
    def n_roots(self) -> int:
        return self.n_rel + 2 * self.n_disc

    # -- values ------------------------------------------------------------------------
    def values(self, t, z, p) -> np.ndarray:
        """g of every relation, then u of every floor value (unoriented); NaN where the
        functions cannot be evaluated (a relation's side read in the modes of the
        relations inside it, before those are settled: abs(x) as -x under a root)."""
        out = np.full(self.n_rel + self.n_disc, np.nan)
        try:
            return self._roots(t, z, p, self.m, out)
        except DOMAIN_ERRORS:
            return out           # what was computed before the failure (the C values)

    def _scale_values(self, t, z, p) -> np.ndarray:
        """|lhs| + |rhs| of every relation; NaN where it cannot be evaluated (see
        :meth:`values`)."""
        out = np.full(self.n_rel, np.nan)
        try:
            return self._scales(t, z, p, self.m, out)
        except DOMAIN_ERRORS:
            return out

    def tolerance(self, t, z, p, v=None) -> np.ndarray:
        """Per item, the distance from zero below which it counts as zero (``v``: the
        values at (t, z) if already computed)."""
        scale = self._scale_values(t, z, p)
        tol_rel = ZERO_RTOL * np.abs(scale) + ZERO_NOMINAL * self.nominal
        u = (self.values(t, z, p) if v is None else v)[self.n_rel:]
        tol_disc = ZERO_RTOL * (np.abs(u) + 1.0)
        return np.concatenate([tol_rel, tol_disc])

    def truth(self, g) -> np.ndarray:
        """The relations' values for g (>, >=, <, <= as declared)."""
        up = np.where(self.strict, g > 0, g >= 0)
        down = np.where(self.strict, g < 0, g <= 0)
        return np.where(self.upward, up, down)

    def relation_modes(self) -> np.ndarray:
        return self.m[: self.n_rel] > 0.5

    # -- the integrator's view -----------------------------------------------------------
    def arm(self, t, z, p, rates, resolution: float) -> None:
        """Arm at a (re)start.  An item settled at zero by its rate may sit a hair on the
        other side of zero (the event point lies within the band of :meth:`settle`); its
        function is raised by that much until a step ends with the item on its own side
        (:meth:`release`), so that the start is not reported as a crossing.  A function
        further below zero than the band is a real contradiction and stays negative."""
        held = self.offset.copy()       # items still held a hair off zero since then
        self.offset[:] = 0.0
        r = self.oriented(t, z, p)
        event_band, self.event_band = self.event_band, None
        low = r < 0
        if not low.any():
            return
        v = self.values(t, z, p)
        tol = self.tolerance(t, z, p, v)
        vdot = np.nan_to_num(np.abs(rates()), posinf=0.0)
        band = 2.0 * (2.0 * tol + vdot * resolution)
        if event_band is not None:
            # the event was located with the rates before it: an item that stops there
            # (a speed that sticks) sits within that band, not within the new one
            band = np.maximum(band, event_band)
        band = np.concatenate([band[: self.n_rel], np.repeat(band[self.n_rel:], 2)])
        fix = low & (-r <= np.maximum(band, held))
        self.offset[fix] = -2.0 * r[fix]

    def release(self, t, z, p) -> None:
        """After an accepted step: an item that has left zero on its own side no longer
        needs the offset it was armed with."""
        if self.offset.any():
            raw = self.oriented(t, z, p) - self.offset
            self.offset[raw >= 0] = 0.0

    def oriented(self, t, z, p) -> np.ndarray:
        """r >= 0 while the frozen values agree with the solution (module docstring)."""
        v = self.values(t, z, p)
        g, u = v[: self.n_rel], v[self.n_rel:]
        sign, side = self._orientation()
        r = np.empty(self.n_roots)
        if self.n_rel:
            scale = self._scale_values(t, z, p)
            tol = ZERO_RTOL * np.abs(scale) + ZERO_NOMINAL * self.nominal
            if self.hysteresis.any():
                # written as the compiled loop computes it (solvers/cbdf.py): the
                # hysteresis rides on the nominal term, side^2 = 1
                nominal = self.nominal + side * self.hysteresis / ZERO_NOMINAL
                tol = ZERO_RTOL * np.abs(scale) + ZERO_NOMINAL * nominal
            r[: self.n_rel] = sign * g + side * tol
        if self.n_disc:
            n = self.m[self.n_rel:self.n_rel + self.n_disc]
            tol_u = ZERO_RTOL * (np.abs(u) + 1.0)
            r[self.n_rel::2] = u - n + tol_u                 # floor(u) = n on [n, n + 1)
            r[self.n_rel + 1::2] = n + 1.0 - u + np.where(self._timed[self.n_rel:], tol_u,
                                                          -tol_u)
        return r + self.offset

    def loop_orientation(self):
        """``(sign, side, nominal)`` for a compiled step loop (solver contract item 18):
        the orientation of :meth:`_orientation`, and the nominal term of each relation's
        tolerance with its hysteresis (a chattering relation's, :meth:`_chatter`), which
        the loop adds with the side's sign (side^2 = 1)."""
        sign, side = self._orientation()
        return sign, side, self.nominal[: self.n_rel] + side * self.hysteresis / ZERO_NOMINAL

    def _orientation(self):
        """Per relation, the sign that makes g >= 0 on the side its frozen value holds,
        and +1 on a closed side, -1 on an open one: the frozen value holds on a closed
        side (g >= 0 for a relation >= 0 that holds, or for a strict one that does not):
        switch once g is beyond zero by its tolerance; on an open side (a strict relation
        that holds) switch when g comes within its tolerance of zero, as a value that
        merely touches zero must.  Both change only with the discrete state."""
        key = self.m[: self.n_rel].tobytes()
        if key != self._orientation_key:
            holds = self.relation_modes()
            holds_up = np.where(holds, self.upward, ~self.upward)
            closed = (holds != self.strict) | self._timed[: self.n_rel]
            self._orientation_cache = (np.where(holds_up, 1.0, -1.0),
                                       np.where(closed, 1.0, -1.0))
            self._orientation_key = key
        return self._orientation_cache

    # -- changing the discrete state -------------------------------------------------------
    def contradicted(self, t, z, p) -> np.ndarray:
        """Items (relations, then floor values) whose frozen value clearly disagrees with
        the solution at (t, z): beyond zero on the wrong side."""
        v = self.values(t, z, p)
        tol = self.tolerance(t, z, p)
        g, u = v[: self.n_rel], v[self.n_rel:]
        tol_g, tol_u = tol[: self.n_rel], tol[self.n_rel:]
        bad_rel = (np.abs(g) > tol_g) & (self.truth(g) != self.relation_modes())
        n = self.m[self.n_rel:self.n_rel + self.n_disc]
        bad_disc = (u < n - tol_u) | (u >= n + 1.0 + tol_u)
        return np.concatenate([bad_rel, bad_disc])

    def settle(self, t, z, p, which, rates, resolution: float = 0.0,
               resting: str = "closed") -> bool:
        """Items in ``which`` take their value just after t; True if any changed.

        ``rates()`` returns d/dt of ``values`` along the solution.  At an event located
        to within ``resolution`` in time, an item counts as at zero within its tolerance,
        its hysteresis and ``|rate| resolution`` (where the crossing may lie).  A
        relation at zero whose rate does not decide takes, by ``resting``: ``"closed"``
        its value at exactly zero (>= and <= hold: an item that crossed and stays there),
        ``"value"`` the side its value g says (an item that is not crossing: x < 1e-15
        holds at x = 0 though 1e-15 is within x's round-off), ``"kept"`` the value it
        has (an item that was not crossing before either).
        """
        if not which.any():
            return False
        before = self.m.copy()
        v = self.values(t, z, p)
        band = self.tolerance(t, z, p, v)
        vdot = None
        if resolution > 0.0:
            # the crossing lies within the hysteresis (= tolerance) and |rate| resolution
            vdot = rates()
            band = 2.0 * (2.0 * band + np.nan_to_num(np.abs(vdot), posinf=0.0) * resolution)
        tol = band
        at_zero = which & (np.abs(self._distance(v)) <= band)
        if vdot is None and at_zero.any():
            vdot = rates()
        for k in np.flatnonzero(which):
            if math.isnan(v[k]):
                continue     # not evaluable in these modes (NaN): settled in a later round
            if k < self.n_rel:
                self.m[k] = float(self._relation_after(k, v[k], tol[k], at_zero[k], vdot,
                                                       resting))
            else:
                self.m[k] = self._floor_after(v[k], tol[k], at_zero[k], vdot, k)
        if resolution > 0.0:
            self._chatter(t, np.flatnonzero(self.m[: self.n_rel] != before[: self.n_rel]),
                          resolution)
        return not np.array_equal(before, self.m)

    def _chatter(self, t, switched, resolution) -> None:
        """Hysteresis for the relations that switch back on round-off (module
        docstring)."""
        if not switched.size:
            return
        # back within the window, at a later instant (an event iteration that flips a
        # relation twice at one time is no chattering: a ball leaving the floor)
        since = t - self.last_switch[switched]
        quick = (since > 0.0) & (since <= _CHATTER_WINDOW * resolution)
        limit = self.atol * self.nominal[switched]
        grown = np.maximum(2.0 * self.hysteresis[switched], _FIRST_HYSTERESIS * limit)
        self.hysteresis[switched] = np.where(quick, np.minimum(grown, limit), 0.0)
        self.last_switch[switched] = t

    def set_all(self, t, z, p, rates, resolution: float = 0.0, resting: str = "value") -> bool:
        """Every item takes its value just after t: at the start (an item at zero whose
        rate does not decide takes the side its value says), or after a reinit
        (``resting="kept"``: such an item keeps its value)."""
        return self.settle(t, z, p, np.ones(self.n_rel + self.n_disc, dtype=bool), rates,
                           resolution, resting)

    def _distance(self, v) -> np.ndarray:
        """Distance of each item from its switching point (g; u from the nearest integer)."""
        u = v[self.n_rel:]
        return np.concatenate([v[: self.n_rel], u - np.round(u)])

    def _relation_after(self, k, g, tol, at_zero, vdot, resting="closed") -> bool:
        if not at_zero:
            return self._holds(k, g)
        rate = vdot[k] if vdot is not None else 0.0
        # a rate that would not take the item out of its zero band within a unit of
        # time is round-off (a stuck speed whose acceleration is solved to 1e-17)
        if math.isfinite(rate) and abs(rate) > tol:
            return (rate > 0) == bool(self.upward[k])
        if resting == "value":
            return self._holds(k, g)              # not crossing: the side it is on
        if resting == "kept":
            return bool(self.m[k] > 0.5)
        return not bool(self.strict[k])           # at zero to stay: >= and <= hold

    def _holds(self, k, g) -> bool:
        if self.upward[k]:
            return g > 0 or (g == 0 and not self.strict[k])
        return g < 0 or (g == 0 and not self.strict[k])

    def _floor_after(self, u, tol, at_zero, vdot, k) -> float:
        if not at_zero:
            return float(math.floor(u))
        whole = float(round(u))
        rate = vdot[k] if vdot is not None else 0.0
        return whole - 1.0 if rate < 0 else whole

    # -- time events -------------------------------------------------------------------------
    def next_time_event(self, t, z, p, t_min) -> float | None:
        """The first time after ``t_min`` at which a time-linear item reaches its switching
        point with the discrete state as it is (exact: the item is linear in time)."""
        if not self.time_linear.size:
            return None
        v0, slopes = self._slopes(t, z, p)
        best, which = None, None
        for k in self.time_linear:
            a0, slope = v0[k], slopes[k]
            if slope == 0.0 or not math.isfinite(slope):
                continue
            if k < self.n_rel:
                target = 0.0
            else:
                n = self.m[k]
                target = n + 1.0 if slope > 0 else n
            te = t + (target - a0) / slope
            if te > t_min and (best is None or te < best):
                best, which = te, (k, target, slope)
        return best if best is None else self._land_on(best, which, z, p, t_min)

    def _land_on(self, te, which, z, p, t_min) -> float:
        """The first float at which the item reaches its target: t + (target - a0)/slope
        is rounded, and a step at startTime must switch at startTime, not one unit in the
        last place before it (where ``time >= startTime`` is still false)."""
        k, target, slope = which

        def reached(tau):
            with np.errstate(all="ignore"):
                g = self.values(tau, z, p)[k] - target
            return g * slope >= 0

        try:
            for _ in range(16):
                if reached(te):
                    break
                te = math.nextafter(te, math.inf)
            for _ in range(16):
                before = math.nextafter(te, -math.inf)
                if before <= t_min or not reached(before):
                    break
                te = before
        except (ValueError, ZeroDivisionError, OverflowError):
            pass
        return te

    def settle_time_items(self, t, z, p) -> bool:
        """At a time event: the time-linear items take their value just after t, decided by
        the sign of their (exact) slope where they sit at zero."""
        if not self.time_linear.size:
            return False
        which = np.zeros(self.n_rel + self.n_disc, dtype=bool)
        which[self.time_linear] = True
        slope = np.zeros(self.n_rel + self.n_disc)
        slope[self.time_linear] = self._slopes(t, z, p)[1][self.time_linear]
        return self.settle(t, z, p, which, lambda: slope)

    def _slopes(self, t, z, p):
        """Values at t and the slopes of the time-linear items (exact for them: a
        difference over a unit of time; a shorter one if another row fails there)."""
        v0 = self.values(t, z, p)
        for dt in (1.0, 1e-6 * (1.0 + abs(t))):
            try:
                with np.errstate(all="ignore"):
                    return v0, (self.values(t + dt, z, p) - v0) / dt
            except (ValueError, ZeroDivisionError, OverflowError):
                continue
        return v0, np.zeros_like(v0)

    def describe(self, k) -> str:
        if k < self.n_rel:
            return self.info.texts[k]
        if k < self.n_rel + self.n_disc:
            return self.info.discrete_texts[k - self.n_rel]
        j = k - self.n_rel - self.n_disc
        if j < self.n_held:
            return self.info.held_names[j]
        return f"pre({self.info.held_names[j - self.n_held]})"

    # -- discrete variables (acausal.compiler.frontend.sampled) -----------------------------------
    @property
    def held(self) -> slice:
        """Where held(y) of the discrete variables lives in m."""
        k = self.n_rel + self.n_disc
        return slice(k, k + self.n_held)

    @property
    def pre(self) -> slice:
        """Where pre(y) lives in m (equal to held(y) between events)."""
        k = self.n_rel + self.n_disc + self.n_held
        return slice(k, k + self.n_held)

    def reset_held(self) -> None:
        """Start values: the discrete variables' values before t0, held and pre."""
        if self.n_held:
            self.m[self.held] = self.held_start
            self.m[self.pre] = self.held_start

    def typed(self, slots, values) -> np.ndarray:
        """Values assigned to the held values ``slots``: a Boolean's 1.0 or 0.0, an
        Integer's whole number (a sum of gains times whole numbers rounds to one)."""
        out = np.asarray(values, dtype=float).copy()
        b, i = self._boolean[slots], self._integer[slots]
        if b.any():
            out[b] = np.where(out[b] > 0.5, 1.0, 0.0)
        if i.any():
            out[i] = np.rint(out[i])
        return out

    def show(self, j, x) -> str:
        """Held value j as its type prints it (True, 3, 0.25)."""
        if self._boolean[j]:
            return str(bool(x > 0.5))
        if self._integer[j]:
            return str(int(round(x)))
        return f"{x:g}"

    def set_initial(self, value: bool) -> None:
        """initial() is true while the initial values are found, false afterwards."""
        if self.has_initial:
            self.m[-1] = 1.0 if value else 0.0
