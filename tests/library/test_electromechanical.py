"""DC motor drives (Egeland & Gravdahl ch. 2-3) against transfer functions, the book's
reduced equations and energy balances."""
import numpy as np
import pytest
import scipy.signal as sig

import acausal as ac
from acausal.library.blocks import Sine
from acausal.library.electromechanical import CurrentControlledDCMotor
from acausal.library.electromechanical.examples.controlled_motor import (CurrentLoop,
                                                                       PositionLoop,
                                                                       VelocityLoop)
from acausal.library.electromechanical.examples.dc_motor import (DCMotorStep,
                                                               DCMotorStepNoInductance)
from acausal.library.electromechanical.examples.elastic_transmission import (
    ElasticTransmission, FreeElasticTransmission, LockedElasticTransmission)
from acausal.library.electromechanical.examples.geared_load import MotorGearLoad
from acausal.library.electromechanical.examples.two_motors import TwoMotorsElasticLoad

R, L, K, J, V, T0 = 1.0, 1e-3, 0.05, 1e-4, 24.0, 0.01   # the examples' motor and step
T_A, T_M = L / R, J * R / K**2                             # (2.28)


def _step_speed_second_order(t, L_a):
    """w(t) for a step V at T0 through (1/K)/(1 + T_m s + T_a T_m s^2)  (2.31)."""
    p1, p2 = np.roots([L_a / R * T_M, T_M, 1.0])
    tau = np.clip(t - T0, 0.0, None)
    return V / K * (1 + (p2 * np.exp(p1 * tau) - p1 * np.exp(p2 * tau)) / (p1 - p2))


def _step_speed_first_order(t):
    """w(t) of T_m dw/dt = -w + u_a/K  (2.39)."""
    return V / K * (1 - np.exp(-np.clip(t - T0, 0.0, None) / T_M))


def test_dc_motor_step_matches_transfer_function_2_31():
    t = np.linspace(0, 0.2, 201)
    res = ac.simulate(DCMotorStep(), t_end=0.2, rtol=1e-10, t_eval=t)
    w_ss = V / K
    assert np.max(np.abs(res["motor.rotor.w"] - _step_speed_second_order(t, L))) < 1e-7 * w_ss


def test_dc_motor_without_inductance_is_first_order_2_39():
    t = np.linspace(0, 0.2, 201)
    res = ac.simulate(DCMotorStepNoInductance(), t_end=0.2, rtol=1e-10, t_eval=t)
    assert np.max(np.abs(res["rotor.w"] - _step_speed_first_order(t))) < 1e-7 * V / K
    # the armature equation is algebraic: 0 = u_a - R i_a - K w at every point
    u_a = res["source.v"]
    assert np.max(np.abs(u_a - R * res["Ra.i"] - K * res["rotor.w"])) < 1e-9 * V


def test_inductance_to_zero_approaches_the_algebraic_model():
    """max |w_La - w_0| shrinks in proportion to L_a (singular perturbation, 2.2.2)."""
    t = np.linspace(0, 0.2, 401)
    reference = ac.simulate(DCMotorStepNoInductance(), t_end=0.2, rtol=1e-10, t_eval=t)
    compiled = ac.compile(DCMotorStep())
    gaps = []
    for L_a in (1e-3, 1e-4, 1e-5):
        res = ac.simulate(compiled, t_end=0.2, rtol=1e-10, t_eval=t,
                          parameters={"motor.L": L_a})
        gaps.append(np.max(np.abs(res["motor.rotor.w"] - reference["rotor.w"])))
    ratios = [gaps[0] / gaps[1], gaps[1] / gaps[2]]
    assert all(8.0 < r < 12.0 for r in ratios), (gaps, ratios)
    assert gaps[-1] < 1e-3 * V / K


def test_dc_motor_with_zero_inductance_parameter():
    """L = 0 is a structural zero: the armature equation becomes algebraic (2.2.1)."""
    res = ac.simulate(DCMotorStep(motor={"L": 0.0}), t_end=0.2, rtol=1e-8,
                      t_eval=np.linspace(0, 0.2, 21), raise_on_failure=True)
    assert np.max(np.abs(res["motor.rotor.w"] - _step_speed_first_order(res.t))) < 1e-5 * V / K


class RawDCMotor(ac.Component):
    """The DC motor as the book writes it, (3.29)-(3.31), on a voltage step at T0."""

    L_a = ac.Parameter(L)
    i_a = ac.Variable(start=0.0)
    w = ac.Variable(start=0.0)
    theta = ac.Variable(start=0.0)

    def equations(self):
        u_a = ac.if_else(ac.time >= T0, V, 0.0)
        return [ac.Eq(self.L_a * ac.der(self.i_a), u_a - R * self.i_a - K * self.w),
                ac.Eq(J * ac.der(self.w), K * self.i_a),
                ac.Eq(ac.der(self.theta), self.w)]


