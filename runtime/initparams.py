"""Parameters found by initialization (``Parameter(fixed=False)``), at run time.

The compiler keeps such a parameter in the parameter vector p and records where
(``meta["free_parameters"]``: positions, names, starts).  Initialization solves for them
with the unknowns z: the system [G; I](z, p_free) = 0 has one more column per free
parameter and one more initial row kept for it (:mod:`acausal.compiler.initrows`).  The
columns of the Jacobian for p_free are central differences of the residual (the
generated code differentiates by z only; a free parameter or two costs a few residual
evaluations per Newton step, and Newton's solution is judged on the residual, never on
the Jacobian).  The values found are written into p before the run: the run, its
result (``res.parameter_values``) and every later evaluation read them.  Each
initialization starts again from the starts, so the same inputs give the same values.
"""
from __future__ import annotations

import numpy as np

from ..errors import InitializationFailed

__all__ = ["free_parameters", "reset_free", "augmented", "not_tunable", "check_found"]


def free_parameters(model):
    """``(index, start, names)`` of the parameters found by initialization (empty
    arrays when there are none)."""
    found = model.meta.get("free_parameters") or {}
    return (np.asarray(found.get("index", ()), dtype=np.int64),
            np.asarray(found.get("start", ()), dtype=float), list(found.get("names", ())))


def reset_free(model) -> None:
    """The free parameters at their starts: where every initialization begins."""
    index, start, _ = free_parameters(model)
    if index.size:
        model.p[index] = start


def check_found(model, t0) -> None:
    """The values found respect the parameters' declared [min, max] (as Modelica's
    assertions on min and max): else InitializationFailed naming the parameter."""
    index, _, names = free_parameters(model)
    bounds = model.meta.get("parameter_bounds", {})
    for k, name in zip(index, names):
        lo, hi = bounds.get(name, (None, None))
        x = float(model.p[k])
        if (lo is not None and x < lo) or (hi is not None and x > hi):
            raise InitializationFailed(
                f"initialization at t = {t0}: parameter '{name}' (found by "
                f"initialization, fixed=False) = {x!r} is outside its range "
                f"[{'-inf' if lo is None else lo}, {'inf' if hi is None else hi}]", t0)


def not_tunable(model, name) -> str | None:
    """Why ``name`` cannot be given a value (it is found by initialization), or None."""
    if name in free_parameters(model)[2]:
        return (f"parameter '{name}' is found by initialization (fixed=False): its value "
                "is what the initial equations make it, not tunable (its start, Newton's "
                "guess, is given in the model)")
    return None


def augmented(model, F, J, z_guess, weights, dense: bool):
    """``(F, J, x0, weights, scale, names, split)``: the initial system over
    x = [z; p_free] from the one over z (``F``, ``J`` read ``model.p``), and
    ``split(x)`` which writes p_free into ``model.p`` and returns z."""
    index, _, names = free_parameters(model)
    n = model.n
    p0 = model.p[index].copy()
    nominal = np.maximum(np.abs(p0), 1.0)

    def split(x):
        model.p[index] = x[n:]
        return x[:n]

    def Fx(x):
        return F(split(x))

    def Jx(x):
        z = split(x)
        cols = []
        for j, k in enumerate(index):
            h = 1e-6 * max(abs(x[n + j]), nominal[j])
            model.p[k] = x[n + j] + h
            up = F(z)
            model.p[k] = x[n + j] - h
            down = F(z)
            model.p[k] = x[n + j]
            cols.append((up - down) / (2.0 * h))
        Jz = J(z)
        extra = np.column_stack(cols)
        if dense:
            return np.hstack([np.asarray(Jz), extra])
        import scipy.sparse as sps
        return sps.hstack([Jz, sps.csc_matrix(extra)]).tocsc()

    def wx(x):
        wp = 1.0 / (1e-6 * np.maximum(np.abs(x[n:]), np.abs(p0)) + 1e-6 * nominal)
        return np.concatenate([weights(x[:n]), wp])

    x0 = np.concatenate([z_guess, p0])
    scale = np.concatenate([model.nominal, nominal])
    return Fx, Jx, x0, wx, scale, list(model.names) + names, split
