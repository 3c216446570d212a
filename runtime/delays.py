"""The history of delayed expressions: ``delay(expr, T)`` at run time.

The compiler turns every ``delay(expr, T)`` into a value the generated code reads from
``p[n_params + j]`` (:mod:`acausal.compiler.frontend.delays`); here those values are written
before every call of the generated code at time t, from a history of expr:

* **Step size.**  The integrator's step is limited to the smallest delay time
  (``CompiledModel.max_step``, solver contract item 14).  Then ``t - T`` lies before
  the start of the step being taken, in the part of the solution already accepted, so
  a delayed value is an *explicit input* of the step: the corrector's Newton iteration
  and Jacobian are those of an ODE with a known input, with no iteration between the
  step and its own past (which steps longer than T would need, through the step's own
  interpolant).  The cost is that a model with a short delay takes at least
  (t_end - t0)/T steps.
* **History.**  After every accepted interval [t_lo, t_hi] (solver contract item 15,
  ``commit``) the delayed expressions are evaluated on the integrator's dense output
  (the BDF interpolation polynomial) at ``_NODES`` Chebyshev-Lobatto points of the
  interval, in the discrete state that held over it, and kept as a polynomial of
  degree ``_NODES - 1`` (5, the BDF's highest order), evaluated by the barycentric
  formula (Berrut & Trefethen, SIAM Review 46 (2004) 501-517).  An interval ends at
  every event, so a jump of expr is a break between two polynomials; reads are
  right-continuous, as the solution is.  Intervals older than twice the longest delay
  are dropped (the buffer is trimmed); the driver records the delayed values at every
  output point (contract item 16), so results need no old history.
* **Before t0.**  Modelica's rule: expr(t) for t < t0 is expr(t0).  Since expr(t0)
  may itself depend on the delayed value (a loop through the delay), the delayed
  values at t0 are solved for, by Newton's method around the initialization.
* **Discontinuities.**  Every event at t_e (and t0, where the constant history meets
  the solution) may put a jump into expr or one of its derivatives, which reappears
  at t_e + T: those times are time events (``next_time_event``), so the integrator
  lands on them and restarts there.  In a loop through a delay each of them is
  followed on to t_e + 2T, ... up to ``_MAX_LEVEL`` generations (a jump in the k-th
  derivative is below the error of a BDF of order <= 5 for k > 6); without a loop
  (``DelayCode.feedback``, decided by the compiler) one generation is all there is.
"""
from __future__ import annotations

import bisect

import numpy as np

from ..errors import InitializationFailed, SimulationError

__all__ = ["DelayLines", "FilledCode", "refuse_delays"]

_NODES = 6            # Chebyshev-Lobatto points per accepted interval (degree 5)
_MAX_LEVEL = 6        # a discontinuity at t_e is followed to t_e + k T, k <= this
_INIT_ROUNDS = 20     # Newton steps on expr(t0) = delayed value at t0
_INIT_RTOL = 1e-12    # ... until they agree to this, relative
_TRIM_EVERY = 256     # drop old intervals in batches of at least this many
_MERGE = 1e3          # events and breaks within this many root-finding resolutions merge
_MAX_SPLITS = 12      # an accepted interval is cut in at most 2^this pieces
_READ_AHEAD = 1e-2    # past the history by this fraction of its last interval: extrapolated

_X = np.cos(np.pi * np.arange(_NODES) / (_NODES - 1))          # 1 .. -1
_W = np.array([(-1.0) ** i for i in range(_NODES)])
_W[0] *= 0.5
_W[-1] *= 0.5


def refuse_delays(compiled, what: str, advice: str) -> None:
    """ModelError naming every delay of ``compiled`` (a CompiledModel), for a method
    that cannot treat one (``what`` says which and why; ``advice`` what to do)."""
    d = getattr(getattr(compiled, "model_code", None), "delays", None)
    if d is None:
        return
    from ..components.component import ModelError
    raise ModelError(f"{what}: " + "; ".join(f"{x} in {w}" for x, w in zip(d.texts, d.wheres))
                     + f".  {advice}")


