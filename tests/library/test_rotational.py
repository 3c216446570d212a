"""Rotational components: sources, sensors, converters to translation, the dead-zone
gear, against closed forms, the book's reduced equations and conservation laws."""
import numpy as np

import acausal as ac
from acausal.library import rotational as rot
from acausal.library import translational as tr
from acausal.library.blocks import Sine
from acausal.library.rotational.examples.backlash import GearWithDeadzone
from acausal.library.rotational.examples.rack_and_pinion import RackAndPinionDrive


class _Oscillator(ac.Component):
    """Inertia on a torsional spring and damper to the housing, released from 0.2 rad."""

    housing = rot.Fixed()
    inertia = rot.Inertia(J=0.5, phi={"start": 0.2, "fixed": True},
                          w={"start": 0.0, "fixed": True})


class SeparateSpringAndDamper(_Oscillator):
    spring = rot.Spring(c=8.0)
    damper = rot.Damper(d=0.3)

    def equations(self):
        return [ac.connect(self.housing.flange, self.spring.flange_a, self.damper.flange_a),
                ac.connect(self.spring.flange_b, self.damper.flange_b, self.inertia.flange_a)]


class CombinedSpringDamper(_Oscillator):
    spring_damper = rot.SpringDamper(c=8.0, d=0.3)

    def equations(self):
        return [ac.connect(self.housing.flange, self.spring_damper.flange_a),
                ac.connect(self.spring_damper.flange_b, self.inertia.flange_a)]


def test_spring_and_damper_in_parallel_equal_spring_damper():
    t = np.linspace(0, 5, 101)
    a = ac.simulate(SeparateSpringAndDamper(), t_end=5, rtol=1e-10, t_eval=t)
    b = ac.simulate(CombinedSpringDamper(), t_end=5, rtol=1e-10, t_eval=t)
    assert np.max(np.abs(a["inertia.phi"] - b["inertia.phi"])) < 1e-8
    # and both are the damped oscillator J phi'' + d phi' + c phi = 0
    w0, zeta = np.sqrt(8.0 / 0.5), 0.3 / (2 * np.sqrt(8.0 * 0.5))
    wd = w0 * np.sqrt(1 - zeta**2)
    exact = 0.2 * np.exp(-zeta * w0 * t) * (np.cos(wd * t) + zeta * w0 / wd * np.sin(wd * t))
    assert np.max(np.abs(a["inertia.phi"] - exact)) < 1e-7


def test_rack_and_pinion_reduced_equation_3_18():
    """(J_m + m r^2) w_m' = T - r F_e  and  v = r w_m  (3.14), (3.18)."""
    t = np.linspace(0, 1, 51)
    res = ac.simulate(RackAndPinionDrive(), t_end=1.0, rtol=1e-10, t_eval=t)
    acc = (2.0 - 0.05 * 5.0) / (0.01 + 10.0 * 0.05**2)
    assert np.max(np.abs(res["motor.w"] - acc * t)) < 1e-8 * acc
    assert np.max(np.abs(res["cart.v"] - 0.05 * res["motor.w"])) < 1e-10 * acc
    # the rack force is F = T_L / r  (3.15)
    assert np.max(np.abs(-res["pinion.flangeT.f"] - res["pinion.flangeR.tau"] / 0.05)) < 1e-8


class WheelOnCart(ac.Component):
    """IdealGearR2T and IdealRollingWheel pushing masses with a speed-driven flange."""

    reference = Sine(amplitude=2.0, f=0.5)
    drive = rot.Speed()
    r2t = rot.IdealGearR2T(ratio=20.0)
    cart = tr.Mass(m=3.0)
    wheel = rot.IdealRollingWheel(radius=0.25)
    car = tr.Mass(m=2.0)
    speed = rot.SpeedSensor()
    power = rot.PowerSensor()

    def equations(self):
        return [ac.connect(self.reference.y, self.drive.w_ref),
                ac.connect(self.drive.flange, self.speed.flange, self.power.flange_a),
                ac.connect(self.power.flange_b, self.r2t.flangeR, self.wheel.flangeR),
                ac.connect(self.r2t.flangeT, self.cart.flange_a),
                ac.connect(self.wheel.flangeT, self.car.flange_a)]


def test_rotation_to_translation_kinematics_and_power():
    t = np.linspace(0, 2, 81)
    res = ac.simulate(WheelOnCart(), t_end=2, rtol=1e-10, t_eval=t)
    w = 2.0 * np.sin(np.pi * t)
    # the imposed speed, evaluated, not integrated: to rounding of its amplitude 2 rad/s
    assert np.max(np.abs(res["speed.w.signal"] - w)) < 1e-12 * 2.0
    assert np.max(np.abs(res["cart.v"] - w / 20.0)) < 1e-8
    assert np.max(np.abs(res["car.v"] - 0.25 * w)) < 1e-8
    # the drive's power goes into the kinetic energy of the two masses
    power = 3.0 * res["cart.v"] * res["cart.a"] + 2.0 * res["car.v"] * res["car.a"]
    assert np.max(np.abs(res["power.power.signal"] - power)) < 1e-7


