"""MB-09: the linearized ball and beam (Egeland & Gravdahl, 001 §7.4, Examples 125-126,
(7.133)-(7.134), (7.141)-(7.143)).

About theta = theta' = x = x' = 0 the book linearizes its R -> 0 model to

    J_1 theta'' = T + m_2 g x                                                   (7.141)
    x'' = (5/7) g theta                                                         (7.142)

and prints their combination as d^4x/dt^4 = (m_2 g / J_1) x + (5/7)(g/J_1) T (7.143).
Eliminating theta from (7.141)-(7.142) gives instead

    d^4x/dt^4 = (5/7)(m_2 g^2 / J_1) x + (5/7)(g / J_1) T                      (corrected)

-- the printed x-term lacks the factor (5/7) g, and is dimensionally wrong (1/s^2 times
x where m/s^4 is needed).  This test checks the corrected form.

For a finite radius R, linearizing the full model (7.133)-(7.134) by hand gives
J_1 theta'' = T + m_2 g x and x'' = (5/7) g theta - R theta'', so

    x/T = ((5/7) g - R s^2) / (J_1 s^4 + m_2 g R s^2 - (5/7) m_2 g^2),

which tends to the corrected (7.143) as R -> 0.  The model is the library's BallAndBeam
(planar multibody: revolute pivot, prismatic track, rolling as a rack-and-pinion
constraint); its torque is about +z and its angle is -theta, so T = -motor torque.
Checked: acausal's linearization (A, B, C, D at the upright rest point) has the transfer
function above for R = 0.02 m (frequency response and poles, relative 1e-8), and for
R = 1e-4 m it agrees with the corrected (7.143) to O(R s^2 / g) and not with the printed one.
"""
import numpy as np
import pytest

import acausal as ac
from acausal.library.multibody.examples.ball_and_beam import BallAndBeam

G = 9.81
J_1, M_2 = 0.05, 0.1                    # the example's values
REST = {"pivot.phi": 0.0, "pivot.w": 0.0, "track.s": 0.0, "track.v": 0.0}
W = np.logspace(-1, 2, 31)


def _linear(R):
    sys = ac.linearize(BallAndBeam(R=R), inputs=["motor.tau.signal"], outputs=["track.s"],
                       at=REST)
    A, B, C, D = (np.asarray(m, dtype=float) for m in (sys.A, sys.B, sys.C, sys.D))
    n = A.shape[0]
    # C (jw I - A)^-1 B + D from the matrices themselves; the book's T is minus the
    # motor's torque
    H = np.array([(C @ np.linalg.solve(1j * w * np.eye(n) - A, B) + D)[0, 0] for w in W])
    return -H, sys


def _finite_radius(R, s):
    return ((5 / 7) * G - R * s**2) / (J_1 * s**4 + M_2 * G * R * s**2
                                       - (5 / 7) * M_2 * G**2)


def _corrected_7_143(s):
    return (5 / 7) * (G / J_1) / (s**4 - (5 / 7) * M_2 * G**2 / J_1)


def _printed_7_143(s):
    return (5 / 7) * (G / J_1) / (s**4 - M_2 * G / J_1)


def test_linearization_of_the_full_model():
    R = 0.02
    response, sys = _linear(R)
    exact = _finite_radius(R, 1j * W)
    assert np.max(np.abs(response - exact) / np.abs(exact)) < 1e-8
    poles = np.sort_complex(sys.poles())
    expected = np.sort_complex(np.roots([J_1, 0.0, M_2 * G * R, 0.0, -(5 / 7) * M_2 * G**2]))
    assert np.max(np.abs(poles - expected)) < 1e-8 * np.max(np.abs(expected))


def test_small_ball_gives_the_corrected_7_143():
    R = 1e-4
    response, sys = _linear(R)
    corrected = _corrected_7_143(1j * W)
    printed = _printed_7_143(1j * W)
    # O(R s^2 / g): |s| <= 100 rad/s on this grid gives at most ~1e-4 * 1e4 / 7 ~ 0.15,
    # so compare where |s| <= 10 (1.5e-3) and, everywhere, to the finite-R form
    low = W <= 10.0
    assert np.max(np.abs(response[low] - corrected[low]) / np.abs(corrected[low])) < 5e-3
    assert np.max(np.abs(response - _finite_radius(R, 1j * W))
                  / np.abs(_finite_radius(R, 1j * W))) < 1e-7
    # the printed form is far off: its unstable pole is (m_2 g / J_1)^(1/4) = 2.10 rad/s
    # against ((5/7) m_2 g^2 / J_1)^(1/4) = 3.42 rad/s
    assert np.max(np.abs(response[low] - printed[low]) / np.abs(printed[low])) > 0.5
    unstable = np.max(sys.poles().real)
    assert unstable == pytest.approx(((5 / 7) * M_2 * G**2 / J_1)**0.25, rel=1e-3)
