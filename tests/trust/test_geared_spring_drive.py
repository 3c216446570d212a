"""A sine torque on a motor inertia, an ideal gear, a spring to a load inertia: the
simplest drive train of the Modelica Standard Library's rotational examples (after
Modelica.Mechanics.Rotational.Examples.First: amplitude 10 N m at 5 Hz, J_motor = 0.1,
gear ratio 10, J_2 = 2 and J_load = 2 kg m2, spring c = 1e4 N m/rad, damping 10 N m s/rad
from the load to the housing, or none), starting at rest at t = 0.

The motor is rigidly geared to inertia 2 (phi_motor = n phi_2), so four states remain;
by hand (Egeland & Gravdahl (3.12) for the reflected inertia):

    (n^2 J_motor + J_2) phi_2'' = n tau(t) - c (phi_2 - phi_L)
    J_L phi_L''                 = c (phi_2 - phi_L) - d phi_L'

Reference: that ODE under scipy's solve_ivp (DOP853, rtol 1e-12, atol 1e-14).
"""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal as ac
from acausal.library import rotational as rot
from acausal.library.blocks import Sine

AMP, F_HZ, J_M, N, J_2, J_L, C = 10.0, 5.0, 0.1, 10.0, 2.0, 2.0, 1e4
T_END = 1.0


class GearedSpringDrive(ac.Component):
    """Sine torque - motor - ideal gear - inertia 2 - spring - load (- damper - housing)."""

    sine = Sine(amplitude=AMP, f=F_HZ)
    torque = rot.Torque()
    motor = rot.Inertia(J=J_M)
    gear = rot.IdealGear(ratio=N)
    inertia_2 = rot.Inertia(J=J_2, phi={"start": 0.0, "fixed": True},
                            w={"start": 0.0, "fixed": True})
    spring = rot.Spring(c=C)
    load = rot.Inertia(J=J_L, phi={"start": 0.0, "fixed": True},
                       w={"start": 0.0, "fixed": True})

    def __init__(self, damping=10.0, **mods):
        super().__init__(**mods)
        self.damping = damping
        if damping > 0:
            self.damper = rot.Damper(d=damping)
            self.housing = rot.Fixed()

    def equations(self):
        eqs = [ac.connect(self.sine.y, self.torque.tau),
               ac.connect(self.torque.flange, self.motor.flange_a),
               ac.connect(self.motor.flange_b, self.gear.flange_a),
               ac.connect(self.gear.flange_b, self.inertia_2.flange_a),
               ac.connect(self.inertia_2.flange_b, self.spring.flange_a),
               ac.connect(self.spring.flange_b, self.load.flange_a)]
        if self.damping > 0:
            eqs += [ac.connect(self.load.flange_b, self.damper.flange_b),
                    ac.connect(self.damper.flange_a, self.housing.flange)]
        return eqs


def _reference(t, damping):
    def rhs(tt, y):
        phi_2, w_2, phi_l, w_l = y
        tau = AMP * np.sin(2 * np.pi * F_HZ * tt)
        twist = C * (phi_2 - phi_l)
        return [w_2, (N * tau - twist) / (N**2 * J_M + J_2), w_l, (twist - damping * w_l) / J_L]
    sol = solve_ivp(rhs, (0.0, T_END), [0.0, 0.0, 0.0, 0.0], method="DOP853", rtol=1e-12,
                    atol=1e-14, t_eval=t)
    return sol.y


@pytest.mark.parametrize("damping", [10.0, 0.0])
def test_geared_spring_drive_from_rest_matches_the_reduced_ode(damping):
    t = np.linspace(0.0, T_END, 201)
    res = ac.simulate(GearedSpringDrive(damping=damping), t_end=T_END, rtol=1e-9, t_eval=t)
    assert res.success, res.message
    assert res.t[-1] == pytest.approx(T_END)
    phi_2, w_2, phi_l, w_l = _reference(t, damping)
    for name, ref in (("inertia_2.phi", phi_2), ("inertia_2.w", w_2), ("load.phi", phi_l),
                      ("load.w", w_l), ("motor.w", N * w_2)):
        assert np.max(np.abs(res[name] - ref)) < 1e-6 * np.max(np.abs(ref)), name
