"""StateSpace: a linear time-invariant model x' = A x + B u, y = C x + D u, with names.

What a control engineer asks of a linearized model (Egeland & Gravdahl 1.3, 2.1):

* poles (eigenvalues of A) and transmission zeros (the invariant zeros of the Rosenbrock
  pencil of a minimal realization, by the reduction of Emami-Naeini & Van Dooren 1982);
* transfer functions H(s) = C (sI - A)^-1 B + D as numerator/denominator polynomials
  (Egeland & Gravdahl (1.57)), after removing the uncontrollable and unobservable
  modes (Kalman decomposition by the orthogonal staircase form, Varga 2017 ch. 2), so
  that a motor's free angle does not leave a pole at s = 0 in its speed transfer
  function, and checked against the state-space frequency response;
* step, impulse and frequency responses, Bode plots, and the gain and phase margins of
  a loop transfer function (Egeland & Gravdahl 2.1.4), computed from the polynomials:
  the phase crossovers are the real roots of Im N(jw) D(-jw) and the gain crossovers
  those of |N(jw)|^2 - |D(jw)|^2, so no frequency grid can miss one;
* unity or dynamic feedback, series connection, and conversion to and from
  ``scipy.signal`` objects.

Every rank decision is made on the balanced system, relative to its own norm
(:mod:`.realization`): ill-scaled and closed-loop models give the same answers as
well-scaled ones.
"""
from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
import scipy.linalg as sla

from .realization import (frequency_response, invariant_zeros, minimal_realization, scaled,
                          tf_polynomials)
from ..errors import TransferFunctionWarning

if TYPE_CHECKING:
    import scipy.signal

__all__ = ["StateSpace", "Margins", "TransferFunctionWarning"]


class Margins:
    """Stability margins of a loop transfer function L (Egeland & Gravdahl 2.1.4).

    ``gain`` is 1/|L(j w_180)| at the phase crossover w_180 (inf if the phase never
    reaches -180 deg), ``gain_db`` the same in decibel, ``phase`` 180 + angle L(j w_c) in
    degrees at the gain crossover w_c (inf if |L| never crosses 1).
    """

    def __init__(self, gain, phase, w_180, w_c):
        self.gain, self.phase, self.w_180, self.w_c = gain, phase, w_180, w_c

    @property
    def gain_db(self) -> float:
        return float(20.0 * np.log10(self.gain)) if np.isfinite(self.gain) else np.inf

    def __repr__(self):
        return (f"Margins(gain={self.gain:.6g} ({self.gain_db:.4g} dB) at w_180={self.w_180:.6g}"
                f" rad/s, phase={self.phase:.6g} deg at w_c={self.w_c:.6g} rad/s)")


