"""Equilibria of models with switching elements: the mode must be the one the solution
is in, not the one the start values were in.

Heater with a limited controller.  A body of heat capacity C = 5 kJ/K loses heat to a
20 degC ambient through G = 10 W/K; a proportional controller, gain K_p = 100 W/K,
drives the heater through a ``Limiter`` 0 <= Q <= Q_max = 1 kW:

    C T' = Q - G (T - T_amb),   Q = clip(K_p (T_set - T), 0, Q_max)

Unsaturated, the equilibrium is T* = (K_p T_set + G T_amb)/(K_p + G); it is the solution
if 0 < K_p (T_set - T*) < Q_max, otherwise T* = T_amb + Q_max/G (upper limit) or
T* = T_amb (lower limit).  The start values put the limiter in the other mode.

Stribeck friction.  An inertia J = 0.02 kg m2 driven by a constant torque tau_0,
|tau_0| = 3 N m > F_s, against StribeckFriction (Egeland & Gravdahl (5.13)) with
F_c = 1, F_s = 1.5 N m, v_s = 0.1 rad/s, F_v = 0.5 N m s/rad.  The equilibrium speed w*
solves tau_0 = [F_c + (F_s - F_c) exp(-(w/v_s)^2)] sgn(w) + F_v w, found here by brentq
on the curve; its sign is that of tau_0, opposite to the start value of the speed.
"""
import numpy as np
import pytest
from scipy.optimize import brentq

import acausal as ac
from acausal.library import rotational as rot
from acausal.library.friction.rotational import StribeckFriction

from ..heater import C_TH, G, K_P, Q_MAX, T_AMB, LimitedHeater, heater_equilibrium

# (set point, start temperature): the first starts saturated high with an unsaturated
# equilibrium, the second starts unsaturated with a saturated equilibrium
HEATER_CASES = [(323.15, T_AMB), (420.0, 415.0)]


@pytest.mark.parametrize("t_set, t_start", HEATER_CASES)
def test_heater_equilibrium_is_consistent_with_the_limiter(t_set, t_start):
    """The returned point must satisfy its own limiter mode: Q = clip(K_p (T_set - T))
    and zero net heat flow."""
    model = LimitedHeater(set_point={"k": t_set}, body={"T": {"start": t_start}})
    op = ac.steady_state(model)
    T = op["body.T"]
    Q = float(np.clip(K_P * (t_set - T), 0.0, Q_MAX))
    assert op["limit.y.signal"] == pytest.approx(Q, rel=1e-9, abs=1e-9 * Q_MAX)
    assert abs(Q - G * (T - T_AMB)) < 1e-9 * Q_MAX


@pytest.mark.parametrize("t_set, t_start", HEATER_CASES)
def test_heater_equilibrium_is_the_hand_computed_one(t_set, t_start):
    model = LimitedHeater(set_point={"k": t_set}, body={"T": {"start": t_start}})
    op = ac.steady_state(model)
    T, Q = heater_equilibrium(t_set)
    assert op["body.T"] == pytest.approx(T, rel=1e-10)
    assert op["heater.Q_flow.signal"] == pytest.approx(Q, rel=1e-9, abs=1e-9 * Q_MAX)
    assert abs(op["der(body.T)"]) < 1e-9 * Q_MAX / C_TH


F_C, F_S, V_S, F_V, J, TAU = 1.0, 1.5, 0.1, 0.5, 0.02, 3.0


def _stribeck(w):
    return (F_C + (F_S - F_C) * np.exp(-(w / V_S) ** 2)) * np.sign(w) + F_V * w


class DrivenSpinner(ac.Component):
    """Inertia on Stribeck friction (flange_a to the housing), driven by a constant torque."""

    housing = rot.Fixed()
    friction = StribeckFriction(F_c=F_C, F_s=F_S, v_s=V_S, F_v=F_V)
    wheel = rot.Inertia(J=J)
    drive = rot.ConstantTorque(tau_constant=TAU)

    def equations(self):
        return [ac.connect(self.housing.flange, self.friction.flange_a),
                ac.connect(self.friction.flange_b, self.wheel.flange_a),
                ac.connect(self.wheel.flange_b, self.drive.flange)]


@pytest.mark.parametrize("direction", [-1.0, 1.0])
def test_stribeck_equilibrium_opposite_to_the_start_speed(direction):
    tau_0 = direction * TAU
    model = DrivenSpinner(drive={"tau_constant": tau_0},
                          wheel={"w": {"start": -direction * 1.0}})
    op = ac.steady_state(model, hold=["wheel.phi"])
    w_star = direction * brentq(lambda w: _stribeck(w) - TAU, 1e-9, 100.0, xtol=1e-15)
    assert op["wheel.w"] == pytest.approx(w_star, rel=1e-9)
    # the friction torque the model reports balances the drive, and is the curve's
    assert op["friction.tau"] == pytest.approx(tau_0, rel=1e-9)
    assert abs(op["der(wheel.w)"]) < 1e-9 * TAU / J
