"""SUNDIALS IDA (scikit-sundae) on the residual acausal generates, for comparison.

IDA integrates the same F(t, z, z') = 0 as acausal's BDF (``CompiledModel.residual``
and ``.jacobian``, the index-1 system after index reduction, the algebraic unknowns
marked), from the same consistent initial point (``CompiledModel.initialize``), at
the same tolerances (atol = rtol x nominal; the unknowns acausal's error test leaves
out, derivatives solved as unknowns, get an atol that leaves them out of IDA's too).
Where the model has events, IDA runs from event to event: it stops at the next time
event (steps land on it) or where a zero-crossing function of the model changes sign
(IDA's root finding), the model's own event handling settles the discrete state and
re-initializes, and IDA starts again.  A model whose choice of states changes while it
runs is integrated with the choice made at t0 (IDA knows nothing of the switch); such
a run is said to be "fixed states".
"""
from __future__ import annotations

import time

import numpy as np

__all__ = ["ida_available", "run_ida"]

_MAX_STEPS = 10**6
_EXCLUDED = 1e12     # the atol of an unknown left out of the error test


def ida_available() -> bool:
    try:
        import sksundae.ida  # noqa: F401
    except Exception:         # noqa: BLE001  (not installed or not loadable)
        return False
    return True


def run_ida(compiled, t_end: float, rtol: float, names) -> tuple:
    """``(success, values at t_end by name, accepted steps, seconds, message)``."""
    from sksundae.ida import IDA
    t0 = time.perf_counter()
    model = compiled
    z, zp = model.initialize(0.0)
    atol = rtol * np.asarray(model.nominal, float)
    skip = np.asarray(getattr(model, "self_scaled", np.zeros(model.n, bool)), bool)
    atol = np.where(skip & model.algebraic, _EXCLUDED, atol)
    t, steps = 0.0, 0
    n_roots = int(getattr(model, "n_roots", 0))
    for _ in range(100000):
        t_next = t_end
        nxt = model.next_time_event(t) if hasattr(model, "next_time_event") else None
        if nxt is not None and t < nxt < t_end:
            t_next = nxt
        options = dict(rtol=rtol, atol=atol, max_num_steps=_MAX_STEPS,
                       algebraic_idx=np.flatnonzero(model.algebraic).tolist() or None,
                       jacfn=_jacobian(model))
        if n_roots:
            model.arm(t, z, zp)
            options.update(eventsfn=_events(model), num_events=n_roots)
        solver = IDA(_residual(model), **options)
        sol = solver.solve([t, t_next], z, zp)
        steps += int(sol.nsteps) if hasattr(sol, "nsteps") else len(sol.t) - 1
        if not sol.success and not getattr(sol, "status", 0) == 2:
            return False, {}, steps, time.perf_counter() - t0, str(sol.message)
        t, z, zp = float(sol.t[-1]), np.array(sol.y[-1]), np.array(sol.yp[-1])
        if t >= t_end * (1 - 1e-14):
            break
        crossed = np.zeros(n_roots, bool)
        if n_roots and sol.i_events is not None and len(sol.i_events):
            crossed[np.flatnonzero(sol.i_events[-1])] = True
        action = model.handle_event(t, z, zp, crossed)
        if action.y is not None:
            z = np.array(action.y, float)
        z, zp = model.reinitialize(t, z, zp, rtol=rtol, atol=rtol)
    y = model.expand(t, z) if hasattr(model, "expand") else z
    values = {}
    for name in names:
        sign, k = model.outputs[name]
        if sign is None:
            values[name] = float(k(model.p) if callable(k) else k)
        else:
            values[name] = float(sign * y[k])
    return True, values, steps, time.perf_counter() - t0, ""


def _residual(model):
    def residual(t, y, yp, res):
        res[:] = model.residual(t, y, yp)
    return residual


def _jacobian(model):
    def jacobian(t, y, yp, res, cj, JJ):
        JJ[:, :] = model.jacobian(t, y, yp, cj, dense=True)
    return jacobian


def _events(model):
    def events(t, y, yp, g):
        g[:] = model.roots(t, y, yp)
    return events
