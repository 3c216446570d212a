"""Mode-by-mode reference for a chain of inertias coupled by clutches and braked to the
housing, integrated by scipy's solve_ivp with its own event functions (no acausal).

    T(t) -> J[0] -- element 0 -- J[1] -- element 1 -- ... -- J[n-1] -- brake -| housing

Element k couples J[k] (its flange_a) and J[k+1] (flange_b), the brake holds J[n-1]
against the housing.  With w_rel = w_b - w_a (the brake: w_rel = w of its inertia) an
element acts with torque tau on flange_b and -tau on flange_a:

    open (fn = 0):        tau = 0
    sliding, s = sgn w_rel: tau = s mu fn             (constant coefficient mu)
    stuck:                 w_rel' = 0, tau from the torque balance, |tau| <= peak mu fn

The stuck inertias form rigid groups; each mode is an ODE for the speeds whose
accelerations and constraint torques come from one linear system

    J_i w_i' = (torques on i),     w_rel' = 0 for every stuck element.

Events: a sliding element reaches w_rel = 0 (it sticks if the torque it must then carry
is at most peak mu fn, else it slides the other way), a stuck one's torque reaches
peak mu fn (it breaks away in the direction of that torque), and the times at which an
element is pressed or released (piecewise-constant fn).  A lock-up merges the group:
its speed is the angular-momentum average, sum J_i w_i / sum J_i.
"""
from dataclasses import dataclass, field

import numpy as np
from scipy.integrate import solve_ivp

__all__ = ["Chain", "simulate_chain", "speeds"]


@dataclass
class Chain:
    J: tuple                       # inertias, kg m2
    fn: tuple                      # per element (clutches ..., brake): fn_max, N
    on: tuple                      # per element: list of (t_on, t_off or None)
    mu: float = 0.5
    peak: float = 1.1
    amplitude: float = 10.0        # T(t) = amplitude sin(2 pi f t) on J[0]
    f: float = 5.0
    w0: tuple = (10.0, 0.0, 0.0)
    log: list = field(default_factory=list)

    def torque(self, t):
        return self.amplitude * np.sin(2 * np.pi * self.f * t)

    def pressed(self, k, t):
        return any(t_on <= t and (t_off is None or t < t_off) for t_on, t_off in self.on[k])

    def times(self):
        return sorted({t for spans in self.on for span in spans for t in span
                       if t is not None})

    def couples(self, k):
        """(a, b): the inertias on flange_a and flange_b of element k (b None: housing)."""
        n = len(self.J)
        return (k, k + 1) if k < n - 1 else (n - 1, None)

    def w_rel(self, k, w):
        a, b = self.couples(k)
        return w[a] if b is None else w[b] - w[a]


def _brake_sign(chain, k):
    """The brake acts on its inertia like a clutch whose flange_a is the housing."""
    return k == len(chain.J) - 1


def solve_mode(chain, t, w, mode):
    """Accelerations and element torques for the mode (per element: 'open', +1, -1,
    'stuck').  Returns (acc, tau)."""
    n, m = len(chain.J), len(mode)
    stuck = [k for k in range(m) if mode[k] == "stuck"]
    A = np.zeros((n + len(stuck), n + len(stuck)))
    rhs = np.zeros(n + len(stuck))
    A[:n, :n] = np.diag(chain.J)
    rhs[0] += chain.torque(t)
    tau = np.zeros(m)
    for k in range(m):
        if mode[k] in (1, -1):
            tau[k] = mode[k] * chain.mu * chain.fn[k]
    for k in range(m):
        a, b = chain.couples(k)
        if _brake_sign(chain, k):
            # brake: torque -tau on its inertia (w_rel = w of that inertia)
            rhs[a] -= tau[k]
        else:
            rhs[b] -= tau[k]
            rhs[a] += tau[k]
    for j, k in enumerate(stuck):
        a, b = chain.couples(k)
        col = n + j
        if _brake_sign(chain, k):
            A[a, col] += 1.0                 # J a' = ... - tau_k
            A[n + j, a] = 1.0                # w_a' = 0
        else:
            A[b, col] += 1.0
            A[a, col] -= 1.0
            A[n + j, b], A[n + j, a] = 1.0, -1.0
    x = np.linalg.solve(A, rhs)
    for j, k in enumerate(stuck):
        tau[k] = x[n + j]
    return x[:n], tau


def settle(chain, t, w, mode, at_zero):
    """Modes of the elements in ``at_zero`` (w_rel = 0, pressed): stuck unless the
    torque exceeds what they hold, then sliding in its direction; repeated until no
    stuck element is overloaded (the most overloaded one is released first)."""
    mode = list(mode)
    for k in at_zero:
        mode[k] = "stuck"
    while True:
        _, tau = solve_mode(chain, t, w, mode)
        load = [(abs(tau[k]) / (chain.peak * chain.mu * chain.fn[k]), k)
                for k in range(len(mode)) if mode[k] == "stuck"]
        over = [x for x in load if x[0] > 1.0 + 1e-12]
        if not over:
            return mode
        _, k = max(over)
        mode[k] = 1 if tau[k] > 0 else -1


