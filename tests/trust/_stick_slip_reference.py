"""Mode-by-mode reference for a DC motor positioning a load through an ideal gear against
Coulomb friction with F_s = F_c (Karnopp, Egeland & Gravdahl 5.2.3, (5.22)-(5.23)),
integrated by scipy's solve_ivp with its own event functions (no acausal involved).

Reflected to the load shaft, with the gear ratio n = w_motor / w_load:

    J_eff w' = T_a - F_c sgn(w)        sliding,   J_eff = J_L + n^2 J_m,  T_a = n k i
    w = 0                               stuck, while |T_a| <= F_s
    L i' = u - R i - k n w                                          (3.29)-(3.31)

and the library's PID (derivative filtered, output clipped, back-calculation
anti-windup with T_t = T_i), with e = r(t) - phi_L:

    v = k_p e + x_i + k_p N_d (e - x_d),   u = clip(v, u_min, u_max)
    x_i' = (k_p/T_i) e + (u - v)/T_i,      (T_d/N_d) x_d' = e - x_d

A sliding load that reaches w = 0 sticks if |T_a| <= F_s there, otherwise it reverses;
a stuck load breaks away when |T_a| reaches F_s, in the direction of T_a.
"""
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

__all__ = ["Drive", "simulate_drive"]


@dataclass
class Drive:
    R: float = 1.0
    L: float = 1e-3
    k: float = 0.05
    J_m: float = 1e-4
    n: float = 10.0
    J_L: float = 0.01
    F_c: float = 0.2
    k_p: float = 20.0
    T_i: float = 0.5
    T_d: float = 0.05
    N_d: float = 10.0
    u_max: float = 24.0

    @property
    def J_eff(self):
        return self.J_L + self.n**2 * self.J_m


def _unclipped(d, t, y, r):
    e = r(t) - y[0]
    return d.k_p * e + y[3] + d.k_p * d.N_d * (e - y[4])


def _rhs(d, r, stuck, direction, sat):
    def f(t, y):
        phi, w, i, x_i, x_d = y
        e = r(t) - phi
        v = _unclipped(d, t, y, r)
        u = v if sat == 0 else sat * d.u_max
        T_a = d.n * d.k * i
        dw = 0.0 if stuck else (T_a - d.F_c * direction) / d.J_eff
        return [0.0 if stuck else w, dw, (u - d.R * i - d.k * d.n * w) / d.L,
                d.k_p / d.T_i * e + (u - v) / d.T_i, d.N_d / d.T_d * (e - x_d)]
    return f


def _events(d, r, stuck, direction, sat):
    """(tag, event function) pairs for the current mode; all terminal."""
    evs = []

    def add(tag, fn, dirn):
        fn.terminal, fn.direction = True, dirn
        evs.append((tag, fn))
    if stuck:
        add("break away", lambda t, y: d.n * d.k * y[2] - d.F_c, 1.0)
        add("break away", lambda t, y: d.n * d.k * y[2] + d.F_c, -1.0)
    else:
        add("w = 0", lambda t, y: y[1], -direction)
    if sat >= 0:
        add("upper limit", lambda t, y: _unclipped(d, t, y, r) - d.u_max,
            -1.0 if sat == 1 else 1.0)
    if sat <= 0:
        add("lower limit", lambda t, y: _unclipped(d, t, y, r) + d.u_max,
            1.0 if sat == -1 else -1.0)
    return evs


def simulate_drive(d: Drive, r, t_eval, breaks=(), rtol=1e-11):
    """phi_L, w_L, i, T_a and the stuck flag at t_eval (sorted, from 0, everything at
    rest at t = 0); ``breaks`` are times where r has a kink.  Returns a dict of arrays
    and the list of (time, what) mode changes."""
    t_eval = np.asarray(t_eval, dtype=float)
    t_end = t_eval[-1]
    y = np.zeros(5)
    out, stuck_at, changes = np.empty((len(t_eval), 5)), np.zeros(len(t_eval), bool), []
    out[0], stuck_at[0] = y, True
    stuck, direction = True, 1.0
    v0 = _unclipped(d, 0.0, y, r)
    sat = 1 if v0 > d.u_max else (-1 if v0 < -d.u_max else 0)
    stops = sorted(b for b in breaks if 0 < b < t_end) + [t_end]
    t = 0.0
    while t < t_end:
        # one segment: up to the next kink of r, or to the first mode change
        t_stop = next(b for b in stops if b > t)
        tagged = _events(d, r, stuck, direction, sat)
        sol = solve_ivp(_rhs(d, r, stuck, direction, sat), (t, t_stop), y, method="DOP853",
                        rtol=rtol, atol=1e-14, dense_output=True,
                        events=[fn for _, fn in tagged])
        t_new = sol.t[-1]
        sel = (t_eval > t) & (t_eval <= t_new)
        if sel.any():
            out[sel] = sol.sol(t_eval[sel]).T
            stuck_at[sel] = stuck
        t, y = t_new, sol.y[:, -1].copy()
        if sol.status != 1:
            continue
        fired = [tag for (tag, _), te in zip(tagged, sol.t_events) if len(te)]
        T_a = d.n * d.k * y[2]
        for tag in fired:
            changes.append((t, tag))
            if tag == "break away":
                stuck, direction = False, np.sign(T_a)
            elif tag == "w = 0":
                y[1] = 0.0
                if abs(T_a) <= d.F_c:
                    stuck = True
                else:
                    direction = np.sign(T_a)
            elif tag == "upper limit":
                sat = 0 if sat == 1 else 1
            else:
                sat = 0 if sat == -1 else -1
    phi, w, i = out[:, 0], out[:, 1], out[:, 2]
    return {"phi": phi, "w": w, "i": i, "T_a": d.n * d.k * i, "stuck": stuck_at}, changes
