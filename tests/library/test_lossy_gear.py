"""LossyGear (MSL Rotational.Components.LossyGear): a gear with mesh efficiency driving
a load (the output power is eta times the input), a gear held by its bearing friction
until a ramped load torque breaks it away, and the ideal table, each against its closed
form; and the energy audit (tauLoss w_a is the power lost)."""
import numpy as np
import pytest

import acausal as ac
from acausal.analysis import energy_balance
from acausal.library import rotational as rot

R, J1, J2 = 2.0, 0.5, 3.0


def geared(lossTable, drive_a=0.0, ramp_b=0.0):
    class Geared(ac.Component):
        """A constant torque on inertia 1 (flange_a side), a ramp torque on inertia 2."""

        drive = rot.ConstantTorque(tau_constant=drive_a)
        one = rot.Inertia(J=J1, phi={"start": 0.0, "fixed": True},
                          w={"start": 0.0, "fixed": True})
        gear = rot.LossyGear(ratio=R, lossTable=lossTable)
        two = rot.Inertia(J=J2)
        load = rot.Torque()
        E_loss = ac.Variable(start=0.0, fixed=True, unit="J", description="energy lost")

        def equations(self):
            return [ac.connect(self.drive.flange, self.one.flange_a),
                    ac.connect(self.one.flange_b, self.gear.flange_a),
                    ac.connect(self.gear.flange_b, self.two.flange_a),
                    ac.connect(self.two.flange_b, self.load.flange),
                    ac.Eq(self.load.tau, ramp_b * ac.time),
                    ac.Eq(ac.der(self.E_loss), self.gear.lossPower)]

    return Geared()


def test_a_gear_of_efficiency_eta_delivers_eta_times_the_input_power():
    eta, T = 0.8, 4.0
    model = geared([[0, eta, 0.6, 0, 0]], drive_a=T)
    t = np.linspace(0, 1, 21)
    res = ac.simulate(model, t_end=1.0, rtol=1e-10, atol=1e-12, t_eval=t)
    # J1 a1 = T - fa,  r eta fa = J2 a1 / r   =>   a1 = r^2 eta T / (J2 + r^2 eta J1)
    a1 = R**2 * eta * T / (J2 + R**2 * eta * J1)
    assert np.max(np.abs(res["one.w"] - a1 * t)) < 1e-8 * a1
    p_in = res["gear.flange_a.tau"] * res["one.w"]
    p_out = -res["gear.flange_b.tau"] * res["two.w"]
    assert np.max(np.abs(p_out - eta * p_in)) < 1e-8 * np.max(p_in)
    assert np.max(np.abs(res["gear.lossPower"] - (1 - eta) * p_in)) < 1e-8 * np.max(p_in)
    assert not energy_balance(res, model).violations


def test_bearing_friction_holds_the_gear_until_the_load_exceeds_it():
    B, k = 1.5, 2.0                      # friction [N.m] on the flange_a side, ramp [N.m/s]
    model = geared([[0, 1, 1, B, B]], ramp_b=k)
    t = np.linspace(0, 3, 61)
    res = ac.simulate(model, t_end=3.0, rtol=1e-10, atol=1e-12, t_eval=t)
    # locked while the load k t, seen at flange_a (k t / r), is below B; then
    # a1 = r (k t - r B) / (J2 + r^2 J1)
    t_star = R * B / k
    w1 = np.where(t > t_star, R * k * (t - t_star)**2 / (2 * (J2 + R**2 * J1)), 0.0)
    assert np.max(np.abs(res["one.w"] - w1)) < 1e-7 * np.max(w1)
    assert np.max(np.abs(res["two.w"][t < t_star])) < 1e-12
    assert np.min(np.abs(np.asarray(res.events) - t_star)) < 1e-8
    # sliding, the gear loses B w_a
    late = t > t_star + 0.1
    assert np.max(np.abs(res["gear.lossPower"][late] - B * res["one.w"][late])) \
        < 1e-8 * B * np.max(w1)
    assert not energy_balance(res, model).violations


def test_the_ideal_table_is_an_ideal_gear():
    T = 3.0
    res = ac.simulate(geared([[0, 1, 1, 0, 0]], drive_a=T), t_end=1.0, rtol=1e-10,
                      atol=1e-12, t_eval=np.linspace(0, 1, 11))
    a1 = R**2 * T / (J2 + R**2 * J1)
    assert np.max(np.abs(res["one.w"] - a1 * res.t)) < 1e-9 * a1
    # its mode signals follow the speed's sign: rolling forward from the start ...
    assert (res["gear.mode"] == 1).all() and not res["gear.locked"].any()
    assert not res["gear.free"].any()
    # ... and at rest without a torque, stuck
    rest = ac.simulate(geared([[0, 1, 1, 0, 0]], drive_a=0.0), t_end=1.0, n_points=3)
    assert (rest["gear.mode"] == 0).all() and rest["gear.locked"].all()
    assert rot.LossyGear().ideal and not rot.LossyGear(lossTable=[0, 0.9, 0.9, 0, 0]).ideal


@pytest.mark.parametrize("table, words", [([[0, 1, 1]], "n x 5"),
                                          ([[0, 0, 1, 0, 0]], "mesh efficiency"),
                                          ([[1, 1, 1, 0, 0], [0, 1, 1, 0, 0]], "increase")])
def test_a_bad_loss_table_is_refused(table, words):
    with pytest.raises(ac.InvalidValue, match=words):
        rot.LossyGear(lossTable=table)
