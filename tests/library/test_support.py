"""Support flanges (the MSL's useSupport): the reaction of a source or a gear goes into
its housing.  Checked against conservation of angular and linear momentum and the
closed-form motion of a gear on a rotating housing."""
import numpy as np
import pytest
from scipy.linalg import expm

import acausal as ac
from acausal.analysis import energy_balance
from acausal.library import electrical as el
from acausal.library import rotational as rot
from acausal.library import translational as tr
from acausal.library.blocks import Constant, Sine
from acausal.library.electromechanical import DCMotor

A, F = 2.0, 0.5            # torque amplitude [N m] and frequency [Hz]
J1, J2 = 2.0, 5.0          # rotor and housing inertias [kg m2]


class MotorOnFreeHousing(ac.Component):
    """A motor torque between a rotor and a housing that floats (both from rest)."""

    signal = Sine(amplitude=A, f=F)
    motor = rot.Torque(useSupport=True)
    rotor = rot.Inertia(J=J1)
    housing = rot.Inertia(J=J2)

    def equations(self):
        return [ac.connect(self.signal.y, self.motor.tau),
                ac.connect(self.motor.flange, self.rotor.flange_a),
                ac.connect(self.motor.support, self.housing.flange_a)]


def test_motor_reaction_goes_into_its_housing():
    t = np.linspace(0, 3, 61)
    model = MotorOnFreeHousing()
    res = ac.simulate(model, t_end=3.0, rtol=1e-10, atol=1e-12, t_eval=t)
    # the rotor gets +tau, the housing exactly -tau: int tau = A/(2 pi f)(1 - cos 2 pi f t)
    impulse = A / (2 * np.pi * F) * (1 - np.cos(2 * np.pi * F * t))
    scale = np.max(impulse) / J1
    assert np.max(np.abs(res["rotor.w"] - impulse / J1)) < 1e-8 * scale
    assert np.max(np.abs(res["housing.w"] + impulse / J2)) < 1e-8 * scale
    # no external torque: the angular momentum of rotor + housing stays 0
    L = J1 * res["rotor.w"] + J2 * res["housing.w"]
    assert np.max(np.abs(L)) < 1e-10 * J1 * scale
    assert np.max(np.abs(res["motor.support.tau"] - res["signal.y.signal"])) < 1e-10 * A
    # the source delivers tau (w_rotor - w_housing), all of it stored as kinetic energy
    audit = energy_balance(res, model)
    assert not audit.violations
    assert audit.relative_residual() < 1e-6


N, T, JA, JB = 3.0, 1.5, 0.4, 2.0   # gear ratio, drive torque, input and output inertias
WS, FS = 4.0, 0.8                   # housing speed amplitude [rad/s] and frequency [Hz]


class GearOnRotatingHousing(ac.Component):
    """A torque drives the input inertia through an IdealGear whose housing turns
    with a prescribed speed ws(t) = WS sin(2 pi FS t)."""

    drive = rot.ConstantTorque(tau_constant=T)
    input = rot.Inertia(J=JA)
    gear = rot.IdealGear(ratio=N, useSupport=True)
    output = rot.Inertia(J=JB)
    housing_speed = Sine(amplitude=WS, f=FS)
    housing = rot.Speed()

    def equations(self):
        return [ac.connect(self.drive.flange, self.input.flange_a),
                ac.connect(self.input.flange_b, self.gear.flange_a),
                ac.connect(self.gear.flange_b, self.output.flange_a),
                ac.connect(self.housing_speed.y, self.housing.w_ref),
                ac.connect(self.housing.flange, self.gear.support)]


