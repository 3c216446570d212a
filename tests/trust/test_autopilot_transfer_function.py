"""Closed-loop transfer function of a course autopilot around a Nomoto-type ship model.

The ship is the tanker of Egeland & Gravdahl Example 12 (Blanke 1981, Fossen 1994),
rudder angle delta to course psi,

    psi/delta = K (1 + T_a s) / (s (1 + T_1 s)(T_2 s - 1)),   K = 0.022 1/s,
    T_a = 38 s, T_1 = 16 s, T_2 = 192 s                                    (1.99)

(open-loop unstable, a pole at +1/T_2).  Two autopilots:

* the book's PD in lead-lag form delta = K_p (1 + T_1 s)/(1 + 0.1 T_1 s) (psi_0 - psi)
  (1.100) with K_p = 14, whose closed-loop poles the book prints as -0.5609 and
  -0.0295 +- j0.0303 (the roots of (1.101); the inventory notes that these are the poles
  of K_p = 14, not of the K_p = 20 of its MATLAB line);
* heading and yaw-rate feedback delta = K_p (psi_0 - psi) - K_d r, r = psi', with
  K_p = 2, K_d = 100 (stable by Routh's criterion on the cubic below).

Each is written twice where it matters: with ``TransferFunction`` blocks, and as the
user's own equations (the ship's differential equation T_1 T_2 psi''' + (T_2 - T_1) psi''
- psi' = K (T_a delta' + delta), which contains the derivative of its input).

The reference transfer functions psi/psi_0 are closed forms:

    lead-lag PD:  K K_p (1 + T_a s) / (s (1 + 0.1 T_1 s)(T_2 s - 1) + K K_p (1 + T_a s))
    P + rate:     K K_p (1 + T_a s) / (s (1 + T_1 s)(T_2 s - 1) + K (1 + T_a s)(K_d s + K_p))

(the lead-lag zero cancels the ship's pole at -1/T_1).  Frequency responses of
``StateSpace.tf()`` are also compared with ``scipy.signal.ss2tf`` on the same A, B, C, D:
two algorithms on the same matrices must agree whatever the matrices are.
"""
import numpy as np
import pytest
import scipy.signal as ss

import acausal as ac
from acausal.library.blocks import Constant, Feedback, Gain, Add, Step, TransferFunction
from acausal.ports import RealInput, RealOutput

K, T_A, T_1, T_2 = 0.022, 38.0, 16.0, 192.0
W = np.logspace(-3.5, 1.0, 40)


def _lead_lag_closed_loop(k_p=14.0):
    den = np.polyadd(np.polymul(np.polymul([1.0, 0.0], [0.1 * T_1, 1.0]), [T_2, -1.0]),
                     K * k_p * np.array([T_A, 1.0]))
    return K * k_p * np.array([T_A, 1.0]), den


def _rate_feedback_closed_loop(k_p=2.0, k_d=100.0):
    den = np.polyadd(np.polymul([T_1, 1.0, 0.0], [T_2, -1.0]),
                     K * np.polymul([T_A, 1.0], [k_d, k_p]))
    return K * k_p * np.array([T_A, 1.0]), den


def _response(num, den, w=W):
    s = 1j * w
    return np.polyval(num, s) / np.polyval(den, s)


def _relative(a, b):
    return np.max(np.abs(a - b) / np.abs(b))


class BlockAutopilot(ac.Component):
    """Lead-lag PD (1.100) and the tanker (1.99) as TransferFunction blocks."""

    reference = Step(height=0.1)
    error = Feedback()
    pd = TransferFunction(b=[14.0 * T_1, 14.0], a=[0.1 * T_1, 1.0])
    ship = TransferFunction(b=[K * T_A, K], a=np.polymul([T_1, 1.0, 0.0], [T_2, -1.0]))

    def equations(self):
        return [ac.connect(self.reference.y, self.error.u1),
                ac.connect(self.error.y, self.pd.u),
                ac.connect(self.pd.y, self.ship.u),
                ac.connect(self.ship.y, self.error.u2)]


class NomotoShip(ac.Component):
    """T_1 T_2 psi''' + (T_2 - T_1) psi'' - psi' = K (T_a delta' + delta)   ((1.99) in time)."""

    delta = RealInput()
    course = RealOutput()
    yaw_rate = RealOutput()
    psi = ac.Variable(start=0.0, unit="rad", description="course angle")
    r = ac.Variable(start=0.0, unit="rad/s", description="yaw rate")
    r_dot = ac.Variable(start=0.0, unit="rad/s2", description="yaw acceleration")

    def equations(self):
        d = self.delta.signal
        return [ac.Eq(ac.der(self.psi), self.r),
                ac.Eq(ac.der(self.r), self.r_dot),
                ac.Eq(T_1 * T_2 * ac.der(self.r_dot) + (T_2 - T_1) * self.r_dot - self.r,
                      K * (T_A * ac.der(d) + d)),
                ac.Eq(self.course, self.psi),
                ac.Eq(self.yaw_rate, self.r)]