class FilledCode:
    """Generated code whose functions first write the delayed values at t into p."""

    FUNCTIONS = ("residual", "jacobian", "roots", "scales", "expand")

    def __init__(self, code, fill):
        self._code = code
        for name in self.FUNCTIONS:
            fn = getattr(code, name, None)
            if fn is not None:
                setattr(self, name, _filled(fn, fill))

    def __getattr__(self, name):
        return getattr(self._code, name)


def _filled(fn, fill):
    def call(t, z, p, m, out):
        fill(t, p)
        return fn(t, z, p, m, out)
    return call


class DelayLines:
    """The delays of one model: their times, histories and pending discontinuities.

    Parameters
    ----------
    dc : acausal.compiler.modelcode.DelayCode
    n_params : int
        Number of tunable parameters: delay j is read from ``p[n_params + j]``.
    """

    def __init__(self, dc, n_params: int):
        self.texts, self.wheres = list(dc.texts), list(dc.wheres)
        self._times = list(dc.times)
        self.n = len(self.texts)
        self.slots = n_params + np.arange(self.n)
        # without a loop through a delay, a discontinuity comes back once
        self.generations = _MAX_LEVEL if getattr(dc, "feedback", True) else 1
        self.T = None                  # the delay times of the current run
        self.t0 = None
        self.before = np.zeros(self.n)
        self.held = None               # values given by the caller (recorded results)
        self._reset()

    def _reset(self):
        self._starts, self._ends, self._values = [], [], []
        self._kept_from = -np.inf      # intervals before this were trimmed
        self.scale = np.zeros(self.n)  # the largest |expr| so far: its own scale
        self._breaks = []              # sorted (time, generation)
        self._merge = 0.0              # breaks closer than this are one (see _schedule)
        self._last_event = None

    # -- the delay times ----------------------------------------------------------------
    def times(self, p) -> np.ndarray:
        """The delay times at the parameter values p; each must be positive."""
        T = np.array([f(p) if callable(f) else f for f in self._times], dtype=float)
        bad = [k for k in range(self.n) if not (0 < T[k] < np.inf)]
        if bad:
            from ..components.component import InvalidValue
            k = bad[0]
            raise InvalidValue(f"{self.texts[k]} in {self.wheres[k]}: the delay time is "
                               f"{T[k]!r} with these parameter values; it must be positive")
        return T

    # -- values -------------------------------------------------------------------------
    def fill(self, t, p) -> None:
        """Write the delayed values at time t into p (the generated code reads them)."""
        if self.held is not None:
            p[self.slots] = self.held
            return
        if self.T is None:
            raise SimulationError("a model with delay() must be initialized with "
                                  "compiled.initialize(t0) first (it starts the history)")
        p[self.slots] = self.values_at(t)

    def values_at(self, t) -> np.ndarray:
        """The delayed values at time t.  A time before the event being approached
        reads a jump in the history by its left limit, after it by its right limit (as
        the discrete state is old before an event and new after it)."""
        left = self._last_event is None or t > self._last_event
        snap = 8 * np.finfo(float).eps * max(1.0, abs(t))
        return np.array([self.value(j, t - self.T[j], left, snap) for j in range(self.n)])

    def value(self, j: int, s: float, left: bool = False, snap: float = 0.0) -> float:
        """expr_j at time s from the history (its value at t0 before t0); ``left``:
        at a jump (two intervals meeting at s, to within ``snap``) the left limit."""
        if s <= self.t0 or not self._starts:
            return float(self.before[j])
        if s < self._kept_from:
            raise SimulationError(f"{self.texts[j]}: the history at t = {s:.10g} is no "
                                  "longer kept (it is trimmed to twice the longest delay)",
                                  t=s)
        k = bisect.bisect_right(self._starts, s) - 1
        last = len(self._starts) - 1
        if left and k > 0 and s - self._starts[k] <= snap and self._ends[k - 1] >= s - snap:
            k -= 1                          # at the start of a piece: the one before
        elif not left and k < last and self._starts[k + 1] - s <= snap:
            k += 1                          # just before the start of the next piece
        if k < 0:
            return float(self.before[j])
        if s > self._ends[k] and s - self._ends[k] > _READ_AHEAD * (
                self._ends[k] - self._starts[k]):
            # ahead of the accepted solution: only a prediction reads there (the next
            # time event of a relation on time alone, which reads no delay); a step
            # longer than T would, and gets a failed iterate
            return np.nan
        return _barycentric(self._starts[k], self._ends[k], self._values[k][:, j], s)

    # -- the run --------------------------------------------------------------------------
    def initialize(self, model, t0: float, solve):
        """Consistent (z, z') at t0 (``solve(model, t0)``, the one initialization path)
        with the delayed values equal to the delayed expressions at t0 (the history
        before t0): v = F(v), F(v) the expressions after initializing with the delayed
        values v, solved by Newton's method with a difference Jacobian (one step when
        the expressions do not depend on v, as when they are fixed states); then the
        first discontinuities are scheduled."""
        self.T = self.times(model.p)
        self.t0 = float(t0)
        self.held = None
        self._reset()
        self._merge = 1e-9 * float(np.max(self.T))   # until the driver's resolution is known
        self._last_event = self.t0

        def F(v):
            self.before[:] = v
            z, zp = solve(model, t0)
            return model.delay_arguments(t0, z), (z, zp)

        self.before[:] = 0.0
        v = np.nan_to_num(model.delay_arguments(t0, model.start))
        fv, point = F(v)
        for _ in range(_INIT_ROUNDS):
            if np.all(np.abs(fv - v) <= _INIT_RTOL * np.maximum(np.abs(fv), np.abs(v))):
                self.before[:] = fv
                self._schedule(self.t0, 0)
                return point
            J = -np.eye(self.n)
            for k in range(self.n):
                h = 1e-7 * max(abs(v[k]), abs(fv[k]), 1e-3)
                vk = v.copy()
                vk[k] += h
                J[:, k] += (F(vk)[0] - fv) / h
            try:
                v = v - np.linalg.solve(J, fv - v)
            except np.linalg.LinAlgError:
                break
            fv, point = F(v)
        worst = int(np.argmax(np.abs(fv - v)))
        raise InitializationFailed(
            f"the delayed values at t0 = {t0:.6g} (the history before the start, "
            f"Modelica's expr(t0)) could not be made equal to the delayed expressions: "
            f"{self.texts[worst]} in {self.wheres[worst]} is {v[worst]:.6g}, its "
            f"expression {fv[worst]:.6g} (a loop through the delay with a gain of 1 at "
            "t0 has no consistent start); give start values near the initial solution",
            t=t0)

    def commit(self, model, t_lo: float, t_hi: float, interpolate, rtol: float) -> None:
        """Keep the delayed expressions over the accepted interval [t_lo, t_hi], as
        polynomials on pieces short enough for ``rtol`` of each expression's scale."""
        if not t_hi > t_lo:
            return
        pieces = [(float(t_lo), float(t_hi), 0)]
        while pieces:
            a, b, depth = pieces.pop()
            values = self._sample(model, a, b, interpolate)
            self.scale = np.maximum(self.scale, np.max(np.abs(values), axis=0))
            if depth < _MAX_SPLITS and np.any(_tail(values) > 0.1 * rtol * self.scale):
                mid = 0.5 * (a + b)
                pieces += [(mid, b, depth + 1), (a, mid, depth + 1)]   # a..mid first
                continue
            self._starts.append(a)
            self._ends.append(b)
            self._values.append(values)
        self._trim(t_hi)

    def _sample(self, model, a, b, interpolate) -> np.ndarray:
        """The delayed expressions at the Chebyshev-Lobatto points of [a, b] (b first)."""
        nodes = 0.5 * (a + b) + 0.5 * (b - a) * _X
        nodes[0], nodes[-1] = b, a
        values = np.empty((_NODES, self.n))
        for i, s in enumerate(nodes):
            values[i] = model.delay_arguments(s, interpolate(s)[0])
        return values

    def _trim(self, t) -> None:
        horizon = t - 2.0 * float(np.max(self.T))
        old = bisect.bisect_left(self._ends, horizon)
        if old >= _TRIM_EVERY:
            self._kept_from = self._ends[old - 1]
            del self._starts[:old], self._ends[:old], self._values[:old]

    # -- discontinuities ----------------------------------------------------------------
    def _schedule(self, t, generation) -> None:
        """Discontinuities at t + T of every delay; one within the merging distance of
        one already scheduled is that one (the earlier, with the younger generation):
        an event located to within the root-finding resolution, plus a delay, must not
        become two events a hair apart."""
        if generation >= self.generations:
            return
        for T in self.T:
            b = float(t + T)
            tol = max(self._merge, 64 * np.finfo(float).eps * abs(b))
            k = bisect.bisect_left(self._breaks, (b - tol, -1))
            if k < len(self._breaks) and self._breaks[k][0] <= b + tol:
                near, g = self._breaks[k]
                self._breaks[k] = (min(near, b), min(g, generation + 1))
                self._breaks.sort()
            else:
                bisect.insort(self._breaks, (b, generation + 1))

    def event_at(self, t: float, resolution: float, fresh: bool) -> None:
        """An event at t: its discontinuities reappear one delay later.  An event that
        is only a scheduled time continues that generation; one of the model's own
        (``fresh``: a crossing, a time event of a relation) starts a new one."""
        if self._last_event == t:
            return
        self._last_event = t
        self._merge = max(self._merge, _MERGE * resolution)
        tol = max(self._merge, 64 * np.finfo(float).eps * max(1.0, abs(t)))
        generation, keep = 0, []
        for b, g in self._breaks:
            if abs(b - t) <= tol:
                generation = max(generation, g)
            elif b > t:
                keep.append((b, g))
        self._breaks = keep
        self._schedule(t, 0 if fresh else generation)

    def next_break(self, t_min: float):
        """The first scheduled discontinuity at or after t_min, or None."""
        k = bisect.bisect_left(self._breaks, (t_min, -1))
        return self._breaks[k][0] if k < len(self._breaks) else None


