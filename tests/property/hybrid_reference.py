"""The independent reference of the hybrid random models: an explicit ODE per mode,
written by hand from the physics (not through acausal's compiler), integrated with
scipy's ``solve_ivp`` at rtol 1e-11, its switchings located as events and the
integration restarted in the new mode.

A model gives

* ``rhs(t, y, mode)``: the derivatives in a mode;
* ``guards(t, y, mode)``: a list of (value, direction) pairs; a guard's value crossing
  zero in its direction (+1 rising, -1 falling) ends the mode.  A guard's direction is
  that of the crossing which leaves the mode, so a guard that is exactly zero at the
  restart (the switching point itself) does not fire again;
* ``switch(t, y, mode, k)``: the state and mode after guard k fired;
* ``outputs(t, y, mode)``: a dict of the compared signals.

A model whose modes switch back and forth without end (a sliding mode, which acausal
would chatter through and the reference cannot follow) raises :class:`Chattering`; the
fuzzer then draws another model.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, Dict, List

import numpy as np
from scipy.integrate import solve_ivp

__all__ = ["Chattering", "HybridCase", "ModeSolution", "integrate_modes", "RTOL_REF"]

RTOL_REF = 1e-11
MAX_EVENTS = 150


@dataclass
class HybridCase:
    """One random model: its parameters, the acausal model (``build()``), the reference
    (``reference()`` -> ModeSolution; None for an ill-posed one), the compared signals
    {acausal name: kind} (a signal's size is floored by its kind's largest), and the
    energy balance (``energy(get)`` -> (power supplied, energy stored, power
    dissipated), arrays from the result's signals ``get(name)``) where the elements are
    passive."""
    kind: str
    params: dict
    t_end: float
    build: Callable
    reference: Callable = None
    signals: Dict[str, str] = field(default_factory=dict)
    energy: Callable = None
    expect: str = "regular"
    culprits: tuple = ()

    def describe(self) -> str:
        body = ", ".join(f"{k}={v:.6g}" if isinstance(v, float) else f"{k}={v!r}"
                         for k, v in self.params.items())
        return f"{self.kind} ({self.expect}): {body}"


class Chattering(Exception):
    """The reference switches modes more often than MAX_EVENTS, or twice within a
    round-off of the time span: not a model the fuzzer can judge."""


@dataclass
class ModeSolution:
    segments: List[tuple] = field(default_factory=list)   # (t0, t1, dense sol, mode)
    events: List[float] = field(default_factory=list)
    outputs: Callable = None

    def evaluate(self, times) -> Dict[str, np.ndarray]:
        """The outputs at ``times`` (a time on a switching is read in the later mode)."""
        cols: Dict[str, list] = {}
        k = 0
        for t in times:
            while k + 1 < len(self.segments) and t >= self.segments[k][1]:
                k += 1
            t0, t1, sol, mode = self.segments[k]
            y = sol(min(max(t, t0), t1))
            for name, value in self.outputs(t, y, mode).items():
                cols.setdefault(name, []).append(float(value))
        return {name: np.array(v) for name, v in cols.items()}


def integrate_modes(rhs, guards, switch, outputs, y0, mode, t_end, *, method="DOP853",
                    rtol=RTOL_REF, atol=1e-14) -> ModeSolution:
    out = ModeSolution(outputs=outputs)
    t, y = 0.0, np.asarray(y0, dtype=float)
    atol = atol * np.maximum(1.0, np.abs(y))
    while t < t_end:
        dirs = [d for _, d in guards(t, y, mode)]
        events = []
        for k, d in enumerate(dirs):
            def g(tt, yy, k=k, mode=mode):
                return guards(tt, yy, mode)[k][0]
            g.terminal, g.direction = True, d
            events.append(g)
        # a bounded step: a guard may cross and cross back within a long step of a
        # mode whose state stands still (a stuck body)
        sol = solve_ivp(lambda tt, yy: rhs(tt, yy, mode), (t, t_end), y, method=method,
                        rtol=rtol, atol=atol, events=events or None, dense_output=True,
                        max_step=t_end / 400)
        if sol.status < 0:
            raise RuntimeError(f"reference integration failed: {sol.message}")
        out.segments.append((t, float(sol.t[-1]), sol.sol, mode))
        if sol.status != 1:
            break
        hits = [(float(ts[0]), k) for k, ts in enumerate(sol.t_events) if len(ts)]
        te, k = min(hits)
        ye = sol.y_events[k][0]
        y, mode = switch(te, np.array(ye, dtype=float), mode, k)
        j = _leaves_at_once(rhs, guards, te, y, mode, t_end)
        if j is not None:
            raise Chattering(f"a sliding mode at t = {te:.6g}: after guard {k}, guard {j} of "
                             f"the new mode {mode} fires at once")
        out.events.append(te)
        if len(out.events) > MAX_EVENTS:
            raise Chattering(f"more than {MAX_EVENTS} switchings")
        if len(out.events) >= 3 and out.events[-1] - out.events[-3] < 1e-9 * t_end:
            raise Chattering(f"switching back and forth at t = {te:.6g}")
        t = te
    return out


def _leaves_at_once(rhs, guards, t, y, mode, t_end):
    """The guard (if any) of the new mode that of the new mode fires within about 1e-8 of the time span (an
    Euler step of 1e-9 t_end carries it across, or nearly): the vector fields on both
    sides of the switching surface point into it, a sliding mode."""
    h = 1e-9 * t_end
    y1 = y + h * np.asarray(rhs(t, y, mode), float)
    for j, ((g0, d), (g1, _)) in enumerate(zip(guards(t, y, mode), guards(t + h, y1, mode))):
        if d * g1 > 0 and abs(g0) <= 10 * abs(g1 - g0):
            return j
    return None