class LeadLagPD(ac.Component):
    """0.1 T_1 delta' + delta = K_p (e + T_1 e')   ((1.100) in time)."""

    e = RealInput()
    delta = RealOutput()

    def equations(self):
        return [ac.Eq(0.1 * T_1 * ac.der(self.delta.signal) + self.delta.signal,
                      14.0 * (self.e.signal + T_1 * ac.der(self.e.signal)))]


class EquationAutopilot(ac.Component):
    """The same loop as ``BlockAutopilot``, the ship and the PD as equations."""

    reference = Constant(k=0.1)
    error = Feedback()
    pd = LeadLagPD()
    ship = NomotoShip()

    def equations(self):
        return [ac.connect(self.reference.y, self.error.u1),
                ac.connect(self.error.y, self.pd.e),
                ac.connect(self.pd.delta, self.ship.delta),
                ac.connect(self.ship.course, self.error.u2)]


class RateFeedbackAutopilot(ac.Component):
    """delta = K_p (psi_0 - psi) - K_d r around the equation-form ship."""

    reference = Constant(k=0.1)
    error = Feedback()
    heading_gain = Gain(k=2.0)
    rate_gain = Gain(k=-100.0)
    rudder = Add()
    ship = NomotoShip()

    def equations(self):
        return [ac.connect(self.reference.y, self.error.u1),
                ac.connect(self.ship.course, self.error.u2),
                ac.connect(self.error.y, self.heading_gain.u),
                ac.connect(self.ship.yaw_rate, self.rate_gain.u),
                ac.connect(self.heading_gain.y, self.rudder.u1),
                ac.connect(self.rate_gain.y, self.rudder.u2),
                ac.connect(self.rudder.y, self.ship.delta)]


CASES = {
    "blocks, lead-lag PD": (BlockAutopilot, "reference.y.signal", "ship.y.signal",
                            _lead_lag_closed_loop()),
    "equations, lead-lag PD": (EquationAutopilot, "reference.k", "ship.psi",
                               _lead_lag_closed_loop()),
    "equations, P + yaw rate": (RateFeedbackAutopilot, "reference.k", "ship.psi",
                                _rate_feedback_closed_loop()),
}


@pytest.fixture(scope="module", params=sorted(CASES))
def loop(request):
    model, source, course, exact = CASES[request.param]
    return ac.linearize(model(), [source], [course]), exact


def test_book_poles_of_the_lead_lag_autopilot():
    """(1.101) with K_p = 14: -0.5609 and -0.0295 +- j0.0303 (printed, 4 digits), plus
    the ship's own pole -1/T_1 that the PD's zero cancels (it stays in A, and leaves
    with the minimal realization)."""
    sys = ac.linearize(BlockAutopilot(), ["reference.y.signal"], ["ship.y.signal"])
    printed = np.array([-0.5609, -0.0295 - 0.0303j, -0.0295 + 0.0303j])
    assert np.allclose(np.sort_complex(sys.minimal().poles()), np.sort_complex(printed),
                       atol=1e-4)
    assert np.min(np.abs(sys.poles() + 1.0 / T_1)) < 1e-9 / T_1


def test_tf_is_the_closed_form_closed_loop(loop):
    sys, (num, den) = loop
    n_tf, d_tf = sys.tf()
    assert len(d_tf) - 1 == len(den) - 1          # the cancelled mode is gone: 3 poles
    assert _relative(_response(n_tf, d_tf), _response(num, den)) < 1e-8


def test_tf_agrees_with_scipy_on_the_same_matrices(loop):
    sys, _ = loop
    n_tf, d_tf = sys.tf()
    n_sp, d_sp = ss.ss2tf(sys.A, sys.B, sys.C, sys.D)
    assert _relative(_response(n_tf, d_tf), _response(n_sp[0], d_sp)) < 1e-8


def test_zeros_poles_and_dc_gain(loop):
    sys, (num, den) = loop
    z = sys.zeros()
    assert len(z) == 1 and abs(z[0] - (-1.0 / T_A)) < 1e-9 / T_A
    exact_poles = np.sort_complex(np.roots(den))
    poles = np.sort_complex(sys.minimal().poles())
    assert len(poles) == 3 and np.max(np.abs(poles - exact_poles)) < 1e-8
    assert sys.dcgain()[0, 0] == pytest.approx(1.0, rel=1e-9)
