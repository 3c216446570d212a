"""Forward sensitivities of a compiled model with respect to its parameters.

For F(t, z, z', p) = 0 the sensitivities s_j = dz/d(ln p_j) = p_j dz/dp_j satisfy the
linear DAE (the DAE notes' (7.1.22)-(7.1.26) for an implicit system; Maly & Petzold
1996, the simultaneous corrector method)

    F_z s_j + F_z' s_j' + p_j F_p_j = 0,

integrated together with the model by the same BDF: the augmented vector is
[z, s_1, ..., s_k].  Scaling by p_j gives the s_j the magnitude of z, so the solver's
error weights (``nominal``) serve for both.  The Newton matrix is the block diagonal
of the model's (the coupling of s to z is left out: the iteration stays convergent and
the sensitivity equations are linear).  F_p is a central difference of the generated
residual; F_z and F_z' come from the generated Jacobian.

Event handling is the model's; a reinit does not update the sensitivities, and a
model that selects its states at run time is not supported (its F changes).
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sps

from ..solvers.base import DAEProblem

__all__ = ["ForwardSensitivity", "simulate_sensitivities", "output_sensitivities"]


class ForwardSensitivity(DAEProblem):
    """The model augmented by its sensitivities to the parameters ``params`` (indices
    into ``compiled.p``), from the consistent point ``z0``; see the module docstring."""

    def __init__(self, compiled, params, z0):
        if compiled.dynamic is not None:
            raise NotImplementedError("forward sensitivities need a static choice of states")
        from ..runtime.delays import refuse_delays
        refuse_delays(compiled, "forward sensitivities do not follow delay() (the "
                                "sensitivities would need their own history)",
                      "Use PadeDelay, or differences of simulations")
        c, n, k = compiled, compiled.n, len(params)
        names = list(c.names) + [f"d({z})/dln({c.param_names[j]})" for j in params
                                 for z in c.names]
        super().__init__(n * (k + 1), names)
        self.c, self.params, self.k = c, list(params), k
        self.algebraic = np.tile(c.algebraic, k + 1)
        self.nominal = np.tile(c.nominal, k + 1)
        self.n_roots = c.n_roots
        self.oriented_roots = getattr(c, "oriented_roots", False)
        if hasattr(c, "next_time_event"):
            self.next_time_event = c.next_time_event
        rows, cols = c.jac_pattern
        self.jac_pattern = (np.concatenate([rows + b * n for b in range(k + 1)]),
                            np.concatenate([cols + b * n for b in range(k + 1)]))
        # dF/dz' is constant (ones of the state rows); taken at a point where F is finite
        zp = np.zeros(n)
        self.E = (c.jacobian(0.0, z0, zp, 1.0) - c.jacobian(0.0, z0, zp, 0.0)).tocsr()

    def residual(self, t, y, yp):
        c, n = self.c, self.c.n
        z, zp = y[:n], yp[:n]
        J0 = c.jacobian(t, z, zp, 0.0)
        out = [c.residual(t, z, zp)]
        for b, j in enumerate(self.params, start=1):
            s, sp = y[b * n:(b + 1) * n], yp[b * n:(b + 1) * n]
            out.append(J0 @ s + self.E @ sp + self._scaled_dF_dp(t, z, zp, j))
        return np.concatenate(out)

    def _scaled_dF_dp(self, t, z, zp, j):
        c = self.c
        p0 = c.p[j]
        try:
            c.p[j] = p0 * (1 + 1e-6)
            fp = c.residual(t, z, zp)
            c.p[j] = p0 * (1 - 1e-6)
            fm = c.residual(t, z, zp)
        finally:
            c.p[j] = p0
        return (fp - fm) / (2e-6)

    def jacobian(self, t, y, yp, cj):
        n = self.c.n
        Jc = self.c.jacobian(t, y[:n], yp[:n], cj)
        return sps.block_diag([Jc] * (self.k + 1), format="csc")

    def roots(self, t, y, yp):
        n = self.c.n
        return self.c.roots(t, y[:n], None if yp is None else yp[:n])

    def arm(self, t, y, yp, resolution=0.0):
        n = self.c.n
        if hasattr(self.c, "arm"):
            self.c.arm(t, y[:n], None if yp is None else yp[:n], resolution)

    def handle_event(self, t, y, yp, crossed):
        n = self.c.n
        action = self.c.handle_event(t, y[:n], None if yp is None else yp[:n], crossed)
        if action.y is not None:
            action.y = np.concatenate([action.y, y[n:]])
        return action


def simulate_sensitivities(compiled, params, t_eval, *, rtol=1e-8, atol=None):
    """z(t_k) and s_j(t_k) = p_j dz/dp_j at the times t_eval (from t_eval[0]).

    Returns (t, Z, S) with Z of shape (len(t), n) and S of shape (len(t), k, n).
    """
    from ..simulation import initial_values
    from ..solvers import integrate
    c, t = compiled, np.asarray(t_eval, dtype=float)
    z0 = initial_values(c, t[0])
    s0 = [_initial_sensitivity(c, t[0], j) for j in params]
    problem = ForwardSensitivity(c, params, z0)
    y0 = np.concatenate([z0, *s0])
    atol = rtol if atol is None else atol
    out = integrate(problem, (t[0], t[-1]), y0, None, rtol=rtol, atol=atol, t_eval=t)
    Y = np.asarray(out.y)
    n = c.n
    return out.t, Y[:, :n], Y[:, n:].reshape(len(out.t), len(params), n)


def _initial_sensitivity(c, t0, j):
    """p_j dz(t0)/dp_j of the consistent initial values (0 for fixed start values)."""
    from ..simulation import initial_values
    p0 = c.p[j]
    try:
        c.p[j] = p0 * (1 + 1e-6)
        zp = initial_values(c, t0)
        c.p[j] = p0 * (1 - 1e-6)
        zm = initial_values(c, t0)
    finally:
        c.p[j] = p0
    return (zp - zm) / 2e-6


def output_sensitivities(compiled, t, Z, S, params, names):
    """y(t_k) and p_j dy/dp_j for named outputs, by a central difference of the
    generated ``expand`` along (s_j, p_j) at each point (exact for what is linear)."""
    c = compiled
    idx = [c.outputs[name] for name in names]
    Y = np.zeros((len(t), len(names)))
    dY = np.zeros((len(t), len(params), len(names)))
    saved = c.m.copy()
    try:
        for i, (tk, zk) in enumerate(zip(t, Z)):
            c.init_modes(tk, zk)
            Y[i] = _pick(c, c.expand(tk, zk), idx)
            for b, j in enumerate(params):
                dY[i, b] = _directional(c, tk, zk, S[i, b], j, idx)
    finally:
        c.m[:] = saved
    return Y, dY


def _directional(c, t, z, s, j, idx, h=1e-6):
    p0 = c.p[j]
    try:
        c.p[j] = p0 * (1 + h)
        ahead = _pick(c, c.expand(t, z + h * s), idx)
        c.p[j] = p0 * (1 - h)
        behind = _pick(c, c.expand(t, z - h * s), idx)
    finally:
        c.p[j] = p0
    return (ahead - behind) / (2 * h)


def _pick(c, values, idx):
    from .operating import constant_value
    return np.array([sign * values[k] if sign is not None else constant_value(c, k)
                     for sign, k in idx])
