"""Events: the iteration that settles the discrete state at an instant, and when-clauses.

Event iteration (Modelica Language Specification 3.6, sec. 8.6): at an event the items
that crossed take their value just after it (:mod:`acausal.runtime.modes`); when-clauses
whose condition became true fire; then, repeatedly, the algebraic unknowns are solved
again with the new discrete state (the states are continuous through the event) and the
relations the new solution contradicts are switched, until nothing changes.

That fixed point can cycle where relations are on an algebraic unknown whose value
depends on the modes: a Karnopp element locking up, whose curve parameter
(``tau = sat(sa, F_s)``, ``a = sa - sat(sa, F_s)``) is solved in the saturated mode on
one side, contradicts it, is solved in the other saturated mode, contradicts that, and
so on, never trying the unsaturated mode between them.  A curve-parameter law is
continuous in its parameter (that is why it is written so, as the MSL's ideal diode
is), so once a discrete state repeats, the algebraic equations are solved with those
relations *evaluated at every Newton iterate* (a semismooth Newton method on the
continuous piecewise-smooth system; Qi & Sun 1993), and the discrete state is taken from
the solution.  Relations that sit at zero at the event keep the value the event gave
them (their side was decided by the dynamics).

A relation that sits at zero at the event takes the side its rate chooses, but that
rate is the one before the event: a clutch slipping backwards reaches w = 0 with
der(w) > 0, which says "forward".  So once the algebraic unknowns are solved in the new
discrete state, the rates are taken again there (consistent derivatives): a relation at
zero whose new rate leaves its side, by more than its tolerance within the time
resolution, switches.  One switch per round, relations that hold first, so a pair such
as w > 0 / w < 0 passes through "neither" (the clutch locks) before the other side is
tried; where the sides keep switching, the side chosen before stays (as before this
check existed).  The sliding-to-locked-to-starting order of Modelica's friction elements
(Otter, Elmqvist & Mattsson 1999) then settles without a component's help.

When-clauses (sec. 8.3.5-8.3.6): the body of ``when c`` runs at the instant c becomes
true; ``reinit(x, e)`` restarts the state x from e, evaluated with the values just
before the event (``pre``).  A clause fires when its condition, evaluated with the
discrete state before and after the event, goes from false to true; a clocked clause
(``sample(start, period)``) fires at each tick, exact time events at start + k period,
including a tick at t0 (after the initial values are found; otherwise no clause fires
at initialization).  ``assign(y, e)`` writes the held value of the discrete variable y
(:mod:`acausal.compiler.frontend.sampled`), the clauses' assignments in data-flow order.
"""
from __future__ import annotations

import numpy as np

from ..solvers.base import EventAction
from ..solvers.linalg import SingularMatrixError
from ..solvers.newton import damped_newton
from .initial import algebraic_system, consistent_derivatives
from ..errors import InitializationFailed, InvalidValue
from ..words import shortened

__all__ = ["WhenClauses", "iterate_event", "discrete_iteration"]

_ROUNDS = 20          # solve-and-settle rounds at one instant before giving up
_DISCRETE_ROUNDS = 100   # rounds of the Boolean and Integer equations at one instant


