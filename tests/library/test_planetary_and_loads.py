"""IdealPlanetary, speed-dependent load torques, Torque2, Accelerate and the
acceleration sensors (MSL Rotational) against closed forms and conservation laws."""
import numpy as np
import pytest

import acausal as ac
from acausal.analysis import energy_balance
from acausal.library import rotational as rot
from acausal.library.blocks import Sine

T, R = 2.0, 2.5                  # torque on the sun [N m], ring/sun teeth
JS, JC, JR = 0.1, 0.6, 0.9       # sun, carrier, ring inertias [kg m2]


class FreePlanetary(ac.Component):
    """A torque on the sun; sun, carrier and ring each carry an inertia, none fixed."""

    drive = rot.ConstantTorque(tau_constant=T)
    sun = rot.Inertia(J=JS)
    carrier = rot.Inertia(J=JC)
    ring = rot.Inertia(J=JR)
    gear = rot.IdealPlanetary(ratio=R)

    def equations(self):
        return [ac.connect(self.drive.flange, self.sun.flange_a),
                ac.connect(self.sun.flange_b, self.gear.sun),
                ac.connect(self.gear.carrier, self.carrier.flange_a),
                ac.connect(self.gear.ring, self.ring.flange_a)]


def test_free_planetary_closed_form():
    """With tau the gear's cut torque at the sun: JS a_s = T - tau, JR a_r = -R tau,
    JC a_c = (1 + R) tau and (1 + R) a_c = a_s + R a_r, so
    tau = (T/JS) / ((1 + R)^2/JC + 1/JS + R^2/JR) and all accelerations are constant."""
    model = FreePlanetary()
    t = np.linspace(0, 1, 21)
    res = ac.simulate(model, t_end=1.0, rtol=1e-10, atol=1e-12, t_eval=t)
    tau = (T / JS) / ((1 + R)**2 / JC + 1 / JS + R**2 / JR)
    a_s, a_r, a_c = (T - tau) / JS, -R * tau / JR, (1 + R) * tau / JC
    scale = abs(a_s)
    assert np.max(np.abs(res["sun.w"] - a_s * t)) < 1e-9 * scale
    assert np.max(np.abs(res["ring.w"] - a_r * t)) < 1e-9 * scale
    assert np.max(np.abs(res["carrier.w"] - a_c * t)) < 1e-9 * scale
    # the gear is free: the angular momentum grows by the drive's impulse alone
    L = JS * res["sun.w"] + JC * res["carrier.w"] + JR * res["ring.w"]
    assert np.max(np.abs(L - T * t)) < 1e-9 * T
    assert not energy_balance(res, model).violations


J, T0 = 0.05, 3.0


def fan(TorqueDirection, tau_nominal, w_nominal):
    class Fan(ac.Component):
        """A constant drive torque against a speed-dependent load, from rest."""

        drive = rot.ConstantTorque(tau_constant=T0)
        rotor = rot.Inertia(J=J, phi={"start": 0.0, "fixed": True},
                            w={"start": 0.0, "fixed": True})
        load = rot.QuadraticSpeedDependentTorque(TorqueDirection=TorqueDirection,
                                                 tau_nominal=tau_nominal,
                                                 w_nominal=w_nominal)
        linear = rot.LinearSpeedDependentTorque(TorqueDirection=False, tau_nominal=-0.0,
                                                w_nominal=1.0)

        def equations(self):
            return [ac.connect(self.drive.flange, self.rotor.flange_a),
                    ac.connect(self.rotor.flange_b, self.load.flange, self.linear.flange)]

    return Fan()


def test_quadratic_load_torque_tanh_run_up():
    """J w' = T0 - k w |w| (k = Tn / wn^2):  w = w_inf tanh(t sqrt(T0 k) / J)."""
    Tn, wn = 1.5, 20.0
    t = np.linspace(0, 1, 41)
    res = ac.simulate(fan(False, -Tn, wn), t_end=1.0, rtol=1e-10, atol=1e-12, t_eval=t)
    k = Tn / wn**2
    w_inf = np.sqrt(T0 / k)
    exact = w_inf * np.tanh(t * np.sqrt(T0 * k) / J)
    assert np.max(np.abs(res["rotor.w"] - exact)) < 1e-8 * w_inf
    assert np.max(np.abs(res["load.tau"] + k * res["rotor.w"]**2)) < 1e-8 * T0


