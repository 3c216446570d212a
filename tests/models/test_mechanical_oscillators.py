"""Mechanical systems against closed forms: oscillators, normal modes, motor steady state."""
import numpy as np

import acausal as ac
from acausal.library import rotational as rot
from acausal.library import translational as tr
from acausal.library.electrical import ConstantVoltage, Ground
from acausal.library.electromechanical import DCMotor


class MassSpringDamper(ac.Component):
    """m x'' + d x' + c x = 0, x(0) = 0.1, fixed at one end (Egeland & Gravdahl 2.1.2)."""

    wall = tr.Fixed()
    spring = tr.Spring(c=4.0)
    damper = tr.Damper(d=0.0)
    mass = tr.Mass(m=1.0, s={"start": 0.1, "fixed": True}, v={"start": 0.0, "fixed": True})

    def equations(self):
        return [ac.connect(self.wall.flange, self.spring.flange_a, self.damper.flange_a),
                ac.connect(self.spring.flange_b, self.damper.flange_b, self.mass.flange_a)]


def test_undamped_mass_spring_oscillator():
    t = np.linspace(0, 10, 201)
    res = ac.simulate(MassSpringDamper(), t_end=10, rtol=1e-8, t_eval=t)
    assert np.max(np.abs(res["mass.s"] - 0.1 * np.cos(2.0 * t))) / 0.1 < 1e-5


def test_damped_mass_spring_oscillator():
    t = np.linspace(0, 10, 201)
    res = ac.simulate(MassSpringDamper(damper={"d": 0.8}), t_end=10, rtol=1e-8, t_eval=t)
    zeta_w0, wd = 0.4, np.sqrt(4.0 - 0.16)
    exact = 0.1 * np.exp(-zeta_w0 * t) * (np.cos(wd * t) + zeta_w0 / wd * np.sin(wd * t))
    assert np.max(np.abs(res["mass.s"] - exact)) / 0.1 < 1e-5


class TwoMasses(ac.Component):
    """Two free masses joined by a spring: normal-mode frequency sqrt(c (1/m1 + 1/m2))."""

    m1 = tr.Mass(m=1.0, s={"start": 0.0, "fixed": True}, v={"start": 0.0, "fixed": True})
    k = tr.Spring(c=10.0)
    m2 = tr.Mass(m=3.0, s={"start": 0.2, "fixed": True}, v={"start": 0.0, "fixed": True})

    def equations(self):
        return [ac.connect(self.m1.flange_b, self.k.flange_a),
                ac.connect(self.k.flange_b, self.m2.flange_a)]


def test_two_masses_normal_mode():
    t = np.linspace(0, 5, 201)
    res = ac.simulate(TwoMasses(), t_end=5, rtol=1e-8, t_eval=t)
    w = np.sqrt(10.0 * (1 / 1.0 + 1 / 3.0))
    # the centre of mass stays at rest; the stretch oscillates at the normal mode
    com = (1.0 * res["m1.s"] + 3.0 * res["m2.s"]) / 4.0
    assert np.max(np.abs(com - 0.15)) < 1e-7
    stretch = res["m2.s"] - res["m1.s"]
    assert np.max(np.abs(stretch - 0.2 * np.cos(w * t))) / 0.2 < 1e-5


class MotorWithFriction(ac.Component):
    """DC motor on a constant voltage with viscous friction b on the rotor."""

    src = ConstantVoltage(V=12.0)
    gnd = Ground()
    motor = DCMotor(R=2.0, L=5e-3, k=0.1, J=2e-3)
    friction = rot.Damper(d=5e-3)
    housing = rot.Fixed()

    def equations(self):
        return [ac.connect(self.src.p, self.motor.p), ac.connect(self.src.n, self.motor.n, self.gnd.p),
                ac.connect(self.motor.flange, self.friction.flange_a),
                ac.connect(self.friction.flange_b, self.housing.flange)]


def test_dc_motor_steady_state_speed():
    res = ac.simulate(MotorWithFriction(), t_end=5.0, rtol=1e-8)
    w_ss = 0.1 * 12.0 / (0.1**2 + 2.0 * 5e-3)     # omega = k V / (k^2 + R b)
    assert abs(res["motor.rotor.w"][-1] - w_ss) / w_ss < 1e-5
    # power balance at steady state: V i = R i^2 + b w^2
    i, w = res["motor.La.i"][-1], res["motor.rotor.w"][-1]
    assert abs(12.0 * i - (2.0 * i**2 + 5e-3 * w**2)) < 1e-6 * 12.0 * i
