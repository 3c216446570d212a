"""Steady states: closed-form equilibria, and the errors for missing or non-isolated ones."""
import numpy as np
import pytest
import sympy as sp

import acausal as ac
from acausal.analysis import linearize, steady_state
from acausal.library.electrical import ConstantVoltage, Ground
from acausal.library.electromechanical import DCMotor
from acausal.library.rotational import Damper, Fixed
from acausal.errors import SteadyStateError

R, L, K, J, B, V = 1.2, 1e-3, 0.05, 1e-4, 2e-4, 24.0


class MotorWithFriction(ac.Component):
    source = ConstantVoltage(V=V)
    ground = Ground()
    motor = DCMotor(R=R, L=L, k=K, J=J)
    friction = Damper(d=B)
    housing = Fixed()

    def equations(self):
        return [ac.connect(self.source.p, self.motor.p),
                ac.connect(self.source.n, self.motor.n, self.ground.p),
                ac.connect(self.motor.flange, self.friction.flange_a),
                ac.connect(self.friction.flange_b, self.housing.flange)]


def test_dc_motor_running_speed_with_the_angle_held():
    op = steady_state(MotorWithFriction(), hold=["motor.emf.flange.phi"])
    w = K * V / (R * B + K * K)              # V = R i + K w,  K i = B w
    assert op["motor.rotor.w"] == pytest.approx(w, rel=1e-12)
    assert op["motor.La.i"] == pytest.approx(B * w / K, rel=1e-12)
    # J der(w) = K i - B w, two torques that cancel: judged on B w / J (876 rad/s2)
    assert op["der(motor.rotor.w)"] == pytest.approx(0.0, abs=1e-12 * B * w / J)


def test_free_angle_is_named_when_the_equilibrium_is_not_isolated():
    with pytest.raises(SteadyStateError, match=r"motor\.emf\.flange\.phi"):
        steady_state(MotorWithFriction())


class Runaway(ac.Component):
    """der(x) = x^2 + 1 has no real equilibrium."""

    x = ac.Variable(start=0.5)

    def equations(self):
        return [ac.Eq(ac.der(self.x), self.x**2 + 1)]


def test_missing_equilibrium_is_reported_with_the_derivative_that_stays():
    with pytest.raises(SteadyStateError, match=r"der\(x\)"):
        steady_state(Runaway())


class Tank(ac.Component):
    """A der(h) = u - a sqrt(2 g h)  (the DAE notes (7.2.5)), constant inflow u."""

    A = ac.Parameter(2.0)
    a = ac.Parameter(0.05)
    g = ac.Parameter(9.81)
    u = ac.Parameter(0.3)
    h = ac.Variable(start=1.0)
    q = ac.Variable()

    def equations(self):
        return [ac.Eq(self.q, self.a * sp.sqrt(2 * self.g * self.h)),
                ac.Eq(self.A * ac.der(self.h), self.u - self.q)]


def test_tank_level_and_its_linearization_at_steady_state():
    a, g, u, A = 0.05, 9.81, 0.3, 2.0
    h = (u / a) ** 2 / (2 * g)
    op = steady_state(Tank())
    assert op["h"] == pytest.approx(h, rel=1e-12)
    sys = linearize(Tank(), ["u"], ["q"], at="steady")
    pole = -a * np.sqrt(2 * g) / (2 * A * np.sqrt(h))            # d/dh of (7.2.5)
    assert sys.A[0, 0] == pytest.approx(pole, rel=1e-9)
    assert sys.B[0, 0] == pytest.approx(1 / A, rel=1e-9)
    assert sys.dcgain()[0, 0] == pytest.approx(1.0, rel=1e-9)    # all inflow leaves


def test_a_model_without_states_has_its_one_operating_point():
    """A source on a resistor has no states: the steady state is Ohm's law, i = V/R."""
    from acausal.library.electrical import Resistor

    class SourceOnResistor(ac.Component):
        source = ConstantVoltage(V=2.0)
        r = Resistor(R=4.0)
        ground = Ground()

        def equations(self):
            return [ac.connect(self.source.p, self.r.p),
                    ac.connect(self.source.n, self.r.n, self.ground.p)]

    op = steady_state(SourceOnResistor())
    assert op.states == {}
    assert op["r.i"] == pytest.approx(0.5, rel=1e-12)