class StateSpace:
    """x' = A x + B u,  y = C x + D u, with the names of x, u and y.

    Parameters
    ----------
    A, B, C, D : array_like
        The matrices, shapes (n, n), (n, m), (p, n), (p, m).
    states, inputs, outputs : list of str, optional
        Names (default ``x0..``, ``u0..``, ``y0..``).

    Examples
    --------
    >>> sys = StateSpace.from_tf([1.0], [1.0, 3.0, 2.0])
    >>> np.sort(sys.poles().real)
    array([-2., -1.])
    """

    def __init__(self, A, B, C, D=None, states=None, inputs=None, outputs=None):
        self.A = np.atleast_2d(np.asarray(A, dtype=float))
        n = self.A.shape[0] if self.A.size else 0
        self.A = self.A.reshape(n, n)
        self.B = np.asarray(B, dtype=float).reshape(n, -1) if n else np.zeros((0, _cols(B)))
        self.C = np.asarray(C, dtype=float).reshape(-1, n) if n else np.zeros((_rows(C), 0))
        p, m = self.C.shape[0], self.B.shape[1]
        self.D = np.zeros((p, m)) if D is None else np.asarray(D, dtype=float).reshape(p, m)
        self.states = list(states) if states is not None else [f"x{k}" for k in range(n)]
        self.inputs = list(inputs) if inputs is not None else [f"u{k}" for k in range(m)]
        self.outputs = list(outputs) if outputs is not None else [f"y{k}" for k in range(p)]

    # -- shape and selection --------------------------------------------------------------
    @property
    def n_states(self) -> int:
        return self.A.shape[0]

    @property
    def n_inputs(self) -> int:
        return self.B.shape[1]

    @property
    def n_outputs(self) -> int:
        return self.C.shape[0]

    def select(self, outputs=None, inputs=None) -> "StateSpace":
        """The sub-system from some inputs to some outputs (names or indices)."""
        oi = _indices(outputs, self.outputs)
        ii = _indices(inputs, self.inputs)
        return StateSpace(self.A, self.B[:, ii], self.C[oi], self.D[np.ix_(oi, ii)],
                          self.states, [self.inputs[k] for k in ii],
                          [self.outputs[k] for k in oi])

    def __getitem__(self, key) -> "StateSpace":
        """``sys["w", "u"]``: the channel from input "u" to output "w"."""
        out, inp = key
        return self.select([out] if isinstance(out, (str, int)) else out,
                           [inp] if isinstance(inp, (str, int)) else inp)

    # -- structure ------------------------------------------------------------------------
    def poles(self) -> np.ndarray:
        """Eigenvalues of A, sorted by real part then imaginary part."""
        return _sorted(np.linalg.eigvals(self.A)) if self.n_states else np.zeros(0, complex)

    def is_stable(self) -> bool:
        """Asymptotic stability: every pole in the open left half plane (1.45)."""
        return bool(np.all(self.poles().real < 0.0))

    def minimal(self, tol: float | None = None) -> "StateSpace":
        """A minimal realization: the controllable and observable part (Kalman).

        Computed on the balanced system (:mod:`.realization`), with rank decisions
        relative to its own norm (``tol``, default n 1e-10), so the units of the states
        do not change the answer.  The new states are x = T x_m with T a diagonal
        scaling times orthonormal columns; each is named after the original state that
        weighs most in it (in the balanced coordinates).
        """
        if self.n_states == 0:
            return self
        A, B, C, _, Q = minimal_realization(self.A, self.B, self.C, self.D, tol)
        names = [self.states[int(np.argmax(np.abs(Q[:, k])))] for k in range(Q.shape[1])]
        return StateSpace(A, B, C, self.D, names, self.inputs, self.outputs)

    def zeros(self) -> np.ndarray:
        """Transmission zeros of a square system: the invariant zeros of a minimal
        realization (Emami-Naeini & Van Dooren 1982, see :mod:`.realization`).  Select
        a square sub-system with ``select`` first.  A channel that is identically zero
        has no zeros defined: ValueError."""
        if self.n_outputs != self.n_inputs:
            raise ValueError(f"transmission zeros need as many outputs as inputs (this "
                             f"system has {self.n_outputs} outputs, {self.n_inputs} inputs); "
                             "choose channels with select(outputs=..., inputs=...)")
        if self.n_inputs == 0:
            return np.zeros(0, complex)
        sys = self.minimal()
        return _sorted(invariant_zeros(sys.A, sys.B, sys.C, sys.D))

    # -- transfer functions -----------------------------------------------------------------
    def tf(self, output=None, input=None, minimal: bool = True):  # noqa: A002 (control naming)
        """Numerator and denominator of one transfer function, highest power first.

        ``minimal=True`` cancels the modes the channel cannot see (exactly, by a minimal
        realization, not by matching roots), so the degree is that of the channel;
        ``minimal=False`` keeps every mode of A (common factors stay in num and den).
        The denominator is monic.  num = k prod(s - z_i) from the invariant zeros and
        the first non-zero Markov parameter, rather than ss2tf's difference of
        characteristic polynomials, whose cancelled leading terms leave round-off
        coefficients behind.  The result is checked against the state-space frequency
        response; if it does not match, the numerator is recomputed by interpolation
        and a ``TransferFunctionWarning`` is issued (:mod:`.realization`).
        """
        sys = self.select([_default(output, self.outputs, "output")],
                          [_default(input, self.inputs, "input")])
        if minimal:
            sys = sys.minimal()
        return tf_polynomials(sys.A, sys.B, sys.C, sys.D,
                              what=f"{sys.outputs[0]} / {sys.inputs[0]}")

    def transfer_functions(self, minimal: bool = True) -> dict:
        """Every channel's (num, den), keyed by (output name, input name)."""
        return {(o, i): self.tf(o, i, minimal) for o in self.outputs for i in self.inputs}

    def dcgain(self) -> np.ndarray:
        """H(0) = D - C A^-1 B (p x m) of a minimal realization (so that modes the
        outputs do not see, such as a free angle, do not make A singular).  A pole at
        s = 0 that the outputs do see makes H(0) infinite: ValueError."""
        sys = self.minimal()
        if sys.n_states == 0:
            return sys.D.copy()
        A, B, C, D, _, bu, cy = scaled(sys.A, sys.B, sys.C, sys.D)
        poles = np.linalg.eigvals(A)
        if np.min(np.abs(poles)) <= 1e3 * np.finfo(float).eps * np.linalg.norm(A, 2):
            raise ValueError("dcgain: a pole at s = 0 is seen by the outputs, H(0) is "
                             f"infinite (poles {sys.poles()})")
        H0 = D - C @ np.linalg.solve(A, B)
        return H0 / cy[:, None] / bu

    def freqresp(self, w) -> np.ndarray:
        """H(j w) for each w: shape (len(w), p, m), or (len(w),) for one channel.
        Evaluated on the balanced system, so ill-scaled states cost no accuracy."""
        w = np.atleast_1d(np.asarray(w, dtype=float))
        A, B, C, D, _, bu, cy = scaled(self.A, self.B, self.C, self.D)
        H = frequency_response(A, B, C, D, w) / cy[None, :, None] / bu[None, None, :]
        return H[:, 0, 0] if H.shape[1:] == (1, 1) else H

    # -- time responses ---------------------------------------------------------------------
    def step(self, t=None, input=None):  # noqa: A002
        """Response y(t) to a unit step in one input from x = 0 (exact for the grid).

        Returns (t, y) with y of shape (len(t), p)."""
        t = self._time_grid(t)
        j = _indices([_default(input, self.inputs, "input")], self.inputs)[0]
        u = np.ones(len(t))
        return t, self._zoh(t, self.B[:, j], self.D[:, j], u, np.zeros(self.n_states))

    def impulse(self, t=None, input=None):  # noqa: A002
        """Response y(t) = C e^{At} B to a unit impulse in one input (D's impulse dropped)."""
        t = self._time_grid(t)
        j = _indices([_default(input, self.inputs, "input")], self.inputs)[0]
        x0 = self.B[:, j]
        y = np.array([self.C @ (sla.expm(self.A * tk) @ x0) for tk in t])
        return t, y.reshape(len(t), self.n_outputs)

    def _zoh(self, t, b, d, u, x0):
        """Exact zero-order-hold propagation on a uniform grid (augmented expm)."""
        n = self.n_states
        dt = t[1] - t[0] if len(t) > 1 else 0.0
        if not np.allclose(np.diff(t), dt, rtol=1e-9, atol=0):
            raise ValueError("step(): t must be uniformly spaced")
        M = np.zeros((n + 1, n + 1))
        M[:n, :n], M[:n, n] = self.A, b
        E = sla.expm(M * dt)
        Ad, bd = E[:n, :n], E[:n, n]
        x, ys = np.array(x0, dtype=float), []
        for uk in u:
            ys.append(self.C @ x + d * uk)
            x = Ad @ x + bd * uk
        return np.array(ys).reshape(len(t), self.n_outputs)

    def _time_grid(self, t):
        if t is not None:
            return np.asarray(t, dtype=float)
        re = np.abs(self.poles().real)
        re = re[re > 1e-12 * max(1.0, re.max(initial=0.0))]
        t_end = 7.0 / re.min() if re.size else 10.0
        return np.linspace(0.0, t_end, 1001)

    # -- frequency-domain design ------------------------------------------------------------
    def bode(self, w=None, output=None, input=None, ax=None, plot=False):  # noqa: A002
        """Magnitude [dB] and phase [deg] (unwrapped) of one channel at frequencies w.

        ``plot=True`` or an ``ax`` (a pair of matplotlib axes) draws the Bode plot;
        matplotlib is imported only then.  Returns (w, mag_db, phase_deg).
        """
        sys = self.select([_default(output, self.outputs, "output")],
                          [_default(input, self.inputs, "input")])
        w = sys._frequency_grid() if w is None else np.asarray(w, dtype=float)
        H = sys.freqresp(w)
        with np.errstate(divide="ignore"):   # a channel that is zero has -inf dB, as it is
            mag = 20.0 * np.log10(np.abs(H))
        phase = np.degrees(np.unwrap(np.angle(H)))
        if plot or ax is not None:
            _bode_plot(w, mag, phase, ax, f"{sys.outputs[0]} / {sys.inputs[0]}")
        return w, mag, phase

    def _frequency_grid(self):
        try:
            zeros = self.zeros() if self.n_inputs == self.n_outputs else []
        except ValueError:                 # a channel that is identically zero
            zeros = []
        mags = np.abs(np.concatenate([self.poles(), zeros]))
        mags = mags[mags > 0]
        lo = np.log10(mags.min()) - 2 if mags.size else -2
        hi = np.log10(mags.max()) + 2 if mags.size else 2
        return np.logspace(lo, hi, 2000)

    def margins(self, output=None, input=None) -> Margins:  # noqa: A002
        """Gain and phase margins of this system taken as a loop transfer function L(s)
        (negative feedback); crossover frequencies from exact polynomial roots."""
        sys = self.select([_default(output, self.outputs, "output")],
                          [_default(input, self.inputs, "input")])
        num, den = sys.tf()

        def L(w):    # the model's own realization: exact where the polynomials round off
            return complex(sys.freqresp([w])[0])

        w180 = [_polish(lambda w: L(w).imag, w) for w in
                _positive_real_roots(_imag_of_product(num, den))]
        w180 = [w for w in w180 if L(w).real < 0]
        gains = [1.0 / abs(L(w)) for w in w180]
        wc = [_polish(lambda w: abs(L(w)) - 1.0, w) for w in
              _positive_real_roots(_gain_crossover_poly(num, den))]
        phases = [_wrap180(180.0 + np.degrees(np.angle(L(w)))) for w in wc]
        k = int(np.argmin(gains)) if gains else None
        q = int(np.argmin(np.abs(phases))) if phases else None
        return Margins(gains[k] if k is not None else np.inf,
                       phases[q] if q is not None else np.inf,
                       w180[k] if k is not None else np.nan,
                       wc[q] if q is not None else np.nan)

    # -- interconnection --------------------------------------------------------------------
    def feedback(self, other=1.0, sign: int = -1) -> "StateSpace":
        """Closed loop u = r + sign * other(y); ``other`` a StateSpace or a gain."""
        K = other if isinstance(other, StateSpace) else _static(other, self.n_outputs,
                                                                 self.n_inputs)
        A1, B1, C1, D1 = self.A, self.B, self.C, self.D
        A2, B2, C2, D2 = K.A, K.B, K.C, K.D
        E = np.linalg.inv(np.eye(self.n_outputs) - sign * D1 @ D2)
        Cy = E @ np.hstack([C1, sign * D1 @ C2])          # y = Cy x + Dy r
        Dy = E @ D1
        Cu = sign * np.hstack([D2 @ Cy[:, : len(A1)], C2 + D2 @ Cy[:, len(A1):]])
        Du = np.eye(self.n_inputs) + sign * D2 @ Dy       # u = Cu x + Du r
        A = np.block([[A1, np.zeros((len(A1), len(A2)))],
                      [B2 @ Cy[:, : len(A1)], A2 + B2 @ Cy[:, len(A1):]]])
        A[: len(A1)] += B1 @ Cu
        B = np.vstack([B1 @ Du, B2 @ Dy])
        return StateSpace(A, B, Cy, Dy, self.states + K.states, self.inputs, self.outputs)

    def series(self, other: "StateSpace") -> "StateSpace":
        """``other`` after ``self``: y = other(self(u))."""
        n1 = self.n_states
        A = np.block([[self.A, np.zeros((n1, other.n_states))],
                      [other.B @ self.C, other.A]])
        B = np.vstack([self.B, other.B @ self.D])
        C = np.hstack([other.D @ self.C, other.C])
        return StateSpace(A, B, C, other.D @ self.D, self.states + other.states,
                          self.inputs, other.outputs)

    # -- conversion -------------------------------------------------------------------------
    def to_scipy(self) -> scipy.signal.StateSpace:
        """The ``scipy.signal.StateSpace`` (continuous-time) of the same matrices."""
        import scipy.signal    # slow to import (it brings scipy.stats): only here
        return scipy.signal.StateSpace(self.A, self.B, self.C, self.D)

    @classmethod
    def from_scipy(cls, system, states=None, inputs=None, outputs=None) -> "StateSpace":
        """From any continuous ``scipy.signal`` LTI object (tf, zpk or ss)."""
        s = system.to_ss()
        return cls(s.A, s.B, s.C, s.D, states, inputs, outputs)

    @classmethod
    def from_tf(cls, num, den, **names) -> "StateSpace":
        """From a SISO numerator and denominator, highest power first (a constant
        gives a static system without states)."""
        den = np.trim_zeros(np.atleast_1d(np.asarray(den, dtype=float)), "f")
        if len(den) == 1:
            k = np.atleast_1d(np.asarray(num, dtype=float))
            if len(np.trim_zeros(k, "f")) > 1:
                raise ValueError("from_tf: num has a higher degree than den (improper)")
            return cls(np.zeros((0, 0)), np.zeros((0, 1)), np.zeros((1, 0)),
                       [[k[-1] / den[0]]], **names)
        from scipy.signal import tf2ss
        A, B, C, D = tf2ss(num, den)
        return cls(A, B, C, D, **names)

    def __repr__(self):
        return (f"<StateSpace {self.n_states} states {self.states}, inputs {self.inputs}, "
                f"outputs {self.outputs}>")


