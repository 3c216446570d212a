"""Relative states of dampers and spring-dampers (MSL PartialCompliantWithRelativeStates)
and their lossPower: a stiff shaft twisting by 1e-6 rad while its ends have turned
1e4 rad, against the exact solution (matrix exponential) of the relative dynamics; the
integrated lossPower against the kinetic energy lost (closed form and conservation)."""
import numpy as np
import pytest
from scipy.linalg import expm

import acausal as ac
from acausal.analysis import energy_balance
from acausal.library import rotational as rot
from acausal.library import translational as tr

J1, J2, C, D = 1.0, 1.0, 1.0e4, 1.0     # kg m2, kg m2, N m/rad, N m s/rad
T0, W0, P0 = 0.02, 1.0e4, 1.0e-6          # drive torque, initial speed, initial twist


def stiff_shaft(stateSelect):
    class StiffShaft(ac.Component):
        """A constant torque on inertia a, coupled to inertia b by a stiff shaft; both
        spin at W0, so after 1 s their angles are 1e4 rad; the twist is ~1e-6 rad."""

        drive = rot.ConstantTorque(tau_constant=T0)
        a = rot.Inertia(J=J1, phi={"start": 0.0, "fixed": True},
                        w={"start": W0, "fixed": True})
        shaft = rot.SpringDamper(c=C, d=D, stateSelect=stateSelect,
                                 phi_rel={"start": P0, "fixed": True},
                                 w_rel={"start": 0.0, "fixed": True})
        b = rot.Inertia(J=J2)

        def equations(self):
            return [ac.connect(self.drive.flange, self.a.flange_a),
                    ac.connect(self.a.flange_b, self.shaft.flange_a),
                    ac.connect(self.shaft.flange_b, self.b.flange_a)]

    return StiffShaft()


def twist_exact(t):
    """x = (phi_rel, w_rel):  x' = A x + B T0  with J_eff a_rel = -tau - J_eff T0 / J1
    (tau = c phi_rel + d w_rel, 1/J_eff = 1/J1 + 1/J2), solved by the matrix
    exponential:  x(t) = e^{At} x0 + A^{-1} (e^{At} - I) B T0."""
    J_eff = 1 / (1 / J1 + 1 / J2)
    A = np.array([[0.0, 1.0], [-C / J_eff, -D / J_eff]])
    B = np.array([0.0, -T0 / J1])
    out = []
    for ti in t:
        E = expm(A * ti)
        out.append(E @ [P0, 0.0] + np.linalg.solve(A, (E - np.eye(2)) @ B))
    return np.array(out)


def test_stiff_shaft_twist_stays_accurate_at_large_absolute_angles():
    t = np.linspace(0, 1, 201)
    compiled = ac.compile(stiff_shaft("prefer"))
    assert {"shaft.phi_rel", "shaft.w_rel"} <= set(compiled.states)
    # atol (times the nominal 1e-4 of phi_rel) puts the twist's tolerance on its scale
    res = ac.simulate(compiled, t_end=1.0, rtol=1e-10, atol=1e-14, t_eval=t)
    exact = twist_exact(t)
    assert abs(res["a.phi"][-1]) > 0.99e4                 # the ends turned ~1e4 rad
    scale = np.max(np.abs(exact[:, 0]))
    assert 1e-6 < scale < 1e-5
    assert np.max(np.abs(res["shaft.phi_rel"] - exact[:, 0])) < 1e-6 * scale
    w_scale = np.max(np.abs(exact[:, 1]))
    assert np.max(np.abs(res["shaft.w_rel"] - exact[:, 1])) < 1e-6 * w_scale
    # "prefer" brings the relative acceleration: a_rel = -(c phi_rel + d w_rel)/J_eff - T0/J1
    J_eff = 1 / (1 / J1 + 1 / J2)
    a_rel = -(C * exact[:, 0] + D * exact[:, 1]) / J_eff - T0 / J1
    assert np.max(np.abs(res["shaft.acc.a_rel"] - a_rel)) < 1e-5 * np.max(np.abs(a_rel))


