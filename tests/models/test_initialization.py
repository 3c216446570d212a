"""Consistent initialization the Modelica way: fixed starts, initial equations, errors."""
import numpy as np
import pytest

import acausal as ac
from acausal import InitializationFailed
from acausal.library import rotational as rot
from acausal.library.electrical import ConstantVoltage, Ground
from acausal.library.electromechanical import DCMotor

V, R, L, K, J, B, T_LOAD = 12.0, 2.0, 5e-3, 0.1, 2e-3, 5e-3, 0.2


class LoadedMotor(ac.Component):
    """DC motor on 12 V with viscous friction and a constant load torque."""

    src = ConstantVoltage(V=V)
    gnd = Ground()
    motor = DCMotor(R=R, L=L, k=K, J=J)
    friction = rot.Damper(d=B)
    housing = rot.Fixed()
    load = rot.ConstantTorque(tau_constant=-T_LOAD)

    def equations(self):
        return [ac.connect(self.src.p, self.motor.p),
                ac.connect(self.src.n, self.motor.n, self.gnd.p),
                ac.connect(self.motor.flange, self.friction.flange_a, self.load.flange),
                ac.connect(self.friction.flange_b, self.housing.flange)]


class SteadyMotor(LoadedMotor):
    """The same motor started in steady state: der(w) = 0 and der(i) = 0 at t0."""

    def initial_equations(self):
        return [ac.Eq(ac.der(self.motor.rotor.w), 0), ac.Eq(ac.der(self.motor.La.i), 0)]


def _steady_state():
    # V = R i + K w  and  K i = B w + T_load  (Egeland & Gravdahl (3.29)-(3.31) at rest)
    A = np.array([[R, K], [K, -B]])
    i, w = np.linalg.solve(A, [V, T_LOAD])
    return i, w


def test_steady_state_initialization_of_a_loaded_dc_motor():
    i_ss, w_ss = _steady_state()
    res = ac.simulate(SteadyMotor(), t_end=1.0, rtol=1e-8, n_points=11)
    assert abs(res["motor.rotor.w"][0] - w_ss) < 1e-9 * w_ss
    assert abs(res["motor.La.i"][0] - i_ss) < 1e-9 * i_ss
    # and it stays there: it is an equilibrium
    assert np.max(np.abs(res["motor.rotor.w"] - w_ss)) < 1e-7 * w_ss


def test_start_values_of_states_are_used_when_nothing_else_fixes_them():
    res = ac.simulate(LoadedMotor(motor={"rotor": {"w": 5.0}}), t_end=1e-3, rtol=1e-8,
                      n_points=3)
    assert res["motor.rotor.w"][0] == pytest.approx(5.0)


def test_over_specified_initial_problem_names_the_conditions():
    class Over(SteadyMotor):
        def initial_equations(self):
            return [ac.Eq(self.motor.rotor.w, 3.0),
                    ac.Eq(self.motor.La.i, 1.0)]

    # four conditions for two states: the steady state is kept, and w = 3, i = 1 do not
    # hold there (tests/models/test_overspecified_initial.py: consistent ones are dropped)
    with pytest.raises(InitializationFailed,
                       match=r"over-specified and inconsistent.*motor.rotor.w"):
        ac.simulate(Over(), t_end=0.1)


def test_inconsistent_initial_problem_fails_with_the_residuals_named():
    class Impossible(LoadedMotor):
        """w^2 = -1 has no real solution."""

        def initial_equations(self):
            return [ac.Eq(self.motor.rotor.w**2, -1.0)]

    with pytest.raises(InitializationFailed) as err:
        ac.simulate(Impossible(), t_end=0.1)
    assert "motor.rotor.w**2 = -1" in str(err.value)


def test_fixed_start_contradicted_by_an_equation_is_an_error():
    class Contradiction(ac.Component):
        x = ac.Variable(start=0.5, fixed=True)

        def equations(self):
            return [ac.Eq(self.x, 0)]

    with pytest.raises(ac.ModelError, match=r"'x'.*fixed=True.*over-specified"):
        ac.compile(Contradiction())