class LinearLoad(ac.Component):
    """A drive against a viscous load tau = tau_nominal w / w_nominal (tau_nominal < 0)."""

    drive = rot.ConstantTorque(tau_constant=T0)
    rotor = rot.Inertia(J=J, phi={"start": 0.0, "fixed": True}, w={"start": 0.0, "fixed": True})
    load = rot.LinearSpeedDependentTorque(TorqueDirection=False, tau_nominal=-0.3,
                                          w_nominal=2.0)

    def equations(self):
        return [ac.connect(self.drive.flange, self.rotor.flange_a),
                ac.connect(self.rotor.flange_b, self.load.flange)]


def test_linear_load_torque_exponential_run_up():
    """J w' = T0 - b w (b = 0.3 / 2):  w = (T0 / b)(1 - exp(-b t / J))."""
    b = 0.3 / 2.0
    t = np.linspace(0, 2, 41)
    res = ac.simulate(LinearLoad(), t_end=2.0, rtol=1e-10, atol=1e-12, t_eval=t)
    exact = T0 / b * (1 - np.exp(-b * t / J))
    assert np.max(np.abs(res["rotor.w"] - exact)) < 1e-8 * T0 / b


class AcceleratedShaft(ac.Component):
    """A flange accelerated by a_ref = 3 sin(2 pi t), a torque between two free
    inertias, and the acceleration sensors on both."""

    a_ref = Sine(amplitude=3.0, f=1.0)
    drive = rot.Accelerate(w={"start": 0.5, "fixed": True}, phi={"start": 0.0, "fixed": True})
    hub = rot.Inertia(J=0.2)
    acc = rot.AccSensor()
    housing = rot.Fixed()
    rel_acc = rot.RelAccSensor()
    push = Sine(amplitude=1.0, f=2.0)
    pair = rot.Torque2()
    left = rot.Inertia(J=1.0)
    right = rot.Inertia(J=4.0)

    def equations(self):
        return [ac.connect(self.a_ref.y, self.drive.a_ref),
                ac.connect(self.drive.flange, self.hub.flange_a, self.acc.flange,
                           self.rel_acc.flange_b),
                ac.connect(self.housing.flange, self.rel_acc.flange_a),
                ac.connect(self.push.y, self.pair.tau),
                ac.connect(self.pair.flange_a, self.left.flange_a),
                ac.connect(self.pair.flange_b, self.right.flange_a)]


def test_accelerate_and_acceleration_sensors():
    t = np.linspace(0, 1, 41)
    res = ac.simulate(AcceleratedShaft(), t_end=1.0, rtol=1e-10, atol=1e-12, t_eval=t)
    a = 3.0 * np.sin(2 * np.pi * t)
    w = 0.5 + 3.0 / (2 * np.pi) * (1 - np.cos(2 * np.pi * t))
    assert np.max(np.abs(res["hub.w"] - w)) < 1e-8 * 3.0
    assert np.max(np.abs(res["acc.a.signal"] - a)) < 1e-8 * 3.0
    assert np.max(np.abs(res["rel_acc.a_rel.signal"] - a)) < 1e-8 * 3.0
    # Torque2 pushes the pair apart: no net impulse, so J_l w_l + J_r w_r = 0
    assert np.max(np.abs(res["left.w"] + 4.0 * res["right.w"])) < 1e-10
    impulse = (1 - np.cos(4 * np.pi * t)) / (4 * np.pi)
    assert np.max(np.abs(res["right.w"] - impulse / 4.0)) < 1e-9


def test_torque_direction_must_be_a_bool():
    with pytest.raises(ac.ModelError, match="TorqueDirection must be True or False"):
        rot.QuadraticSpeedDependentTorque(TorqueDirection=1)