class WhenClauses:
    """The when-clauses of a model (see :class:`acausal.compiler.modelcode.WhenCode`):
    conditions, clocks, reinit actions and assignments of discrete variables."""

    def __init__(self, whens):
        self.code = whens.code
        self.n_when = int(whens.n_when)
        self.targets = np.asarray(whens.targets, dtype=np.int64)
        self.owners = np.asarray(whens.owners, dtype=np.int64)
        self.texts = list(whens.texts)
        self.slots = np.asarray(getattr(whens, "assign_slots", []), dtype=np.int64)
        self.assign_owners = np.asarray(getattr(whens, "assign_owners", []), dtype=np.int64)
        self.levels = np.asarray(getattr(whens, "assign_levels", []), dtype=np.int64)
        self.clocks = np.asarray(getattr(whens, "clocks", []), dtype=np.int64)
        owners = getattr(whens, "cond_owners", None)
        self.cond_owners = np.arange(self.n_when) if owners is None else \
            np.asarray(owners, dtype=np.int64)
        n = getattr(whens, "n_clauses", None)
        self.n_clauses = self.n_when if n is None else int(n)
        # the equations of Boolean and Integer variables: evaluated at every event
        self.always = np.zeros(self.n_clauses, dtype=bool)
        self.always[np.asarray(getattr(whens, "always", []), dtype=np.int64)] = True
        self.equation = self.always[self.assign_owners] if len(self.slots) else \
            np.zeros(0, dtype=bool)
        self.has_equations = bool(self.equation.any())
        self.clause_slots = np.unique(self.slots[~self.equation])
        self.pulse_slots = np.asarray(getattr(whens, "pulse_slots", []), dtype=np.int64)
        self.has_equations |= bool(self.pulse_slots.size)
        self._assign_row = self.n_when + len(self.targets)
        self._clock_row = self._assign_row + len(self.slots)
        self.tick = np.zeros(len(self.clocks), dtype=np.int64)   # next tick of each clock
        self.start = np.zeros(len(self.clocks))
        self.period = np.ones(len(self.clocks))
        # (time, indices of the clauses that fired, z indices they re-initialized,
        # those values before and after): what the event records of a result report
        self.log = []

    def values(self, t, z, p, m) -> np.ndarray:
        return self.code.residual(t, z, p, m, np.empty(self.code.n_rows))

    # -- clocks: sample(start, period) ticks at start + k period, k = 0, 1, ... ----------
    def reset_clocks(self, t0, z, p, m) -> None:
        """Before a run: each clock's first tick at or after t0 (the parameters may have
        changed since the last run)."""
        if not len(self.clocks):
            return
        v = self.values(t0, z, p, m)
        self.start = v[self._clock_row::2].copy()
        self.period = v[self._clock_row + 1::2].copy()
        for c, w in enumerate(self.clocks):
            if not (np.isfinite(self.start[c]) and np.isfinite(self.period[c])
                    and self.period[c] > 0):
                raise InvalidValue(f"{self.texts[w]}: sample(start = {self.start[c]:g}, "
                                   f"period = {self.period[c]:g}) needs a finite start and "
                                   "a positive period")
        k = np.ceil((t0 - self.start) / self.period)
        k = np.maximum(k, 0.0)
        k -= (k > 0) & (self._tick_time(k - 1) >= t0 - _tick_tol(t0))   # rounding
        self.tick = k.astype(np.int64)

    def _tick_time(self, k):
        return self.start + k * self.period      # a product: no drift over many periods

    def next_tick(self, t_min) -> float | None:
        """The first tick after ``t_min`` (clocks fire at their ticks: time events)."""
        if not len(self.clocks):
            return None
        ticks = self._tick_time(self.tick)
        ticks = ticks[ticks > t_min]
        return float(ticks.min()) if ticks.size else None

    def due(self, t) -> np.ndarray:
        """The clocks whose next tick is t (within the rounding of t)."""
        return self._tick_time(self.tick) <= t + _tick_tol(t)

    # -- firing ----------------------------------------------------------------------------
    def fire(self, model, t, z, p, m_before, m_after):
        """New z if some clause fired between the two discrete states (or its clock
        ticks at t), else None.  Assignments write the held values in ``m_after`` (the
        model's discrete state) in data-flow order."""
        before = self.values(t, z, p, m_before)
        after = self.values(t, z, p, m_after)
        rows = (before[: self.n_when] < 0.5) & (after[: self.n_when] > 0.5)
        fired = np.zeros(self.n_clauses, dtype=bool)
        fired[self.cond_owners[rows]] = True       # any of its conditions became true
        due = self.due(t) if len(self.clocks) else np.zeros(0, dtype=bool)
        if due.any():
            fired[self.clocks[due]] = True
            self.tick[due] += 1
        if not fired.any():
            return None
        act = fired[self.owners]
        # every equation of a clause reads the values before the event: the
        # assignments see the states as they were, and the re-initializations (their
        # values computed from those same values) take effect after them
        new = self._assign(model, t, z, p, fired[self.assign_owners])
        if new is z:
            new = z.copy()
        new[self.targets[act]] = before[self.n_when:self._assign_row][act]   # pre values
        self.log.append((t, np.flatnonzero(fired).tolist(), self.targets[act].tolist(),
                         z[self.targets[act]].tolist(), new[self.targets[act]].tolist()))
        return new

    def _assign(self, model, t, z, p, act):
        """The assignments of the fired clauses, level by level (a level reads the held
        values the levels before it assigned; torn algebraic unknowns are solved again
        in between).  pre(y) is the held value before the instant while they run."""
        if not act.any():
            return z
        disc, m = model.discrete, model.m
        held = disc.held.start + self.clause_slots
        pre = disc.pre.start + self.clause_slots
        m[pre] = m[held]
        z = self._evaluate(model, t, z, p, act)
        m[pre] = m[held]            # after the instant, the left limit is the new value
        return z

    def _evaluate(self, model, t, z, p, act):
        """The assignments in ``act``, level by level of their data flow (a level reads
        the held values the levels before it wrote; torn algebraic unknowns are solved
        again in between)."""
        disc, m = model.discrete, model.m
        for n, lv in enumerate(np.unique(self.levels[act])):
            if n and model.algebraic.any():
                z = _solve_algebraic(model, t, z)
            v = self.values(t, z, p, m)
            sel = act & (self.levels == lv)
            slots = self.slots[sel]
            m[disc.held.start + slots] = disc.typed(slots, v[self._assign_row
                                                             + np.flatnonzero(sel)])
        return z

    def update_equations(self, model, t, z, p):
        """The equations of the Boolean and Integer variables evaluated (with pre as it
        is): (z, True if a held value changed)."""
        if not self.has_equations:
            return z, False
        held = model.discrete.held
        before = model.m[held].copy()
        z = self._evaluate(model, t, z, p, self.equation)
        return z, not np.array_equal(before, model.m[held])


