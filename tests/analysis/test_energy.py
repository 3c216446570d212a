"""Energy audits against the energy functions of Egeland & Gravdahl."""
import numpy as np
import pytest

import acausal as ac
from acausal.analysis import energy_balance, is_passive
from acausal.library.electrical import Ground, Resistor, StepVoltage
from acausal.library.electrical.interfaces import OnePort
from acausal.library.electromechanical import DCMotor
from acausal.library.translational import Damper, Fixed, Mass, Spring

M, C, D = 2.0, 50.0, 0.8


class MassSpringDamper(ac.Component):
    """m x'' + d x' + k x = 0 (2.57), released from x = 0.1 m."""

    mass = Mass(m=M, s={"start": 0.1, "fixed": True}, v={"start": 0.0, "fixed": True})
    spring = Spring(c=C)
    damper = Damper(d=D)
    wall = Fixed()

    def equations(self):
        return [ac.connect(self.wall.flange, self.spring.flange_a, self.damper.flange_a),
                ac.connect(self.spring.flange_b, self.damper.flange_b, self.mass.flange_a)]


def test_mass_spring_damper_energy_decays_as_2_60():
    model = MassSpringDamper()
    res = ac.simulate(model, t_end=5.0, rtol=1e-9, atol=1e-12, n_points=501)
    audit = energy_balance(res, model)
    assert set(audit.stored) == {"mass", "spring"} and set(audit.dissipated) == {"damper"}
    V = 0.5 * M * res["mass.v"] ** 2 + 0.5 * C * res["mass.s"] ** 2    # (2.58)
    assert np.allclose(audit.E, V, rtol=1e-12, atol=0)
    assert audit.relative_residual() < 1e-6
    V0 = 0.5 * C * 0.1**2
    assert np.max(np.abs(audit.dE_dt + D * res["mass.v"] ** 2)) < 1e-6 * V0   # (2.60)
    assert not audit.sources and not audit.ports


class MotorOnVoltageStep(ac.Component):
    source = StepVoltage(V=12.0, startTime=0.0)
    ground = Ground()
    motor = DCMotor(R=1.0, L=1e-3, k=0.05, J=1e-4)

    def equations(self):
        return [ac.connect(self.source.p, self.motor.p),
                ac.connect(self.source.n, self.motor.n, self.ground.p)]


def test_dc_motor_energy_3_33_and_passivity():
    model = MotorOnVoltageStep()
    res = ac.simulate(model, t_end=0.1, rtol=1e-9, atol=1e-10, n_points=201)
    audit = energy_balance(res, model)
    u, i = res["motor.p.v"] - res["motor.n.v"], res["motor.La.i"]
    # V' = i_a u_a - R_a i_a^2 without load (3.33); the source delivers u_a i_a
    assert set(audit.sources) == {"source"}                     # the EMF is lossless
    assert np.allclose(audit.sources["source"], u * i, rtol=1e-9, atol=1e-9)
    assert np.allclose(audit.dE_dt, u * i - 1.0 * i**2, rtol=0, atol=1e-6 * np.max(u * i))
    assert audit.relative_residual() < 1e-6
    assert is_passive(res, model, "motor")
    assert is_passive(res, model, "motor.La")


class NegativeResistor(OnePort):
    """v = -R i: delivers power, so it is not passive."""

    R = ac.Parameter(1.0)

    def equations(self):
        return [ac.Eq(self.v, -self.R * self.i)]


class ActiveCircuit(ac.Component):
    source = StepVoltage(V=1.0)
    ground = Ground()
    load = Resistor(R=2.0)
    active = NegativeResistor(R=1.0)

    def equations(self):
        return [ac.connect(self.source.p, self.load.p),
                ac.connect(self.load.n, self.active.p),
                ac.connect(self.active.n, self.source.n, self.ground.p)]


def test_negative_resistor_is_not_passive_and_per_audit_entries_override():
    model = ActiveCircuit()
    res = ac.simulate(model, t_end=1.0, n_points=11)
    assert not is_passive(res, model, "active")
    assert is_passive(res, model, "load")
    i = res["load.i"]
    audit = energy_balance(res, ActiveCircuit())             # a fresh, unbound instance
    assert np.allclose(audit.sources["active"], 1.0 * i**2)  # it delivers R i^2
    audit = energy_balance(res, model, dissipation={"active": lambda v, p: v("v") * v("i")})
    assert set(audit.sources) == {"source"}
    # a balance of powers that cancel: judged on the power the source delivers (1 W)
    assert np.max(np.abs(audit.residual)) < 1e-9 * np.max(np.abs(audit.sources["source"]))


def test_valve_controlled_motor_energy_audit_4_66():
    hyd = pytest.importorskip("acausal.library.hydraulics")
    if not hasattr(hyd, "Volume"):
        pytest.skip("the hydraulics library has no Volume")
    from acausal.library.hydraulics.examples.valve_motor import V_0, BETA, ValveControlledMotor
    model = ValveControlledMotor()
    res = ac.simulate(model, t_end=0.05, rtol=1e-8, n_points=101)
    audit = energy_balance(res, model)
    assert np.allclose(audit.stored["line_1"], V_0 * res["line_1.p"] ** 2 / (2 * BETA))
    # the valve throttles: it declares its loss (it is no source), which never goes negative
    assert "supply" in audit.sources and audit.roles["valve"] == "dissipation"
    assert np.all(audit.dissipated["valve"] >= -1e-9 * np.max(audit.sources["supply"]))
    assert audit.relative_residual() < 1e-6
