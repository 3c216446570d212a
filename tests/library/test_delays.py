"""Delays: PadeDelay against the closed-form Padé polynomials and the Lambert-W roots
of the delayed feedback loop's characteristic equation.

References: the [m/n] Padé approximant of exp(-z) and its error constant (Baker &
Graves-Morris, *Padé Approximants*, 2nd ed. 1996, sec. 1.2); the characteristic
equation s + a exp(-sT) = 0 of x' = -a x(t - T), whose roots are s = W_k(-aT)/T
(Asl & Ulsoy 2003, J. Dyn. Sys. Meas. Control 125: 215-223).
"""
from math import factorial

import numpy as np
import pytest
from scipy.special import lambertw

import acausal as ac
from acausal.library import blocks as bl
from acausal.library.blocks.delays import pade_coefficients
from acausal.ports import RealInput


class OpenPade(ac.Component):
    """A PadeDelay driven by a top-level input (for its transfer function)."""

    u = RealInput()

    def __init__(self, n, m=None, T=0.5, **mods):
        super().__init__(**mods)
        self.pade = bl.PadeDelay(n=n, m=m, delayTime=T)

    def equations(self):
        return [ac.connect(self.u, self.pade.u)]


class PadeLoop(ac.Component):
    """x' = -a y,  y = PadeDelay(x): the delayed loop x' = -a x(t - T), approximated."""

    def __init__(self, n, a=1.0, T=1.0, **mods):
        super().__init__(**mods)
        self.integ = bl.Integrator(k=-a, x={"start": 1.0})
        self.pade = bl.PadeDelay(n=n, delayTime=T)

    def equations(self):
        return [ac.connect(self.integ.y, self.pade.u), ac.connect(self.pade.y, self.integ.u)]


def _roots(coeffs_low_first, T):
    return np.sort_complex(np.roots([float(c) for c in coeffs_low_first[::-1]]) / T)


def _match(a, b):
    """Largest distance from a root in a to its nearest in b, relative to max |b|."""
    return max(np.min(np.abs(b - x)) for x in a) / np.max(np.abs(b))


@pytest.mark.parametrize("n,m", [(1, 1), (3, 3), (6, 6), (10, 10), (4, 3), (5, 2)])
def test_pade_poles_and_zeros_are_the_pade_polynomial_roots(n, m):
    T = 0.5
    sys = ac.linearize(OpenPade(n, m, T), ["u"], ["pade.y.signal"])
    p, q = pade_coefficients(n, m)
    assert sys.n_states == n
    assert _match(sys.poles(), _roots(q, T)) < 1e-10
    assert _match(_roots(q, T), sys.poles()) < 1e-10
    # numpy.roots of the numerator is itself ill-conditioned at high order (~1e-11)
    assert _match(sys.zeros(), _roots(p, T)) < 1e-9
    assert _match(_roots(p, T), sys.zeros()) < 1e-9
    # the gain at s = 0 is exp(0) = 1
    assert sys.dcgain()[0, 0] == pytest.approx(1.0, rel=1e-12)


@pytest.mark.parametrize("n,wT", [(1, 0.1), (2, 0.2), (3, 0.5), (4, 1.0), (8, None)])
def test_pade_nn_is_all_pass_with_the_delay_phase(n, wT):
    """|G(jw)| = 1 at all frequencies; the phase error against -wT at low frequency is
    the Padé error constant, (n!)^2 / ((2n)! (2n+1)!) (wT)^(2n+1), to a relative
    O((wT)^2) (the next term of the series: 0.15 (wT)^2 for n = 1, less for larger n;
    wT is chosen per n to keep the error far above round-off)."""
    T = 0.5
    sys = ac.linearize(OpenPade(n, None, T), ["u"], ["pade.y.signal"])
    w = np.logspace(-2, 3, 60) / T
    assert np.max(np.abs(np.abs(sys.freqresp(w)) - 1.0)) < 1e-12
    if wT is None:                   # n = 8: the error is below round-off for wT <~ 2
        return
    H = sys.freqresp([wT / T])[0]
    err = abs(np.angle(H * np.exp(1j * wT)))     # phase of G relative to exp(-j w T)
    c = factorial(n) ** 2 / (factorial(2 * n) * factorial(2 * n + 1))
    assert err == pytest.approx(c * wT ** (2 * n + 1), rel=0.2 * wT ** 2)


def test_pade_loop_poles_converge_to_lambert_w_root():
    """The rightmost root of s + a exp(-sT) = 0 is W_0(-aT)/T; the PadeDelay loop's
    nearest pole converges to it as n grows (super-geometrically: the Padé error is
    O(z^(2n+1)) with factorially small constants)."""
    a, T = 1.0, 1.0
    s0 = complex(lambertw(-a * T, 0)) / T
    errors = []
    for n in (1, 2, 3, 4, 6):
        poles = ac.linearize(PadeLoop(n, a, T), [], ["integ.y.signal"]).poles()
        errors.append(np.min(np.abs(poles - s0)) / abs(s0))
    assert all(e1 < 0.1 * e0 for e0, e1 in zip(errors, errors[1:]))
    assert errors[0] > 0.05 and errors[-1] < 1e-10
    # and the loop is stable as the true delayed loop is (aT < pi/2)
    assert s0.real < 0


def test_pade_delay_rejects_bad_orders():
    with pytest.raises(ac.ModelError, match="numerator order m"):
        bl.PadeDelay(n=2, m=3)
    with pytest.raises(ac.ModelError, match="order n"):
        bl.PadeDelay(n=0)
    with pytest.raises(ac.ModelError, match="integer"):
        bl.PadeDelay(n=2.5)