class PositionDrivenInertia(ac.Component):
    reference = Sine(amplitude=0.5, f=1.0)
    drive = rot.Position()
    sensor = rot.TorqueSensor()
    inertia = rot.Inertia(J=0.2)
    angle = rot.AngleSensor()

    def equations(self):
        return [ac.connect(self.reference.y, self.drive.phi_ref),
                ac.connect(self.drive.flange, self.sensor.flange_a),
                ac.connect(self.sensor.flange_b, self.inertia.flange_a, self.angle.flange)]


def test_position_source_differentiates_its_reference():
    """phi = 0.5 sin(2 pi t) imposed: the torque through the sensor is J phi''."""
    t = np.linspace(0, 1, 41)
    res = ac.simulate(PositionDrivenInertia(), t_end=1, rtol=1e-10, t_eval=t)
    # the imposed angle, evaluated: to rounding of its amplitude 0.5 rad
    assert np.max(np.abs(res["angle.phi.signal"] - 0.5 * np.sin(2 * np.pi * t))) < 1e-12 * 0.5
    tau = -0.2 * 0.5 * (2 * np.pi)**2 * np.sin(2 * np.pi * t)
    assert np.max(np.abs(res["sensor.tau.signal"] - tau)) < 1e-8


class TorqueSteps(ac.Component):
    step = rot.TorqueStep(stepTorque=3.0, offsetTorque=1.0, startTime=0.5)
    inertia = rot.Inertia(J=2.0)
    drag = rot.ConstantSpeed(w_fixed=0.7)
    slip = rot.Damper(d=0.4)
    relative = rot.RelSpeedSensor()

    def equations(self):
        return [ac.connect(self.step.flange, self.inertia.flange_a),
                ac.connect(self.inertia.flange_b, self.slip.flange_a, self.relative.flange_a),
                ac.connect(self.slip.flange_b, self.drag.flange, self.relative.flange_b)]


def test_step_torque_against_damper_to_constant_speed():
    """J w' = T(t) - d (w - w_0): exponential approach, the step at 0.5 s an event."""
    t = np.linspace(0, 3, 61)
    res = ac.simulate(TorqueSteps(), t_end=3, rtol=1e-10, t_eval=t)
    a, w0 = 0.4 / 2.0, 0.7

    def segment(w_start, torque, tau):
        w_inf = w0 + torque / 0.4
        return w_inf + (w_start - w_inf) * np.exp(-a * tau)

    w_half = segment(0.0, 1.0, 0.5)
    exact = np.where(t < 0.5, segment(0.0, 1.0, t), segment(w_half, 4.0, t - 0.5))
    assert np.max(np.abs(res["inertia.w"] - exact)) < 1e-7
    assert np.max(np.abs(res["relative.w_rel.signal"] - (w0 - res["inertia.w"]))) < 1e-9


def _deadzone_energy(res, K=100.0, delta=0.05):
    phi = res["gear.phi"]
    stretch = np.where(np.abs(phi) > delta, np.abs(phi) - delta, 0.0)
    return 0.5 * 0.01 * res["motor.w"]**2 + 0.5 * 0.5 * res["load.w"]**2 + 0.5 * K * stretch**2


def test_elastic_gear_with_deadzone_3_119():
    # 22 contacts at sqrt(K/J_m) = 100 rad/s: the energy error of BDF accumulates over
    # them and shrinks with rtol (5e-7, 1e-8, 4e-10 at rtol 1e-8, 1e-10, 1e-12)
    t = np.linspace(0, 0.5, 2001)
    res = ac.simulate(GearWithDeadzone(), t_end=0.5, rtol=1e-12, t_eval=t)
    phi, tau = res["gear.phi"], res["gear.tau"]
    law = np.where(phi < -0.05, 100.0 * (phi + 0.05), np.where(phi > 0.05, 100.0 * (phi - 0.05), 0))
    assert np.max(np.abs(tau - law)) < 1e-9
    assert len(res.events) >= 4                      # contact entered and left, both sides
    assert np.min(phi) < -0.05 < 0.05 < np.max(phi)
    energy = _deadzone_energy(res)
    assert np.max(np.abs(energy - energy[0])) < 1e-8 * energy[0]
    # no external torque: J_m w_m + J_L w_L / n is conserved (J_m w_m' = -tau, J_L w_L' = n tau)
    momentum = 0.01 * res["motor.w"] + 0.5 * res["load.w"] / 5.0
    assert np.max(np.abs(momentum - momentum[0])) < 1e-7 * abs(momentum[0])