def _tick_tol(t) -> float:
    return 64.0 * np.finfo(float).eps * max(1.0, abs(t))


def iterate_event(model, t, z, zp, crossed, initial: bool = False) -> EventAction:
    """Settle the discrete state of ``model`` at the event (t, z); see the module
    docstring.  ``crossed``: the oriented zero-crossing functions that went negative
    (all False at a time event).  ``initial``: the event that ends the initialization
    (when-clauses made true by initial() fire, clocks that tick at t0 too)."""
    disc, p = model.discrete, model.p
    m_old = model.m.copy()
    if initial and disc.has_initial:
        m_old[-1] = 0.0             # before the initialization, initial() was false
    R = disc.n_rel
    crossed = np.asarray(crossed, dtype=bool)
    items = np.concatenate([crossed[:R], crossed[R::2] | crossed[R + 1::2]])
    res = model.resolution

    def rates(zz=z, zzp=zp):
        return model.rates(t, zz, zzp)

    if items.any():
        disc.settle(t, z, p, items, rates, res)
    else:
        disc.settle_time_items(t, z, p)
    equations = model.whens is not None and model.whens.has_equations
    if equations or initial:
        z, fired = discrete_iteration(model, t, z, m_old, initial=initial)
    else:
        z, fired = _fire_clauses(model, t, z, m_old)
    decided = _at_zero(model, t, z, zp)      # their side was chosen by the dynamics
    seen = [model.m.copy()]
    for _ in range(_ROUNDS):
        z = _solve_algebraic(model, t, z)
        bad = disc.contradicted(t, z, p) & ~decided
        if not bad.any():
            before = model.m.copy()
            if not (_follow_new_rates(model, t, z, decided)
                    or _crossing_too(model, t, z, decided)):
                break
            if any(np.array_equal(model.m, m) for m in seen):
                model.discrete.m[:] = before     # no side holds for good: keep the
                break                            # one the dynamics before chose
            if equations:
                z, again = discrete_iteration(model, t, z, before, decided=decided)
                fired |= again
            seen.append(model.m.copy())
            continue
        before = model.m.copy()
        disc.settle(t, z, p, bad, lambda zz=z: model.rates(t, zz, np.zeros(model.n)))
        if equations:
            z, again = discrete_iteration(model, t, z, before, decided=decided)
            fired |= again
        if any(np.array_equal(model.m, m) for m in seen):
            z = _solve_live(model, t, z, decided)
            break
        seen.append(model.m.copy())
    else:
        raise _unsettled(model, t, seen)
    changed = fired or not np.array_equal(m_old, model.m)
    return EventAction(y=z if changed else None, changed=changed)


def _fire_clauses(model, t, z, m_prev):
    """When-clauses fire (a model without Boolean or Integer equations): with discrete
    variables, an assignment can make another clause's condition true at the same
    instant, and it fires in the next round (Modelica's event iteration)."""
    disc, p, fired = model.discrete, model.p, False
    for _ in range((_ROUNDS if disc.n_held else 1) if model.whens is not None else 0):
        m_now = model.m.copy()       # the conditions' values before the assignments
        new = model.whens.fire(model, t, z, p, m_prev, model.m)
        if new is None:
            break
        z, fired = new, True
        m_prev = m_now
        zp_new = np.zeros(model.n)
        zp_new[model.state_index] = model.state_derivatives(t, z)
        disc.set_all(t, z, p, lambda: model.rates(t, z, zp_new), model.resolution,
                     resting="kept")
    return z, fired