def test_dc_motor_composition_agrees_with_raw_equations_3_29():
    t = np.linspace(0, 0.2, 101)
    comp = ac.simulate(DCMotorStep(), t_end=0.2, rtol=1e-10, t_eval=t)
    raw = ac.simulate(RawDCMotor(), t_end=0.2, rtol=1e-10, t_eval=t)
    for a, b, scale in (("motor.La.i", "i_a", V / R), ("motor.rotor.w", "w", V / K),
                        ("motor.rotor.phi", "theta", V / K * 0.2)):
        assert np.max(np.abs(comp[a] - raw[b])) < 1e-7 * scale, a


def test_dc_motor_energy_balance_3_33():
    """V = L i^2/2 + J w^2/2:  dV/dt = i u_a - R i^2 (no load), pointwise."""
    res = ac.simulate(DCMotorStep(), t_end=0.2, rtol=1e-10, t_eval=np.linspace(0.02, 0.2, 50))
    i, w = res["motor.La.i"], res["motor.rotor.w"]
    dV = L * i * res["der(motor.La.i)"] + J * w * res["der(motor.rotor.w)"]
    supplied = i * res["source.v"] - R * i**2
    assert np.max(np.abs(dV - supplied)) < 1e-9 * V * V / R


def test_current_loop_matches_closed_loop_example_44():
    """u_a = K_i (1 + T_m s)/s (i_0 - i_a): i_a/i_0 = C H_a/(1 + C H_a), H_a (3.55)."""
    Ki, g = 50.0, J / K**2
    num = np.polymul([Ki * g], [T_M, 1.0])              # K_i (J/K^2)(1 + T_m s)
    den = np.polyadd([T_A * T_M, T_M, 1.0], num)        # (1 + T_m s + T_a T_m s^2) + num
    t = np.linspace(0, 0.02, 201)
    _, expected = sig.step(sig.lti(num, den), T=t)
    res = ac.simulate(CurrentLoop(), t_end=0.02, rtol=1e-10, t_eval=t)
    assert np.max(np.abs(res["motor.La.i"] - expected)) < 1e-7


def test_velocity_loop_is_first_order_3_64():
    Ka = K * 0.4 / J                                    # (3.65)
    t = np.linspace(0, 0.05, 101)
    res = ac.simulate(VelocityLoop(), t_end=0.05, rtol=1e-10, t_eval=t)
    assert Ka == pytest.approx(200.0)
    assert np.max(np.abs(res["motor.motor.rotor.w"] - 10.0 * (1 - np.exp(-Ka * t)))) < 1e-6


def test_position_loop_matches_3_68():
    Ka, Kv = K * 0.4 / J, 20.0
    t = np.linspace(0, 0.5, 201)
    _, expected = sig.step(sig.lti([1.0], [1 / (Kv * Ka), 1 / Kv, 1.0]), T=t)
    res = ac.simulate(PositionLoop(), t_end=0.5, rtol=1e-10, t_eval=t)
    assert np.max(np.abs(res["motor.flange.phi"] - expected)) < 1e-7


class SineCurrentDrive(ac.Component):
    reference = Sine(amplitude=2.0, f=1.0)
    drive = CurrentControlledDCMotor(R=1.0, L=0.01, k=0.1, J=0.01)

    def equations(self):
        return [ac.connect(self.reference.y, self.drive.i_d)]


def test_current_controlled_motor_is_a_double_integrator_3_59():
    t = np.linspace(0, 2, 201)
    res = ac.simulate(SineCurrentDrive(), t_end=2, rtol=1e-10, t_eval=t)
    w = 0.1 * 2.0 / 0.01 * (1 - np.cos(2 * np.pi * t)) / (2 * np.pi)
    assert np.max(np.abs(res["drive.motor.rotor.w"] - w)) < 1e-7 * 20
    # the drive delivers u_a = R i_d + L di_d/dt + k w
    i_d, di_d = 2 * np.sin(2 * np.pi * t), 4 * np.pi * np.cos(2 * np.pi * t)
    assert np.max(np.abs(res["drive.u_a"] - (i_d + 0.01 * di_d + 0.1 * w))) < 1e-6


def test_motor_gear_load_reduced_equation_3_12_and_lossless_gear():
    t = np.linspace(0.01, 0.5, 100)
    res = ac.simulate(MotorGearLoad(), t_end=0.5, rtol=1e-10, t_eval=t)
    n_b, J_L, T_e = 0.1, 5e-3, 0.2
    lhs = (J + n_b**2 * J_L) * res["der(motor.rotor.w)"]
    rhs = res["motor.emf.tau"] - n_b * T_e
    assert np.max(np.abs(lhs - rhs)) < 1e-9 * np.max(np.abs(res["motor.emf.tau"]))
    assert np.max(np.abs(res["load.w"] - n_b * res["motor.rotor.w"])) < 1e-9 * V / K
    p_in, p_out = res["power_in.power.signal"], res["power_out.power.signal"]
    assert np.max(np.abs(p_in - p_out)) < 1e-9 * np.max(np.abs(p_in))
    assert np.max(np.abs(p_in)) > 1.0


