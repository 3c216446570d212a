"""Stability limit detection for BDF orders 3-5 (STALD).

BDF methods of orders 1 and 2 are A-stable; orders 3-5 are only A(alpha)-stable: their
regions of absolute stability leave out a neighbourhood of the imaginary axis near the
origin.  A lightly damped or undamped oscillatory mode with ``h*lambda`` in that gap is
amplified by the method instead of damped.  If its amplitude is small (a high mode of
a lumped line, excited to about the tolerance), the local error test does not ask to
resolve it, yet it cannot be left to decay either: the error control settles on the
step that keeps that mode at the edge of the stability region, and the integration
crawls (hundreds of steps per period of the *slowest* mode).  Lowering the order to one
whose stability region contains the mode lets it decay and the step grow.

The detector is Hindmarsh's STALD, as in CVODE (Hindmarsh, "Detecting stability
barriers in BDF solvers", in *Computational Ordinary Differential Equations*, Cash &
Gladwell eds., 1992; Hindmarsh et al., "SUNDIALS", ACM TOMS 31, 2005; the CVODE user
guide, "BDF stability limit detection").  Over the last five steps at order q it keeps
the squared weighted norms of the scaled derivatives of orders q-1, q and q+1,
``s_k = ||h^k y^(k)||^2``.  If one mode of characteristic root r dominates them, all
three sequences decrease (or grow) geometrically with the same ratio ``rr = |r|^2``;
rr is found from the ratios directly when they are consistent, otherwise as the
common root of three quartics, refined by Newton.  It is then checked against the
value the order-q BDF theory gives for the variances ``sigma_k^2`` of the three
sequences, and a verified ``rr > 0.98`` means the step is stability-limited (CVODE
then lowers the order by one; what :class:`acausal.solvers.bdf.BDF` does is said
there).

A dominant root of modulus ~1 does not tell a mode excited to about the tolerance,
which is better damped at a low order, from one of large amplitude resolved on
purpose, which needs the high orders: BDF asks in addition that order q-1 meet the
tolerance at the current step, and lifts the cap when the low order fails the error
test.  Even so the detection is a heuristic, off by default.

Here the history is kept as divided differences, not as a Nordsieck array.  With a
constant step after the step ``phi[j] = nabla^j y_n``, the backward differences, so
``h^q y^(q) = phi[q]``, ``h^(q+1) y^(q+1) = phi[q+1]`` (the corrector's correction) and,
from the Newton backward form ``p(t_n + s h) = sum_j binom(s+j-1, j) nabla^j y_n``,
``h^(q-1) y^(q-1) = phi[q-1] + (q-1)/2 phi[q]``.
"""
from __future__ import annotations

import numpy as np

__all__ = ["StabilityLimitDetector"]

_TINY = 1e-10
_RRCUT = 0.98      # a verified dominant root above this limits the step (CVODE)
_VRRTOL = 1e-4     # ratios this consistent give rr directly ...
_VRRT2 = 5e-4      # ... and must then agree to this between the three orders
_SQTOL = 1e-3      # residual accepted for the common root of the quartics
_RRTOL = 1e-2      # agreement of rr with its value from the sigma_k^2


class StabilityLimitDetector:
    """Collects the scaled-derivative norms of consecutive steps and tells when the
    step at order q >= 3 is limited by stability rather than accuracy."""

    def __init__(self):
        self.reset()

    def reset(self) -> None:
        """Forget the history (after a restart or a change of order)."""
        self.order = 0
        self.nscon = 0          # consecutive steps at ``order``
        self.ssdat = []         # newest first: (s_{q-1}, s_q, s_{q+1})

    def record(self, q: int, phi: np.ndarray, ee: np.ndarray, w: np.ndarray) -> None:
        """Note the step just completed at order ``q`` (``phi`` already updated)."""
        if q != self.order:
            self.order, self.nscon, self.ssdat = q, 0, []
        self.nscon += 1
        if q < 3:
            return
        n = w.size

        def sq(v):
            x = v * w
            return x.dot(x) / n

        self.ssdat.insert(0, (sq(phi[q - 1] + 0.5 * (q - 1) * phi[q]), sq(phi[q]), sq(ee)))
        del self.ssdat[5:]

    def limited(self) -> bool:
        """True if the last five steps show a stability-limited step (rr > 0.98)."""
        q = self.order
        if q < 3 or self.nscon < q + 5 or len(self.ssdat) < 5:
            return False
        rr = _dominant_root(np.array(self.ssdat).T, q)
        return rr is not None and rr > _RRCUT


