"""Clutch (MSL Rotational.Components.Clutch, constant mu): engaging two inertias at
different speeds slips at a constant torque until the speeds meet, then sticks; the
piecewise-linear closed form, the momentum and the energy lost."""
import numpy as np

import acausal as ac
from acausal.analysis import energy_balance
from acausal.library import rotational as rot
from acausal.library.blocks import Step

J1, J2, W1, MU, CGEO, FN, T_ON = 1.0, 2.0, 10.0, 0.4, 0.1, 300.0, 0.1


class Engagement(ac.Component):
    """A spinning inertia and one at rest, the clutch closed at T_ON."""

    pedal = Step(height=1.0, startTime=T_ON)
    a = rot.Inertia(J=J1, phi={"start": 0.0, "fixed": True}, w={"start": W1, "fixed": True})
    clutch = rot.Clutch(mu=MU, peak=1.0, cgeo=CGEO, fn_max=FN)
    b = rot.Inertia(J=J2, phi={"start": 0.0, "fixed": True}, w={"start": 0.0, "fixed": True})

    def equations(self):
        return [ac.connect(self.pedal.y, self.clutch.f_normalized),
                ac.connect(self.a.flange_b, self.clutch.flange_a),
                ac.connect(self.clutch.flange_b, self.b.flange_a)]


def test_clutch_slips_then_sticks_closed_form():
    """Slipping, the friction torque T = mu cgeo fn acts against the slip: J1 w1' = -T,
    J2 w2' = T, until w1 = w2 at t* = T_ON + W1 / (T (1/J1 + 1/J2)); then they turn
    together at the momentum's speed J1 W1 / (J1 + J2)."""
    T = MU * CGEO * FN
    t_stick = T_ON + W1 / (T * (1 / J1 + 1 / J2))
    t = np.linspace(0, 1.0, 101)
    model = Engagement()
    res = ac.simulate(model, t_end=1.0, rtol=1e-10, atol=1e-12, t_eval=t)
    assert t_stick < 0.9
    slip = np.clip(t - T_ON, 0, t_stick - T_ON)
    w1 = W1 - T / J1 * slip
    w2 = T / J2 * slip
    assert np.max(np.abs(res["a.w"] - w1)) < 1e-6 * W1
    assert np.max(np.abs(res["b.w"] - w2)) < 1e-6 * W1
    # momentum is kept, up to the sticking event, which sets the slip speed from the
    # band's edge dv to 0 (one of the speeds jumps by at most dv)
    L = J1 * res["a.w"] + J2 * res["b.w"]
    dv = 1e-6
    assert np.max(np.abs(L[t < t_stick] - J1 * W1)) < 1e-8 * J1 * W1
    assert np.max(np.abs(L - J1 * W1)) < 1.01 * max(J1, J2) * dv
    # the stick event is located at t*
    times = [float(e) for e in res.events]
    assert min(abs(ti - t_stick) for ti in times) < 1e-6 * t_stick
    # the energy lost in the slip: the relative kinetic energy J_eff W1^2 / 2
    audit = energy_balance(res, model)
    assert not audit.violations
    J_eff = J1 * J2 / (J1 + J2)
    E = J1 * res["a.w"]**2 / 2 + J2 * res["b.w"]**2 / 2
    assert abs((J1 * W1**2 / 2 - E[-1]) - J_eff * W1**2 / 2) < 1e-5 * J1 * W1**2 / 2


class Braking(ac.Component):
    """A spinning wheel braked from T_ON on, then held against a drive torque below the
    static friction."""

    pedal = Step(height=1.0, startTime=T_ON)
    drive = rot.ConstantTorque(tau_constant=5.0)
    wheel = rot.Inertia(J=J1, phi={"start": 0.0, "fixed": True}, w={"start": W1, "fixed": True})
    brake = rot.Brake(mu=MU, peak=1.2, cgeo=CGEO, fn_max=FN)

    def equations(self):
        return [ac.connect(self.pedal.y, self.brake.f_normalized),
                ac.connect(self.drive.flange, self.wheel.flange_a),
                ac.connect(self.wheel.flange_b, self.brake.flange_a)]


def test_brake_stops_the_wheel_and_holds_it():
    """J w' = 5 before T_ON, 5 - T while sliding (T = mu cgeo fn = 12 > 5), stopped at
    t* = T_ON + J w(T_ON) / (T - 5); then held: 5 N m < peak T."""
    T = MU * CGEO * FN
    t_stop = T_ON + (J1 * W1 + 5.0 * T_ON) / (T - 5.0)
    t = np.linspace(0, 2.0, 81)
    res = ac.simulate(Braking(), t_end=2.0, rtol=1e-10, atol=1e-12, t_eval=t)
    slide = np.clip(t - T_ON, 0, t_stop - T_ON)
    w = W1 + 5.0 / J1 * np.minimum(t, T_ON) - (T - 5.0) / J1 * slide
    w = np.where(t >= t_stop, 0.0, w)
    assert np.max(np.abs(res["wheel.w"] - w)) < 1e-5 * W1
    held = t > t_stop + 0.01
    assert np.max(np.abs(res["brake.tau"][held] - 5.0)) < 1e-8 * 5.0
