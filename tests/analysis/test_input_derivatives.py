"""Linearization of models that differentiate their inputs: the derivative of a
top-level input is part of the transfer function, not silently dropped."""
import numpy as np
import pytest

import acausal as ac
from acausal.analysis import linearize
from acausal.library import translational as tr
from acausal.library.blocks import Constant
from acausal.ports import RealInput, RealOutput

# The tanker of Egeland & Gravdahl Example 12 (1.99), rudder angle delta to course psi:
# psi/delta = K (1 + T_a s) / (s (1 + T_1 s)(T_2 s - 1))
K, T_A, T_1, T_2 = 0.022, 38.0, 16.0, 192.0


class Tanker(ac.Component):
    """T_1 T_2 psi''' + (T_2 - T_1) psi'' - psi' = K (T_a delta' + delta), in time."""

    delta = RealInput()
    psi = ac.Variable(start=0.0, unit="rad")
    r = ac.Variable(start=0.0, unit="rad/s")
    r_dot = ac.Variable(start=0.0, unit="rad/s2")

    def equations(self):
        d = self.delta.signal
        return [ac.Eq(ac.der(self.psi), self.r), ac.Eq(ac.der(self.r), self.r_dot),
                ac.Eq(T_1 * T_2 * ac.der(self.r_dot) + (T_2 - T_1) * self.r_dot - self.r,
                      K * (T_A * ac.der(d) + d))]


class Autopilot(ac.Component):
    """delta = K_p (psi_0 - psi) - K_d r around the tanker; psi_0 a top-level input."""

    psi_0 = RealInput()
    rudder = RealOutput()
    ship = Tanker()
    K_p = ac.Parameter(2.0)
    K_d = ac.Parameter(100.0)

    def equations(self):
        return [ac.Eq(self.rudder, self.K_p * (self.psi_0.signal - self.ship.psi)
                      - self.K_d * self.ship.r),
                ac.connect(self.rudder, self.ship.delta)]


def _response(num, den, w):
    return np.polyval(num, 1j * w) / np.polyval(den, 1j * w)


W = np.logspace(-3.5, 0.5, 30)


def test_open_loop_ship_keeps_the_zero_of_its_rudder_derivative():
    sys = linearize(Tanker(), ["delta"], ["psi"])
    num, den = sys.tf()
    num_ref = K * np.array([T_A, 1.0])
    den_ref = np.polymul([T_1, 1.0, 0.0], [T_2, -1.0])
    assert sys.zeros() == pytest.approx([-1.0 / T_A], rel=1e-9)
    assert np.allclose(_response(num, den, W), _response(num_ref, den_ref, W), rtol=1e-8)


def test_closed_loop_with_rate_feedback():
    """psi/psi_0 = K K_p (1 + T_a s) / (s (1 + T_1 s)(T_2 s - 1) + K (1 + T_a s)(K_d s + K_p))."""
    kp, kd = 2.0, 100.0
    sys = linearize(Autopilot(), ["psi_0"], ["ship.psi"])
    num_ref = K * kp * np.array([T_A, 1.0])
    den_ref = np.polyadd(np.polymul([T_1, 1.0, 0.0], [T_2, -1.0]),
                         K * np.polymul([T_A, 1.0], [kd, kp]))
    num, den = sys.tf()
    assert np.allclose(_response(num, den, W), _response(num_ref, den_ref, W), rtol=1e-8)
    assert sys.is_stable()
    assert sys.dcgain()[0, 0] == pytest.approx(1.0, rel=1e-9)


class ImposedPosition(ac.Component):
    """A mass on a spring whose position is the input: s = u, f = m u'' + c u."""

    u = RealInput()
    position = tr.Position()
    mass = tr.Mass(m=2.0)
    spring = tr.Spring(c=50.0)
    wall = tr.Fixed()

    def equations(self):
        return [ac.connect(self.u, self.position.s_ref),
                ac.connect(self.position.flange, self.mass.flange_a),
                ac.connect(self.mass.flange_b, self.spring.flange_b),
                ac.connect(self.spring.flange_a, self.wall.flange)]


def test_outputs_that_follow_the_input_derivative_are_refused():
    static = linearize(ImposedPosition(), ["u"], ["spring.f", "mass.s"])
    assert static.n_states == 0 and static.D[:, 0] == pytest.approx([50.0, 1.0], rel=1e-9)
    for out in ("mass.v", "position.flange.f"):      # u' and m u'' + c u
        with pytest.raises(ValueError, match="derivative of input 'u'"):
            linearize(ImposedPosition(), ["u"], [out])


class SetPointAutopilot(ac.Component):
    """The same loop with the set point a Constant block's parameter."""

    rudder = RealOutput()
    ship = Tanker()
    set_point = Constant(k=0.1)
    K_p = ac.Parameter(2.0)
    K_d = ac.Parameter(100.0)

    def equations(self):
        return [ac.Eq(self.rudder, self.K_p * (self.set_point.y.signal - self.ship.psi)
                      - self.K_d * self.ship.r),
                ac.connect(self.rudder, self.ship.delta)]


def test_a_parameter_as_input_keeps_its_derivative():
    """The set point enters der(delta): linearizing with respect to the Constant's k
    gives the closed loop with its zero at -1/T_a, as the top-level input does."""
    kp, kd = 2.0, 100.0
    sys = linearize(SetPointAutopilot(), ["set_point.k"], ["ship.psi"])
    num_ref = K * kp * np.array([T_A, 1.0])
    den_ref = np.polyadd(np.polymul([T_1, 1.0, 0.0], [T_2, -1.0]),
                         K * np.polymul([T_A, 1.0], [kd, kp]))
    num, den = sys.tf()
    assert np.allclose(_response(num, den, W), _response(num_ref, den_ref, W), rtol=1e-8)
    assert sys.zeros() == pytest.approx([-1.0 / T_A], rel=1e-9)


def test_driving_a_parameter_changes_nothing_where_it_is_not_differentiated():
    """Friction coefficient of a motor load: the same A, B, C, D whether the parameter is
    driven (a Component) or perturbed as a constant (a CompiledModel)."""
    from acausal.library.electrical import ConstantVoltage, Ground
    from acausal.library.electromechanical import DCMotor
    from acausal.library.rotational import Damper, Fixed

    class Loaded(ac.Component):
        source = ConstantVoltage(V=12.0)
        ground = Ground()
        motor = DCMotor(R=1.5, L=2e-3, k=0.06, J=2e-4)
        friction = Damper(d=3e-4)
        housing = Fixed()

        def equations(self):
            return [ac.connect(self.source.p, self.motor.p),
                    ac.connect(self.source.n, self.motor.n, self.ground.p),
                    ac.connect(self.motor.flange, self.friction.flange_a),
                    ac.connect(self.friction.flange_b, self.housing.flange)]

    at = {"motor.rotor.w": 150.0}
    driven = linearize(Loaded(), ["friction.d", "source.V"], ["motor.rotor.w"], at=at)
    const = linearize(ac.compile(Loaded()), ["friction.d", "source.V"], ["motor.rotor.w"],
                      at=at)
    for a, b in ((driven.A, const.A), (driven.B, const.B), (driven.C, const.C),
                 (driven.D, const.D)):
        assert np.allclose(a, b, rtol=1e-7, atol=1e-9 * np.max(np.abs(b)))
    assert driven.B[:, 0] != pytest.approx(0.0)        # d enters: -w/J in der(w)