def test_state_select_of_the_relative_variables():
    # by default the speeds stay the inertias' (w_rel "avoid"), as with PartialCompliant
    assert rot.SpringDamper().stateSelect == "default"
    assert set(ac.compile(stiff_shaft("default")).states) == {"a.phi", "a.w",
                                                              "shaft.phi_rel", "b.w"}
    assert set(ac.compile(stiff_shaft("avoid")).states) == {"a.phi", "a.w", "b.phi", "b.w"}
    # an explicit state_select of the variable takes precedence over stateSelect
    class Host(ac.Component):
        d = rot.Damper(stateSelect="avoid", w_rel={"state_select": "always"})

    host = Host()
    host._bind()
    damper = host.d
    assert damper.variable_attributes("w_rel").state_select == "always"
    assert damper.variable_attributes("phi_rel").state_select == "avoid"
    with pytest.raises(ac.ModelError, match="stateSelect must be one of"):
        tr.SpringDamper(stateSelect="sometimes")


class DampedPair(ac.Component):
    """Two inertias coupled by a damper only, from different speeds; E_loss integrates
    the damper's lossPower."""

    a = rot.Inertia(J=2.0, phi={"start": 0.0, "fixed": True}, w={"start": 3.0, "fixed": True})
    damper = rot.Damper(d=0.7)
    b = rot.Inertia(J=0.5, phi={"start": 0.0, "fixed": True}, w={"start": -1.0, "fixed": True})
    E_loss = ac.Variable(start=0.0, fixed=True, unit="J", description="energy dissipated")

    def equations(self):
        return [ac.connect(self.a.flange_b, self.damper.flange_a),
                ac.connect(self.damper.flange_b, self.b.flange_a),
                ac.Eq(ac.der(self.E_loss), self.damper.lossPower)]


def test_damper_loss_power_integrates_to_the_kinetic_energy_lost():
    t = np.linspace(0, 3, 61)
    model = DampedPair()
    res = ac.simulate(model, t_end=3.0, rtol=1e-10, atol=1e-12, t_eval=t)
    # w_rel decays as exp(-d t / J_eff): the energy of the relative motion is lost
    J_eff, w_rel0 = 1 / (1 / 2.0 + 1 / 0.5), -1.0 - 3.0
    lost = J_eff * w_rel0**2 / 2 * (1 - np.exp(-2 * 0.7 * t / J_eff))
    E0 = 2.0 * 3.0**2 / 2 + 0.5 * 1.0**2 / 2
    assert np.max(np.abs(res["E_loss"] - lost)) < 1e-8 * E0
    # conservation: kinetic energy + dissipated energy is constant
    E = 2.0 * res["a.w"]**2 / 2 + 0.5 * res["b.w"]**2 / 2
    assert np.max(np.abs(E + res["E_loss"] - E0)) < 1e-8 * E0
    assert np.max(np.abs(res["damper.w_rel"] - w_rel0 * np.exp(-0.7 * t / J_eff))) \
        < 1e-8 * abs(w_rel0)


class TranslationalOscillator(ac.Component):
    """A mass on a spring-damper to the wall, released from 0.1 m; E_loss integrates
    the spring-damper's lossPower."""

    wall = tr.Fixed()
    spring_damper = tr.SpringDamper(c=50.0, d=0.8)
    mass = tr.Mass(m=2.0, s={"start": 0.1, "fixed": True}, v={"start": 0.0, "fixed": True})
    E_loss = ac.Variable(start=0.0, fixed=True, unit="J", description="energy dissipated")

    def equations(self):
        return [ac.connect(self.wall.flange, self.spring_damper.flange_a),
                ac.connect(self.spring_damper.flange_b, self.mass.flange_a),
                ac.Eq(ac.der(self.E_loss), self.spring_damper.lossPower)]


def test_spring_damper_loss_power_closes_the_energy_balance():
    model = TranslationalOscillator()
    res = ac.simulate(model, t_end=4.0, rtol=1e-10, atol=1e-12, n_points=201)
    E0 = 50.0 * 0.1**2 / 2
    E = 2.0 * res["mass.v"]**2 / 2 + 50.0 * res["mass.s"]**2 / 2
    assert np.max(np.abs(E + res["E_loss"] - E0)) < 1e-8 * E0
    assert res["E_loss"][-1] > 0.5 * E0                  # most of it is gone by t = 4 s
    assert np.max(np.abs(res["spring_damper.v_rel"] - res["mass.v"])) < 1e-12 * 1.0
    audit = energy_balance(res, model)
    assert set(audit.dissipated) == {"spring_damper"} and not audit.violations