# -- helpers ----------------------------------------------------------------------------------
def _rows(M):
    return np.atleast_2d(np.asarray(M, dtype=float)).shape[0]


def _cols(M):
    return np.atleast_2d(np.asarray(M, dtype=float)).shape[1]


def _indices(keys, names):
    if keys is None:
        return list(range(len(names)))
    out = []
    for k in keys:
        if isinstance(k, (int, np.integer)):
            out.append(int(k))
        elif k in names:
            out.append(names.index(k))
        else:
            raise KeyError(f"'{k}' is not one of {names}")
    return out


def _default(key, names, what):
    if key is not None:
        return key
    if len(names) != 1:
        raise ValueError(f"the system has {len(names)} {what}s ({names}): name the {what}")
    return 0


def _sorted(values):
    v = np.asarray(values, dtype=complex)
    return v[np.lexsort((v.imag, v.real))]


def _static(k, p, m):
    K = np.atleast_2d(np.asarray(k, dtype=float))
    if K.size == 1:
        K = K[0, 0] * np.eye(p) if p == m else np.full((m, p), K[0, 0])
    return StateSpace(np.zeros((0, 0)), np.zeros((0, p)), np.zeros((m, 0)), K.reshape(m, p))


def _jw_poly(c):
    """Coefficients (highest first) of c(j w) as a complex polynomial in w."""
    deg = len(c) - 1
    return np.array([ck * (1j) ** (deg - k) for k, ck in enumerate(c)])