def simulate_chain(chain, t_end, rtol=1e-10, atol=1e-12):
    """Returns (segments, switches): segments (t array, w array (n x len t), mode) and
    switches (t, element, old mode, new mode, momentum of the group before, after)."""
    t, w = 0.0, np.array(chain.w0, dtype=float)
    m = len(chain.fn)
    mode = ["open"] * m
    segments, switches = [], []
    stops = [s for s in chain.times() if s > 0] + [t_end]
    while t < t_end - 1e-14:
        mode = _engagement(chain, t, w, mode, switches)
        t_stop = min(s for s in stops if s > t + 1e-14)

        def rhs(tt, ww, mode=mode):
            return solve_mode(chain, tt, ww, mode)[0]

        events = []
        for k in range(m):
            if mode[k] in (1, -1):
                ev = (lambda tt, ww, k=k: chain.w_rel(k, ww))
                ev.terminal, ev.direction = True, -mode[k]
                events.append(("zero", k, ev))
            elif mode[k] == "stuck":
                ev = (lambda tt, ww, k=k, mode=mode: chain.peak * chain.mu * chain.fn[k]
                      - abs(solve_mode(chain, tt, ww, mode)[1][k]))
                ev.terminal, ev.direction = True, -1
                events.append(("load", k, ev))
        sol = solve_ivp(rhs, (t, t_stop), w, method="DOP853", rtol=rtol, atol=atol,
                        events=[e for _, _, e in events] or None, dense_output=True)
        hit = None
        for i, (kind, k, _) in enumerate(events):
            if sol.t_events[i].size and (hit is None or sol.t_events[i][0] < hit[0]):
                hit = (sol.t_events[i][0], kind, k, sol.y_events[i][0])
        t1 = hit[0] if hit else t_stop
        segments.append((t, t1, sol.sol, tuple(mode)))
        t, w = t1, (hit[3].copy() if hit else sol.y[:, -1].copy())
        if hit:
            kind, k = hit[1], hit[2]
            old = mode[k]
            if kind == "zero":
                new = settle(chain, t, w, mode, [k])
            else:
                new = list(mode)
                _, tau = solve_mode(chain, t, w, mode)
                new[k] = 1 if tau[k] > 0 else -1
            before = _momentum(chain, w, new)
            w = _merge(chain, w, new)
            switches.append((t, k, old, new[k], before, _momentum(chain, w, new)))
            mode = new
    return segments, switches


def _engagement(chain, t, w, mode, switches):
    """At a pressing or release time: released elements open, pressed open ones slide
    in the direction of their w_rel (or settle when it is zero), and the stuck ones
    settle again."""
    new = list(mode)
    zero = []
    for k in range(len(mode)):
        pressed = chain.pressed(k, t)
        if not pressed:
            new[k] = "open"
        elif mode[k] == "open":
            wr = chain.w_rel(k, w)
            if abs(wr) > 1e-12:
                new[k] = 1 if wr > 0 else -1
            else:
                zero.append(k)
    if zero or new != list(mode):
        # a stuck element must hold what the new configuration asks of it too
        zero += [k for k in range(len(mode)) if new[k] == "stuck"]
        new = settle(chain, t, w, new, zero)
    for k in range(len(mode)):
        if new[k] != mode[k]:
            switches.append((t, k, mode[k], new[k], None, None))
    return new


def _groups(chain, mode):
    """Inertia index -> group label (stuck clutches merge neighbours)."""
    n = len(chain.J)
    label = list(range(n))
    for k in range(n - 1):
        if mode[k] == "stuck":
            old, new = label[k + 1], label[k]
            label = [new if x == old else x for x in label]
    return label


def _momentum(chain, w, mode):
    """Per group, sum J_i w_i."""
    label = _groups(chain, mode)
    return {g: sum(chain.J[i] * w[i] for i in range(len(w)) if label[i] == g)
            for g in set(label)}


def _merge(chain, w, mode):
    """Each group takes its angular-momentum average speed (a braked group: 0)."""
    label = _groups(chain, mode)
    w = w.copy()
    braked = mode[-1] == "stuck"
    for g in set(label):
        idx = [i for i in range(len(w)) if label[i] == g]
        Jg = sum(chain.J[i] for i in idx)
        wg = sum(chain.J[i] * w[i] for i in idx) / Jg
        if braked and label[len(w) - 1] == g:
            wg = 0.0
        w[idx] = wg
    return w


def speeds(segments, t):
    """w at the times t (each in the segment that contains it)."""
    out = np.empty((len(segments[0][2](segments[0][0])), len(t)))
    for j, tt in enumerate(t):
        for t0, t1, sol, _ in segments:
            if t0 <= tt <= t1:
                out[:, j] = sol(tt)
                break
    return out