def _dominant_root(s: np.ndarray, q: int):
    """rr from ``s[k, i]`` (k: order q-1, q, q+1; i: steps back), verified; else None.

    Follows CVODE's ``cvSLdet``: the sequences are modelled as
    ``s[k, i] = sigma_k^2 rr^(-i) + (terms decaying faster)``.
    """
    smax = s.max(axis=1)
    if np.any(s.min(axis=1) < _TINY * smax):
        return None
    rat = s[:, :4] / s[:, 1:]
    rav = rat.mean(axis=1)
    vrat = np.abs((rat * rat).mean(axis=1) - rav * rav)
    # coefficients of the quartics  qc5 + qc4 r + qc2 r^3 + qc1 r^4  whose common root
    # is rr when one mode dominates (CVODE's qc[5..1]; qc3 = 0)
    qc5 = s[:, 0] * s[:, 2] - s[:, 1] ** 2
    qc4 = s[:, 1] * s[:, 2] - s[:, 0] * s[:, 3]
    qc2 = s[:, 1] * s[:, 4] - s[:, 2] * s[:, 3]
    qc1 = s[:, 3] ** 2 - s[:, 2] * s[:, 4]
    ssmax = smax * smax
    if vrat.min() < _VRRTOL ** 2:
        # nearly normal case: the three ratio sequences are (nearly) constant
        if vrat.max() > _VRRT2 ** 2:
            return None
        rr = rav.mean()
        if np.abs(rav - rr).max() > _VRRT2:
            return None
    else:
        rr = _quartic_root(qc1, qc2, qc4, qc5, ssmax)
        if rr is None:
            return None
    return rr if _verified(s, smax, rr, q) else None


def _quartic_root(qc1, qc2, qc4, qc5, ssmax):
    """Common root of the three quartics by elimination, refined by Newton."""
    Q = np.array([qc1, qc2, np.zeros(3), qc4, qc5])     # Q[i, k], i: qc1..qc5
    if abs(Q[0, 0]) < _TINY * ssmax[0]:
        return None
    for k in (1, 2):
        Q[1:, k] -= (Q[0, k] / Q[0, 0]) * Q[1:, 0]
        Q[0, k] = 0.0
    if abs(Q[1, 1]) < _TINY * ssmax[1]:
        return None
    Q[2:, 2] -= (Q[1, 2] / Q[1, 1]) * Q[2:, 1]
    if abs(Q[3, 2]) < _TINY * ssmax[2]:
        return None
    rr = -Q[4, 2] / Q[3, 2]
    if not _TINY <= rr <= 100.0:
        return None

    def resid(r):
        qk = qc5 + r * (qc4 + r * r * (qc2 + r * qc1))
        return qk, np.abs(qk) / ssmax

    qkr, sc = resid(rr)
    if sc.max() < _SQTOL:
        return rr
    for _ in range(3):
        qp = qc4 + rr * rr * (3.0 * qc2 + 4.0 * rr * qc1)
        drr = np.where(np.abs(qp) > _TINY * ssmax, -qkr / np.where(qp == 0, 1.0, qp), 0.0)
        cands = rr + drr
        fits = [resid(c) for c in cands]
        kmin = int(np.argmin([f[1].max() for f in fits]))
        rr = cands[kmin]
        qkr, sc = fits[kmin]
        if sc.max() < _SQTOL:
            return rr
    return None


def _verified(s, smax, rr, q) -> bool:
    """Check rr against the sigma_k^2 that BDF of order q implies (CVODE's last part)."""
    sig = np.empty(3)
    for k in range(3):
        rs = s[k, :4] * rr ** np.arange(4)
        d1 = rs[:-1] - rs[1:]
        d2 = d1[:-1] - d1[1:]
        d3 = d2[0] - d2[1]
        if abs(d1[1]) < _TINY * smax[k]:
            return False
        cest = -d3 / d1[1]
        if not _TINY <= cest <= 4.0:
            return False
        sig[k] = s[k, 2] + (d2[1] / cest) / (rr * rr)
    if sig[1] < _TINY:
        return False
    ratp, ratm = sig[2] / sig[1], sig[0] / sig[1]
    bb = ratp * ratm - 1.0 - 0.25 * (q * q - 1) * ratp
    tem = 1.0 - 2.0 / (q - 1) * bb
    if abs(tem) < _TINY:
        return False
    return abs(1.0 / tem - rr) <= _RRTOL
