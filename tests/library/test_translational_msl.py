"""Translational components after the MSL (Modelica.Mechanics.Translational v4.0.0):
the rigid mass of length L and the multi-sensor, against closed forms."""
import numpy as np

import acausal as ac
from acausal.library import translational as tr

M, F, L = 2.0, 3.0, 0.8


class PushedMass(ac.Component):
    """A constant force pushes a mass of length L through a multi-sensor."""

    push = tr.ConstantForce(f_constant=F)
    sensor = tr.MultiSensor()
    mass = tr.Mass(m=M, L=L, s={"start": 0.1, "fixed": True}, v={"start": 0.0, "fixed": True})

    def equations(self):
        return [ac.connect(self.push.flange, self.sensor.flange_a),
                ac.connect(self.sensor.flange_b, self.mass.flange_a)]


def test_a_mass_of_length_L_is_pushed_at_its_left_flange_and_the_multisensor_reads_it():
    t = np.linspace(0, 2, 41)
    res = ac.simulate(PushedMass(), t_end=2.0, rtol=1e-10, atol=1e-12, t_eval=t)
    s = 0.1 + F / M * t**2 / 2                   # the centre, from rest
    v = F / M * t
    assert np.max(np.abs(res["mass.s"] - s)) < 1e-9 * np.ptp(s)
    assert np.max(np.abs(res["mass.flange_a.s"] - (s - L / 2))) < 1e-9 * np.ptp(s)
    assert np.max(np.abs(res["mass.flange_b.s"] - (s + L / 2))) < 1e-9 * np.ptp(s)
    assert np.max(np.abs(res["sensor.f"] - F)) < 1e-9 * F
    assert np.max(np.abs(res["sensor.v"] - v)) < 1e-9 * np.ptp(v)
    assert np.max(np.abs(res["sensor.power"] - F * v)) < 1e-9 * F * np.ptp(v)