def test_ideal_gear_on_a_rotating_housing_closed_form():
    """Relative to the housing, w_a - w_s = n (w_b - w_s); with JA w_a' = T - tau_a,
    JB w_b' = n tau_a (tau_a the gear's cut torque at flange_a) and everything at rest
    at t = 0 (ws(0) = 0):

        w_b(t) = (T t - JA (1 - n) ws(t)) / (JA n + JB / n)
    """
    t = np.linspace(0, 2, 81)
    res = ac.simulate(GearOnRotatingHousing(), t_end=2.0, rtol=1e-10, atol=1e-12, t_eval=t)
    ws = WS * np.sin(2 * np.pi * FS * t)
    wb = (T * t - JA * (1 - N) * ws) / (JA * N + JB / N)
    wa = N * wb + (1 - N) * ws
    scale = np.max(np.abs(wa))
    assert np.max(np.abs(res["output.w"] - wb)) < 1e-8 * scale
    assert np.max(np.abs(res["input.w"] - wa)) < 1e-8 * scale
    # the housing takes the difference of the flange torques:
    # support.tau = -(tau_a + tau_b) = (n - 1) tau_a with tau_a = JB w_b' / n
    ab = (T - JA * (1 - N) * WS * 2 * np.pi * FS * np.cos(2 * np.pi * FS * t)) / (JA * N + JB / N)
    tau_s = (N - 1) * JB * ab / N
    assert np.max(np.abs(res["gear.support.tau"] - tau_s)) < 1e-7 * np.max(np.abs(tau_s))


class ForceBetweenTwoMasses(ac.Component):
    """A translational force source pushing a mass off another one it is mounted on."""

    push = Constant(k=3.0)
    actuator = tr.Force(useSupport=True)
    slider = tr.Mass(m=1.5)
    base = tr.Mass(m=6.0)

    def equations(self):
        return [ac.connect(self.push.y, self.actuator.f),
                ac.connect(self.actuator.flange, self.slider.flange_a),
                ac.connect(self.actuator.support, self.base.flange_a)]


def test_force_reaction_on_the_base_conserves_momentum():
    t = np.linspace(0, 2, 21)
    res = ac.simulate(ForceBetweenTwoMasses(), t_end=2.0, rtol=1e-10, atol=1e-12, t_eval=t)
    assert np.max(np.abs(res["slider.v"] - 3.0 / 1.5 * t)) < 1e-9 * 4.0
    assert np.max(np.abs(res["base.v"] + 3.0 / 6.0 * t)) < 1e-9 * 4.0
    assert np.max(np.abs(1.5 * res["slider.v"] + 6.0 * res["base.v"])) < 1e-10 * 6.0


class SpindleOnCarriage(ac.Component):
    """A spindle (IdealGearR2T) whose nut housing rides on a carriage mass and whose
    motor housing is a free inertia: nothing is fixed, so the angular momentum of the
    rotating parts and the linear momentum of the sliding parts stay 0."""

    signal = Sine(amplitude=1.0, f=1.0)
    motor = rot.Torque(useSupport=True)
    screw = rot.Inertia(J=0.01)
    frame = rot.Inertia(J=0.5)
    spindle = rot.IdealGearR2T(ratio=100.0, useSupportR=True, useSupportT=True)
    nut = tr.Mass(m=2.0)
    carriage = tr.Mass(m=8.0)

    def equations(self):
        return [ac.connect(self.signal.y, self.motor.tau),
                ac.connect(self.motor.flange, self.screw.flange_a, self.spindle.flangeR),
                ac.connect(self.motor.support, self.frame.flange_a, self.spindle.supportR),
                ac.connect(self.spindle.flangeT, self.nut.flange_a),
                ac.connect(self.spindle.supportT, self.carriage.flange_a)]


