"""Time delays (Modelica.Blocks.Nonlinear.PadeDelay and FixedDelay).

``PadeDelay`` replaces exp(-s T) by its [m/n] Padé approximant, a rational transfer
function with n states: an ordinary linear block, which linearizes, exports and runs
like any other.  ``FixedDelay`` is the exact delay y(t) = u(t - T) of Modelica's
``delay()`` operator (``ac.delay``), read from the history the runtime keeps of u.
"""
from __future__ import annotations

from fractions import Fraction
from math import factorial

import numpy as np

import acausal as ac

from .interfaces import SISO

__all__ = ["PadeDelay", "FixedDelay", "pade_coefficients"]


def pade_coefficients(n: int, m: int | None = None) -> tuple[list, list]:
    """The [m/n] Padé approximant of exp(-z) as exact fractions, lowest power first:

        exp(-z) ~ P_m(z) / Q_n(z),
        P_m(z) = sum_k  (m+n-k)! m! / ((m+n)! k! (m-k)!)  (-z)^k,   k = 0..m,
        Q_n(z) = sum_k  (m+n-k)! n! / ((m+n)! k! (n-k)!)    z^k,    k = 0..n

    (Baker & Graves-Morris, *Padé Approximants*, 2nd ed. 1996, sec. 1.2), so that
    P(sT)/Q(sT) approximates the delay exp(-sT); its error is O(z^(m+n+1)).
    """
    m = n if m is None else m
    num = [Fraction(factorial(m + n - k) * factorial(m),
                    factorial(m + n) * factorial(k) * factorial(m - k)) * (-1) ** k
           for k in range(m + 1)]
    den = [Fraction(factorial(m + n - k) * factorial(n),
                    factorial(m + n) * factorial(k) * factorial(n - k))
           for k in range(n + 1)]
    return num, den


def _balanced_realization(n: int, m: int):
    """(A, B, C, D) of P(z)/Q(z) in the scaled time z-domain (d/d tau, tau = t/T):
    the controllable canonical form, its states then scaled by a diagonal similarity
    (scipy.linalg.matrix_balance, powers of 2, exact) so that the rows and columns of A
    have comparable norms.  The companion coefficients q_k/q_n of the Padé denominator
    grow like (2n)!/n!: unscaled, a [10/10] form spans 12 orders of magnitude."""
    from scipy.linalg import matrix_balance
    p, q = pade_coefficients(n, m)
    alpha = [float(c / q[n]) for c in q]                  # monic denominator, alpha[n] = 1
    beta = [float(c / q[n]) for c in p] + [0.0] * (n - m)
    A = np.zeros((n, n))
    A[np.arange(n - 1), np.arange(1, n)] = 1.0            # x_k' = x_{k+1}
    A[n - 1, :] = [-a for a in alpha[:n]]                 # x_n' = -sum alpha_k x_k + u
    B = np.zeros(n)
    B[n - 1] = 1.0
    D = beta[n]
    C = np.array([beta[k] - alpha[k] * D for k in range(n)])
    _, (scale, _) = matrix_balance(A, permute=False, separate=True)
    # x = S x_s:  x_s' = S^-1 A S x_s + S^-1 B u,   y = C S x_s + D u
    return A * scale[None, :] / scale[:, None], B / scale, C * scale, D


class _PadeState(ac.Component):
    """One state of a PadeDelay (scaled, dimensionless time)."""

    x = ac.Variable(start=0.0, description="state of the balanced canonical form")


class PadeDelay(SISO):
    """Padé approximation of a delay, y ~ exp(-s delayTime) u (after the MSL's
    Modelica.Blocks.Nonlinear.PadeDelay with ``balance = true``):

        y = P_m(s T) / Q_n(s T) u,    T = delayTime

    with P, Q the [m/n] Padé polynomials of :func:`pade_coefficients`.  In the time
    tau = t/T the coefficients are pure numbers, computed when the block is built, so
    the realization is

        T der(x) = A x + B u,    y = C x + D u

    (controllable canonical form, states scaled by a diagonal balancing similarity as
    the MSL does for conditioning; ``delayTime`` stays a tunable parameter).  ``n`` is
    the order of the denominator (the number of states), ``m <= n`` that of the
    numerator, default ``m = n``: then |G(j w)| = 1 at every frequency (the numerator's
    roots are the denominator's mirrored, an all-pass) and the phase is -w T to
    O((w T)^(2n+1)); ``m = n - 1`` gives a strictly proper block.  ``n`` and ``m`` are
    structural: plain integers fixed when the block is created.

    Examples
    --------
    >>> block = PadeDelay(n=3, delayTime=0.5)
    >>> len(block.state)
    3
    """

    delayTime = ac.Parameter(1.0, unit="s", min=0, description="delay time T")

    def __init__(self, n: int = 1, m: int | None = None, **mods):
        super().__init__(**mods)
        m = n if m is None else m
        for name, value in (("n", n), ("m", m)):
            if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
                raise ac.ModelError(f"PadeDelay: {name} must be an integer, got {value!r}")
        if not 1 <= n <= 20:
            raise ac.ModelError(f"PadeDelay: the order n must be from 1 to 20, got {n}")
        if not 0 <= m <= n:
            raise ac.ModelError(f"PadeDelay: the numerator order m must be from 0 to n = "
                                f"{n}, got {m}")
        self.n, self.m = int(n), int(m)
        self.A, self.B, self.C, self.D = _balanced_realization(self.n, self.m)
        self.state = [_PadeState() for _ in range(self.n)]

    def equations(self):
        x = [cell.x for cell in self.state]
        u = self.u.signal
        eqs = []
        for i in range(self.n):
            rhs = sum(float(a) * x[j] for j, a in enumerate(self.A[i]) if a != 0.0)
            if self.B[i] != 0.0:
                rhs = rhs + float(self.B[i]) * u
            eqs.append(ac.Eq(self.delayTime * ac.der(x[i]), rhs))
        y = sum(float(c) * x[j] for j, c in enumerate(self.C) if c != 0.0)
        return eqs + [ac.Eq(self.y, y + float(self.D) * u)]


class FixedDelay(SISO):
    """Exact delay of the input by a fixed time, after the MSL's FixedDelay
    (Modelica.Blocks.Nonlinear):

        y = delay(u, delayTime),   i.e.  y(t) = u(t - delayTime),  y(t) = u(t0) for
        t < t0 + delayTime   (Modelica Language Specification 3.7.2.2)

    The runtime keeps a history of u (:mod:`acausal.runtime.delays`): the integrator's
    step is limited to ``delayTime``, so a short delay in a long run costs steps
    (at least (t_end - t0)/delayTime); a jump of u at t1 reappears at t1 + delayTime as
    a time event.  A model with a FixedDelay has no finite-dimensional linearization
    and cannot be exported as an FMU; ``PadeDelay`` approximates it with n states.
    """

    delayTime = ac.Parameter(1.0, unit="s", min=0, description="delay time T (> 0)")

    def equations(self):
        return [ac.Eq(self.y, ac.delay(self.u.signal, self.delayTime))]
