"""Disc, Rod and MultiSensor (MSL Rotational/Translational): rigid offsets and the
torque, speed and power read at one place of a shaft, against the closed form of a
constant-torque run-up."""
import numpy as np

import acausal as ac
from acausal.library import rotational as rot
from acausal.library import translational as tr

J, T0, DPHI, L = 0.5, 2.0, 0.3, 1.2


class Shafts(ac.Component):
    """A torque drives an inertia through a disc and a multisensor; a force pushes a
    mass through a rod."""

    drive = rot.ConstantTorque(tau_constant=T0)
    disc = rot.Disc(deltaPhi=DPHI)
    sensor = rot.MultiSensor()
    wheel = rot.Inertia(J=J, phi={"start": 0.0, "fixed": True}, w={"start": 0.0, "fixed": True})
    push = tr.ConstantForce(f_constant=3.0)
    rod = tr.Rod(L=L)
    cart = tr.Mass(m=1.5, s={"start": 0.0, "fixed": True}, v={"start": 0.0, "fixed": True})

    def equations(self):
        return [ac.connect(self.drive.flange, self.disc.flange_a),
                ac.connect(self.disc.flange_b, self.sensor.flange_a),
                ac.connect(self.sensor.flange_b, self.wheel.flange_a),
                ac.connect(self.push.flange, self.rod.flange_b),
                ac.connect(self.rod.flange_a, self.cart.flange_a)]


def test_disc_rod_and_multisensor():
    t = np.linspace(0, 1, 21)
    res = ac.simulate(Shafts(), t_end=1.0, rtol=1e-10, atol=1e-12, t_eval=t)
    w = T0 / J * t
    assert np.max(np.abs(res["wheel.w"] - w)) < 1e-9 * T0 / J
    assert np.max(np.abs(res["drive.flange.phi"] - (res["wheel.phi"] - DPHI))) < 1e-12 * 1.0
    assert np.max(np.abs(res["sensor.tau.signal"] - T0)) < 1e-9 * T0
    assert np.max(np.abs(res["sensor.w.signal"] - w)) < 1e-9 * T0 / J
    assert np.max(np.abs(res["sensor.power.signal"] - T0 * w)) < 1e-9 * T0**2 / J
    assert np.max(np.abs(res["push.flange.s"] - (res["cart.s"] + L))) < 1e-12 * L
    assert np.max(np.abs(res["cart.v"] - 3.0 / 1.5 * t)) < 1e-9 * 2.0