def _zero_crossings(t, x):
    k = np.nonzero(np.sign(x[:-1]) * np.sign(x[1:]) < 0)[0]
    return t[k] - x[k] * (t[k + 1] - t[k]) / (x[k + 1] - x[k])


def _measured_frequency(res, name):
    tz = _zero_crossings(res.t, res[name])
    return np.pi / np.mean(np.diff(tz)), len(tz)


KS, DS, JM, JL = 0.5, 0.01, 1.0, 1.0                 # Fig. 3.11
JE, JT = JM * JL / (JM + JL), JM + JL
W1, Z1 = np.sqrt(KS / JE), DS / 2 / np.sqrt(JE * KS)     # (3.87)
WA, ZA = np.sqrt(JM / JT) * W1, np.sqrt(JM / JT) * Z1    # (3.88)


def test_resonance_of_elastic_transmission_3_87():
    t = np.linspace(0, 40, 8001)
    res = ac.simulate(FreeElasticTransmission(), t_end=40, rtol=1e-10, t_eval=t)
    w, crossings = _measured_frequency(res, "shaft.phi_rel")
    assert crossings >= 12
    assert w == pytest.approx(W1 * np.sqrt(1 - Z1**2), rel=1e-6)
    assert W1 == pytest.approx(1.0)


def test_anti_resonance_of_elastic_transmission_3_88():
    t = np.linspace(0, 40, 8001)
    res = ac.simulate(LockedElasticTransmission(), t_end=40, rtol=1e-10, t_eval=t)
    w, crossings = _measured_frequency(res, "load.phi")
    assert crossings >= 8
    assert w == pytest.approx(WA * np.sqrt(1 - ZA**2), rel=1e-6)
    assert WA == pytest.approx(np.sqrt(0.5))


def test_elastic_transmission_rigid_mode_3_76():
    """theta_r'' = T_m/J_m with theta_r = theta_m + (J_L/J_m) theta_L  (3.74), (3.76)."""
    t = np.linspace(0, 40, 401)
    res = ac.simulate(ElasticTransmission(), t_end=40, rtol=1e-10, t_eval=t)
    theta_r = res["motor.phi"] + JL / JM * res["load.phi"]
    tau = np.clip(t - 1.0, 0, None)
    assert np.max(np.abs(theta_r - 1.0 / JM * tau**2 / 2)) < 1e-6 * np.max(theta_r)


class TwoMotorsWithEnergy(TwoMotorsElasticLoad):
    """The example plus the energy supplied by T_m1 and the energy dissipated (3.115)."""

    E_in = ac.Variable(start=0.0, fixed=True)
    E_loss = ac.Variable(start=0.0, fixed=True)

    def equations(self):
        w1, w2 = self.motor1.w, self.motor2.w
        loss = (self.gear1_elasticity.d * ac.der(self.gear1_elasticity.phi_rel)**2
                + self.gear2_elasticity.d * ac.der(self.gear2_elasticity.phi_rel)**2
                + 0.2 * w2**2)
        return [ac.Eq(ac.der(self.E_in), self.torque_reference.y.signal * w1),
                ac.Eq(ac.der(self.E_loss), loss)]


def test_two_motors_energy_balance_3_115():
    res = ac.simulate(TwoMotorsWithEnergy(), t_end=2.0, rtol=1e-10,
                      t_eval=np.linspace(0, 2, 201))
    Va = (0.5 * (0.01 * res["motor1.w"]**2 + 0.01 * res["motor2.w"]**2 + 1.0 * res["load.w"]**2)
          + 0.5 * (100.0 * res["gear1_elasticity.phi_rel"]**2
                   + 100.0 * res["gear2_elasticity.phi_rel"]**2 + 2.0 * res["motor2.phi"]**2))
    balance = Va - Va[0] - (res["E_in"] - res["E_loss"])
    assert np.max(res["E_in"]) > 0.1
    assert np.max(np.abs(balance)) < 1e-7 * np.max(res["E_in"])
    # phi_i = theta_i - theta_L/n_b (3.110) is the spring twist (sign: phi_rel = -phi_i)
    phi1 = res["motor1.phi"] - res["load.phi"] / 0.1
    # a difference of angles of up to 0.3 rad: judged on their scale (10 rtol)
    scale = np.max(np.abs(res["motor1.phi"]))
    assert np.max(np.abs(phi1 + res["gear1_elasticity.phi_rel"])) < 1e-9 * scale