def _imag_of_product(num, den):
    """Im N(jw) D(-jw): zero exactly where the phase of N/D is 0 or -180 deg."""
    p = np.polymul(_jw_poly(num), np.conj(_jw_poly(den)))
    return np.real_if_close(p.imag)


def _gain_crossover_poly(num, den):
    """|N(jw)|^2 - |D(jw)|^2 as a real polynomial in w."""
    n, d = _jw_poly(num), _jw_poly(den)
    return np.polysub(np.polymul(n, np.conj(n)), np.polymul(d, np.conj(d))).real


def _positive_real_roots(c):
    c = np.trim_zeros(np.asarray(c, dtype=float), "f")
    if c.size < 2:
        return []
    c = np.where(np.abs(c) < 1e-14 * np.abs(c).max(), 0.0, c)
    r = np.roots(np.trim_zeros(c, "f"))
    return sorted(float(x.real) for x in r
                  if abs(x.imag) <= 1e-7 * max(abs(x), 1.0) and x.real > 1e-12)


def _polish(f, w0, rel=1e-6):
    """Refine a root w0 of f by bisection in [w0 (1 - rel), w0 (1 + rel)] if bracketed."""
    import scipy.optimize as so
    a, b = w0 * (1 - rel), w0 * (1 + rel)
    if np.sign(f(a)) * np.sign(f(b)) < 0:
        return float(so.brentq(f, a, b, xtol=1e-15 * w0, rtol=4 * np.finfo(float).eps))
    return w0


def _wrap180(deg):
    return (deg + 180.0) % 360.0 - 180.0


def _bode_plot(w, mag, phase, ax, title):
    try:
        import matplotlib.pyplot as plt
    except ImportError as err:
        raise ImportError("bode(plot=True) needs matplotlib: pip install 'acausal[plot]'") \
            from err
    if ax is None:
        _, ax = plt.subplots(2, 1, sharex=True, figsize=(7, 5))
    ax[0].semilogx(w, mag)
    ax[0].set_ylabel("magnitude [dB]")
    ax[0].set_title(title)
    ax[1].semilogx(w, phase)
    ax[1].set_ylabel("phase [deg]")
    ax[1].set_xlabel("frequency [rad/s]")
    for a in ax:
        a.grid(True, which="both", alpha=0.3)
    return ax