def discrete_iteration(model, t, z, m_prev, initial: bool = False, decided=None):
    """Modelica's event iteration over the Boolean and Integer equations and the
    when-clauses (Language Specification 3.6, sec. 8.6): the equations are evaluated
    with pre() as it is, the clauses whose condition became true since ``m_prev`` fire;
    while a held value differs from its pre value (or a clause fired), pre takes the
    new values and the round is repeated, the relations that the new values contradict
    switched in between.  Returns (z, whether a clause fired).  ``initial``: the
    instant ends the initialization (initial() is true in the first round only).  A
    cycle (``y = not pre(y)``) is an error naming the variables that keep changing."""
    whens, disc, p = model.whens, model.discrete, model.p
    held, pre = disc.held, disc.pre
    fired, history = False, []
    for k in range(_DISCRETE_ROUNDS):
        z, _ = whens.update_equations(model, t, z, p)
        m_now = model.m.copy()       # the conditions' values before the assignments
        new = whens.fire(model, t, z, p, m_prev, model.m)
        moved = new is not None and not np.array_equal(new, z)
        if new is not None:
            z, fired = new, True
        settled = new is None and np.array_equal(model.m[held], model.m[pre])
        if initial and k == 0:
            disc.set_initial(False)
            settled = False         # the equations read initial() as false from now on
        if settled:
            pulses = held.start + whens.pulse_slots
            if not model.m[pulses].any():
                return z, fired
            model.m[pulses] = 0.0   # the tick is over: y = sample(...) is false again
        history.append(model.m[held].copy())
        m_prev = m_now
        model.m[pre] = model.m[held]
        if moved:                   # a state was re-initialized: every item again
            zp_new = np.zeros(model.n)
            zp_new[model.state_index] = model.state_derivatives(t, z)
            disc.set_all(t, z, p, lambda: model.rates(t, z, zp_new), model.resolution,
                         resting="kept")
        else:                       # the items that read what changed
            bad = disc.contradicted(t, z, p)
            if decided is not None:
                bad &= ~decided
            if bad.any():
                zeros = np.zeros(disc.n_rel + disc.n_disc)
                disc.settle(t, z, p, bad, lambda: zeros)
    raise _cycling(model, t, history)


def _cycling(model, t, history) -> InitializationFailed:
    """The Boolean and Integer variables that kept changing at the instant t."""
    disc = model.discrete
    h = np.array(history[-8:])
    moving = np.flatnonzero(np.any(h != h[:1], axis=0))
    names = [disc.info.held_names[j] for j in moving[:6]]
    seq = "; ".join(f"{disc.info.held_names[j]}: "
                    + " -> ".join(disc.show(j, x) for x in h[:, j]) for j in moving[:6])
    return InitializationFailed(
        f"event iteration at t = {t:.10g}: the Boolean/Integer equations do not settle "
        f"after {_DISCRETE_ROUNDS} rounds, the values cycle ({seq}); an equation that "
        "reads its own variable through the others must read its value before the "
        "event, pre(...)", t, variables=names)


def _crossing_too(model, t, z, at_zero) -> bool:
    """Floor values that cross at this instant too: at zero at the event point
    (``at_zero``, within the band the event is located in) and moving across, by the
    rates of their arguments in the discrete state the event has settled, faster than
    their band per unit of time (floor(x) and floor(2 x) at x = 1).  They switch at
    this event, not at a second one a hair later.  (Relations are not moved by their
    rates here: a relation of an algebraic unknown at its threshold, a spool at its
    stop, has a rate that says nothing about where it goes; a relation that the event
    takes clearly across its threshold is switched by its value.)  Time events are
    exact and wait for their own time.  True if one switched."""
    disc = model.discrete
    R = disc.n_rel
    near = at_zero[R:] & ~disc._timed[R:]
    if not near.any():
        return False
    u = disc.values(t, z, model.p)[R:]
    rate = model.rates(t, z, consistent_derivatives(model, t, z))[R:]
    tol = disc.tolerance(t, z, model.p)[R:]
    band = 2.0 * (2.0 * tol + np.nan_to_num(np.abs(rate), posinf=0.0) * model.resolution)
    with np.errstate(invalid="ignore"):
        near &= np.isfinite(rate) & (np.abs(rate) > band)
        near &= np.abs(u - np.round(u)) <= band
    after = np.round(u) - (rate < 0)
    across = near & (after != disc.m[R:R + disc.n_disc])
    if not across.any():
        return False
    k = np.flatnonzero(across)
    disc.m[R + k] = after[k]
    return True