def _tail(values) -> np.ndarray:
    """Per column, the size of the two highest Chebyshev coefficients of the polynomial
    through values at the Lobatto points (a discrete cosine transform, type I): the
    error of the interpolant where the expansion converges (Trefethen, *Approximation
    Theory and Approximation Practice*, ch. 4)."""
    n = _NODES - 1
    k = np.arange(_NODES)
    C = np.cos(np.pi * np.outer(k[-2:], k) / n) * _HALF_ENDS[None, :]
    return np.max(np.abs(C @ values), axis=0) * (2.0 / n)


_HALF_ENDS = np.ones(_NODES)
_HALF_ENDS[[0, -1]] = 0.5


def _barycentric(a, b, values, s) -> float:
    """The polynomial through ``values`` at the Chebyshev-Lobatto points of [a, b]."""
    x = (2.0 * s - (a + b)) / (b - a)
    d = x - _X
    hit = np.flatnonzero(d == 0.0)
    if hit.size:
        return float(values[hit[0]])
    q = _W / d
    return float(np.dot(q, values) / np.sum(q))


def explicit_values(model, lines: DelayLines, times) -> np.ndarray:
    """The delayed values at ``times`` for a model without states: every variable is
    then a function of time, and so is each delayed expression, evaluated directly at
    t - T (at t0 before t0) in the modes that hold there.  A delayed expression that
    reads another delay has no such closed form here: ModelError."""
    from ..components.component import ModelError
    out = np.empty((len(times), lines.n))
    z = np.zeros(0)
    saved = model.m.copy()
    lines.held = np.full(lines.n, np.nan)     # a delay read inside a delay shows as NaN
    try:
        for k, t in enumerate(times):
            for j in range(lines.n):
                s = max(float(t) - lines.T[j], lines.t0)
                model.init_modes(s, z)
                out[k, j] = model.delay_arguments(s, z)[j]
                if np.isnan(out[k, j]):
                    raise ModelError(f"{lines.texts[j]} in {lines.wheres[j]}: in a model "
                                     "without states a delayed expression must not read "
                                     "another delay (or be undefined at t - T)")
    finally:
        lines.held = None
        model.m[:] = saved
    return out
