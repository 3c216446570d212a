"""CB-04: course autopilot of a tanker (Egeland & Gravdahl, 001 §1.3.8, Example 12,
(1.99)-(1.101)).

Nomoto-type ship from rudder delta to course psi, and a PD in lead-lag form:

    psi/delta = K (1 + T_a s) / (s (1 + T_1 s)(T_2 s - 1)),
    K = 0.022 1/s, T_a = 38 s, T_1 = 16 s, T_2 = 192 s                            (1.99)
    delta = K_p (1 + T_1 s)/(1 + 0.1 T_1 s) (psi_0 - psi)                          (1.100)
    s (1 + 0.1 T_1 s)(T_2 s - 1) + K K_p (1 + T_a s) = 0                           (1.101)

The book prints the closed-loop poles s = -0.5609 and s = -0.0295 +- j0.0303 and says
they come from ``roots(conv([1.6 1 0],[192 -1]) + 20*0.022*[0 0 38 1])``, i.e. K_p = 20.
They do not: the printed poles are those of K_p = 14 (INVENTORY §0.4).  Each is tested
consistently here, never mixed: K_p = 14 against the printed poles (to their 4 printed
decimals), K_p = 20 against the roots of the printed command (numpy's roots of the
book's polynomial, an independent computation), and the two sets are shown to differ.

The loop is written as a user would, the ship's and the PD's differential equations in
time, (1.99) as T_1 T_2 psi''' + (T_2 - T_1) psi'' - psi' = K (T_a delta' + delta) and
(1.100) as 0.1 T_1 delta' + delta = K_p (e + T_1 e'), e = psi_0 - psi; acausal
linearizes it.  Its A has four eigenvalues: the three roots of (1.101) and the ship's
pole -1/T_1, which the PD's zero cancels in psi/psi_0 (it is still a mode of the loop).
"""
import numpy as np
import pytest
from scipy import signal

import acausal as ac

K, T_A, T_1, T_2 = 0.022, 38.0, 16.0, 192.0
PRINTED_POLES = np.array([-0.5609, -0.0295 - 0.0303j, -0.0295 + 0.0303j])


class TankerAutopilot(ac.Component):
    """Heading loop: lead-lag PD (1.100) around the ship (1.99), course set to psi_0."""

    K_p = ac.Parameter(14.0, description="autopilot gain")
    psi_0 = ac.Parameter(0.1, unit="rad", description="commanded course")
    psi = ac.Variable(start=0.0, fixed=True, unit="rad")
    r = ac.Variable(start=0.0, fixed=True, unit="rad/s")
    r_dot = ac.Variable(start=0.0, fixed=True, unit="rad/s2")
    delta = ac.Variable(start=0.0, fixed=True, unit="rad", description="rudder angle")
    e = ac.Variable(unit="rad", description="course error")

    def equations(self):
        return [ac.Eq(ac.der(self.psi), self.r),
                ac.Eq(ac.der(self.r), self.r_dot),
                ac.Eq(T_1 * T_2 * ac.der(self.r_dot) + (T_2 - T_1) * self.r_dot - self.r,
                      K * (T_A * ac.der(self.delta) + self.delta)),
                ac.Eq(self.e, self.psi_0 - self.psi),
                ac.Eq(0.1 * T_1 * ac.der(self.delta) + self.delta,
                      self.K_p * (self.e - T_1 * self.r))]


def _loop_poles(k_p):
    compiled = ac.compile(TankerAutopilot(K_p=k_p))
    return np.sort_complex(ac.linearize(compiled).poles())


def _without_ship_pole(poles):
    k = np.argmin(np.abs(poles + 1.0 / T_1))
    assert abs(poles[k] + 1.0 / T_1) < 1e-9 / T_1
    return np.sort_complex(np.delete(poles, k))


def test_book_poles_with_kp_14():
    poles = _without_ship_pole(_loop_poles(14.0))
    # the book prints 4 decimals
    assert np.max(np.abs(poles - np.sort_complex(PRINTED_POLES))) < 5e-5


def test_printed_matlab_command_with_kp_20():
    book_command = np.roots(np.polyadd(np.polymul([1.6, 1.0, 0.0], [192.0, -1.0]),
                                       20 * 0.022 * np.array([0.0, 0.0, 38.0, 1.0])))
    poles = _without_ship_pole(_loop_poles(20.0))
    expected = np.sort_complex(book_command)
    assert np.max(np.abs(poles - expected)) < 1e-9 * np.max(np.abs(expected))
    # the K_p = 20 poles are not the printed ones: the misprint of §0.4
    assert np.max(np.abs(expected - np.sort_complex(PRINTED_POLES))) > 1e-2


@pytest.mark.parametrize("k_p", [14.0, 20.0])
def test_step_response_is_the_closed_form(k_p):
    """psi(t) for the command psi_0 = 0.1 from rest equals 0.1 times the step response
    of K K_p (1 + T_a s) / (1.101), computed by scipy.signal; the loop is type 1 (the
    ship integrates), so psi settles on psi_0.  A step of psi_0 at t = 0 makes the
    rudder jump by the PD's high-frequency gain, delta(0+) = 10 K_p psi_0, and the
    ship's delta' term makes r' jump by K T_a delta(0+) / (T_1 T_2): those are the
    transfer function's initial conditions at 0+."""
    delta_0 = 10.0 * k_p * 0.1
    model = TankerAutopilot(K_p=k_p, delta={"start": delta_0, "fixed": True},
                            r_dot={"start": K * T_A * delta_0 / (T_1 * T_2), "fixed": True})
    res = ac.simulate(model, t_end=600.0, rtol=1e-10, n_points=601, raise_on_failure=True)
    den = np.polyadd(np.polymul(np.polymul([1.0, 0.0], [0.1 * T_1, 1.0]), [T_2, -1.0]),
                     K * k_p * np.array([T_A, 1.0]))
    _, ref = signal.step(signal.lti(K * k_p * np.array([T_A, 1.0]), den), T=res.t)
    ref = 0.1 * ref
    assert np.max(np.abs(res["psi"] - ref)) < 1e-6 * np.max(np.abs(ref))
    assert abs(res["psi"][-1] - 0.1) < 1e-6