def _at_zero(model, t, z, zp) -> np.ndarray:
    """Items that sit at zero at the event point (within the event band), and those
    held at zero since an earlier event (armed with an offset, see ``arm``).  Keeps the
    band in ``discrete.event_band`` for the arming after the event."""
    disc = model.discrete
    v = disc.values(t, z, model.p)
    band = 2.0 * (2.0 * disc.tolerance(t, z, model.p, v)
                  + np.nan_to_num(np.abs(model.rates(t, z, zp)), posinf=0.0) * model.resolution)
    disc.event_band = band
    held = disc.offset[: disc.n_rel] != 0.0
    held = np.concatenate([held, np.zeros(disc.n_disc, dtype=bool)])
    return (np.abs(disc._distance(v)) <= band) | held


def _follow_new_rates(model, t, z, at_zero) -> bool:
    """A relation sitting at zero whose rate, in the discrete state it now gives, leaves
    the side it holds on (by more than its tolerance within the time resolution)
    switches to the side the rate enters; True if one did (module docstring)."""
    if not at_zero.any():
        return False
    disc, p = model.discrete, model.p
    R = disc.n_rel
    rel = np.flatnonzero(at_zero[:R])
    if not rel.size:
        return False
    rate = model.rates(t, z, consistent_derivatives(model, t, z))[rel]
    tol = disc.tolerance(t, z, p)[rel]
    holds = disc.relation_modes()[rel]
    up = disc.upward[rel]
    # the side the relation holds on lies at g > 0 for (holds == upward)
    inward = np.where(holds == up, 1.0, -1.0)
    away = np.isfinite(rate) & (-inward * rate * max(model.resolution, 1e-12) > tol)
    if not away.any():
        return False
    # one at a time, and first one that holds: a pair such as w > 0, w < 0 that both
    # leave their sides must pass through "neither" (stuck) before the other side holds
    order = np.flatnonzero(away & holds) if (away & holds).any() else np.flatnonzero(away)
    i = order[0]
    disc.m[rel[i]] = float((rate[i] > 0) == up[i])
    return True


def _solve_algebraic(model, t, z) -> np.ndarray:
    """G(t, z) = 0 for the algebraic unknowns, states held, discrete state frozen."""
    z = z.copy()
    alg, F, J = algebraic_system(model, t, z)
    if not alg.size:
        return z
    w = 1.0 / (1e-8 * np.abs(z[alg]) + 1e-8 * model.nominal[alg])
    try:
        out = damped_newton(F, J, z[alg], weights=w, tol=1e-3, max_iter=30)
    except SingularMatrixError:
        return z
    if out.converged:
        z[alg] = out.x
    return z


def _solve_live(model, t, z, decided) -> np.ndarray:
    """The algebraic unknowns with the undecided relations following every iterate, then
    the discrete state taken from the solution (module docstring)."""
    disc, p = model.discrete, model.p
    alg = model.algebraic_index
    free = ~decided
    zeros = np.zeros(disc.n_rel + disc.n_disc)
    z = z.copy()

    def follow(zz):
        before = model.m.copy()
        disc.settle(t, zz, p, free, lambda: zeros)
        return before

    def F(za):
        zz = z.copy()
        zz[alg] = za
        follow(zz)
        return model.G(t, zz)

    def J(za):
        zz = z.copy()
        zz[alg] = za
        follow(zz)
        return model.dG_dy(t, zz).tocsc()[:, alg]

    if alg.size:
        w = 1.0 / (1e-8 * np.abs(z[alg]) + 1e-8 * model.nominal[alg])
        try:
            out = damped_newton(F, J, z[alg], weights=w, tol=1e-3, max_iter=50)
        except SingularMatrixError:
            out = None
        if out is None or not out.converged:
            raise InitializationFailed(
                f"event at t = {t:.10g}: no consistent discrete state; the relations "
                "keep switching: " + "; ".join(_names(model, free)), t)
        z[alg] = out.x
    follow(z)
    bad = disc.contradicted(t, z, p) & free
    if bad.any():
        raise InitializationFailed(
            f"event at t = {t:.10g}: no consistent discrete state; contradicted: "
            + "; ".join(shortened(disc.describe(k)) for k in np.flatnonzero(bad)[:5]), t)
    return z


def _names(model, mask) -> list:
    return [shortened(model.discrete.describe(k)) for k in np.flatnonzero(mask)[:5]]


def _unsettled(model, t, seen) -> InitializationFailed:
    flips = np.flatnonzero(np.any(np.diff(np.array(seen), axis=0) != 0, axis=0))
    return InitializationFailed(
        f"event iteration at t = {t:.10g} did not settle after {_ROUNDS} rounds: "
        + "; ".join(shortened(model.discrete.describe(k)) for k in flips[:5]), t)
