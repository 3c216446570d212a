"""Translational speed-dependent forces, Force2, Accelerate and the speed and
acceleration sensors (MSL Translational) against closed forms and momentum."""
import numpy as np
import pytest

import acausal as ac
from acausal.library import translational as tr
from acausal.library.blocks import Sine

M, F0 = 1200.0, 3000.0           # vehicle mass [kg], traction force [N]


class Vehicle(ac.Component):
    """A traction force against air drag (quadratic, a load) and a viscous drag taken
    against a belt that moves at 2 m/s (on the support of the linear force)."""

    traction = tr.ConstantForce(f_constant=F0)
    car = tr.Mass(m=M, s={"start": 0.0, "fixed": True}, v={"start": 0.0, "fixed": True})
    drag = tr.QuadraticSpeedDependentForce(ForceDirection=False, f_nominal=-400.0,
                                           v_nominal=20.0)
    viscous = tr.LinearSpeedDependentForce(ForceDirection=False, useSupport=True,
                                           f_nominal=-0.0, v_nominal=1.0)
    belt = tr.ConstantSpeed(v_fixed=2.0)

    def equations(self):
        return [ac.connect(self.traction.flange, self.car.flange_a),
                ac.connect(self.car.flange_b, self.drag.flange, self.viscous.flange),
                ac.connect(self.viscous.support, self.belt.flange)]


def test_air_drag_tanh_run_up():
    """m v' = F0 - k v |v|, k = 400 / 20^2:  v = v_inf tanh(t sqrt(F0 k) / m)."""
    t = np.linspace(0, 60, 61)
    res = ac.simulate(Vehicle(), t_end=60.0, rtol=1e-10, atol=1e-12, t_eval=t)
    k = 400.0 / 20.0**2
    v_inf = np.sqrt(F0 / k)
    assert np.max(np.abs(res["car.v"] - v_inf * np.tanh(t * np.sqrt(F0 * k) / M))) \
        < 1e-8 * v_inf
    # the linear force measures its speed against the belt (its support)
    assert np.max(np.abs(res["viscous.v"] - (res["car.v"] - 2.0))) < 1e-9 * v_inf


class BeltDrag(ac.Component):
    """A mass dragged by a belt through a viscous force f = f_nominal (v - v_belt)/v_nominal
    (f_nominal < 0), from rest."""

    block = tr.Mass(m=2.0, s={"start": 0.0, "fixed": True}, v={"start": 0.0, "fixed": True})
    viscous = tr.LinearSpeedDependentForce(ForceDirection=False, useSupport=True,
                                           f_nominal=-6.0, v_nominal=1.5)
    belt = tr.ConstantSpeed(v_fixed=2.0)

    def equations(self):
        return [ac.connect(self.block.flange_a, self.viscous.flange),
                ac.connect(self.viscous.support, self.belt.flange)]


def test_linear_force_relative_to_a_moving_support():
    """m v' = -b (v - 2), b = 6 / 1.5:  v = 2 (1 - exp(-b t / m)); the belt takes the
    reaction."""
    b = 6.0 / 1.5
    t = np.linspace(0, 2, 41)
    res = ac.simulate(BeltDrag(), t_end=2.0, rtol=1e-10, atol=1e-12, t_eval=t)
    assert np.max(np.abs(res["block.v"] - 2.0 * (1 - np.exp(-b * t / 2.0)))) < 1e-8 * 2.0
    # support.f = -flange.f = f: the belt is pulled back by what drags the block forward
    assert np.max(np.abs(res["viscous.support.f"] - res["viscous.f"])) < 1e-10 * b * 2.0
    assert np.max(np.abs(res["viscous.f"] + b * (res["block.v"] - 2.0))) < 1e-9 * b * 2.0


class AcceleratedSlider(ac.Component):
    """A slider accelerated by a_ref = 2 sin(2 pi t) and read by the sensors; a force
    between two free masses."""

    a_ref = Sine(amplitude=2.0, f=1.0)
    drive = tr.Accelerate(v={"start": 0.3, "fixed": True}, s={"start": 0.0, "fixed": True})
    slider = tr.Mass(m=0.5)
    acc = tr.AccSensor()
    wall = tr.Fixed()
    rel_speed = tr.RelSpeedSensor()
    rel_acc = tr.RelAccSensor()
    push = Sine(amplitude=5.0, f=2.0)
    pair = tr.Force2()
    left = tr.Mass(m=1.0)
    right = tr.Mass(m=3.0)

    def equations(self):
        return [ac.connect(self.a_ref.y, self.drive.a_ref),
                ac.connect(self.drive.flange, self.slider.flange_a, self.acc.flange,
                           self.rel_speed.flange_b, self.rel_acc.flange_b),
                ac.connect(self.wall.flange, self.rel_speed.flange_a, self.rel_acc.flange_a),
                ac.connect(self.push.y, self.pair.f),
                ac.connect(self.pair.flange_a, self.left.flange_a),
                ac.connect(self.pair.flange_b, self.right.flange_a)]


def test_accelerate_sensors_and_force2():
    t = np.linspace(0, 1, 41)
    res = ac.simulate(AcceleratedSlider(), t_end=1.0, rtol=1e-10, atol=1e-12, t_eval=t)
    a = 2.0 * np.sin(2 * np.pi * t)
    v = 0.3 + 2.0 / (2 * np.pi) * (1 - np.cos(2 * np.pi * t))
    assert np.max(np.abs(res["acc.a.signal"] - a)) < 1e-8 * 2.0
    assert np.max(np.abs(res["rel_acc.a_rel.signal"] - a)) < 1e-8 * 2.0
    assert np.max(np.abs(res["rel_speed.v_rel.signal"] - v)) < 1e-8 * 2.0
    assert np.max(np.abs(res["left.v"] + 3.0 * res["right.v"])) < 1e-10 * 5.0
    impulse = 5.0 * (1 - np.cos(4 * np.pi * t)) / (4 * np.pi)
    assert np.max(np.abs(res["right.v"] - impulse / 3.0)) < 1e-9 * 5.0


def test_force_direction_must_be_a_bool():
    with pytest.raises(ac.ModelError, match="ForceDirection must be True or False"):
        tr.LinearSpeedDependentForce(ForceDirection="no")