def test_rotation_to_translation_with_both_supports():
    model = SpindleOnCarriage()
    t = np.linspace(0, 1, 41)
    res = ac.simulate(model, t_end=1.0, rtol=1e-10, atol=1e-12, t_eval=t)
    v_rel = res["nut.v"] - res["carriage.v"]
    w_rel = res["screw.w"] - res["frame.w"]
    assert np.max(np.abs(w_rel - 100.0 * v_rel)) < 1e-9 * np.max(np.abs(w_rel))
    p = 2.0 * res["nut.v"] + 8.0 * res["carriage.v"]
    assert np.max(np.abs(p)) < 1e-9 * 2.0 * np.max(np.abs(res["nut.v"]))
    L = 0.01 * res["screw.w"] + 0.5 * res["frame.w"]
    assert np.max(np.abs(L)) < 1e-9 * 0.01 * np.max(np.abs(res["screw.w"]))
    audit = energy_balance(res, model)
    assert not audit.violations and audit.relative_residual() < 1e-6


class MotorInFreeHousing(ac.Component):
    """A DC motor whose stator is mounted on a free housing inertia, driving a load."""

    source = el.ConstantVoltage(V=12.0)
    ground = el.Ground()
    motor = DCMotor(R=1.0, L=1e-3, k=0.05, J=1e-4, useSupport=True)
    load = rot.Inertia(J=2e-4)
    housing = rot.Inertia(J=5e-3)

    def equations(self):
        return [ac.connect(self.source.p, self.motor.p),
                ac.connect(self.source.n, self.motor.n, self.ground.p),
                ac.connect(self.motor.flange, self.load.flange_a),
                ac.connect(self.motor.support, self.housing.flange_a)]


def test_dc_motor_stator_reaction_into_its_housing():
    model = MotorInFreeHousing()
    t = np.linspace(0, 0.2, 41)
    res = ac.simulate(model, t_end=0.2, rtol=1e-10, atol=1e-12, t_eval=t)
    w_r, w_h = res["load.w"], res["housing.w"]
    # no torque from outside: rotor + load + housing keep zero angular momentum
    L = 3e-4 * w_r + 5e-3 * w_h
    assert np.max(np.abs(L)) < 1e-10 * 3e-4 * np.max(np.abs(w_r))
    # the back EMF sees the speed relative to the stator
    assert np.max(np.abs(res["motor.emf.v"] - 0.05 * (w_r - w_h))) < 1e-10 * 12.0
    # relative to the housing the motor drives J_eff = J_r J_h / (J_r + J_h):
    # L i' = V - R i - k w_rel,  J_eff w_rel' = k i, from rest (matrix exponential)
    J_eff = 3e-4 * 5e-3 / (3e-4 + 5e-3)
    A = np.array([[-1.0 / 1e-3, -0.05 / 1e-3], [0.05 / J_eff, 0.0]])
    B = np.array([12.0 / 1e-3, 0.0])
    exact = np.array([np.linalg.solve(A, (expm(A * ti) - np.eye(2)) @ B) for ti in t])
    assert np.max(np.abs((w_r - w_h) - exact[:, 1])) < 1e-7 * 12.0 / 0.05
    assert np.max(np.abs(res["motor.La.i"] - exact[:, 0])) < 1e-7 * 12.0
    audit = energy_balance(res, model)
    assert not audit.violations and audit.relative_residual() < 1e-6


def test_missing_support_is_named():
    with pytest.raises(AttributeError, match=r"Torque\(useSupport=True\)"):
        rot.Torque().support
    with pytest.raises(ac.ModelError, match="useSupport must be True or False"):
        rot.IdealGear(useSupport="yes")

    # a structural argument given as a modification from the parent is named as such
    class Drive(ac.Component):
        motor = rot.Torque()

    named = r"'motor' \(Torque\): 'useSupport' is a structural parameter"
    with pytest.raises(ac.ModelError, match=named + r".*Torque\(useSupport=...\)"):
        ac.compile(Drive(motor={"useSupport": True}))
    # an absent support cannot be connected: the error names the flag
    class Grounded(ac.Component):
        motor = rot.Torque()
        housing = rot.Fixed()

        def equations(self):
            return [ac.connect(self.motor.support, self.housing.flange)]

    with pytest.raises(ac.AbsentComponent, match=r"'motor' \(Torque\)\.support exists "
                                                 r"only with useSupport=True"):
        ac.compile(Grounded())
