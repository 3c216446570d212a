"""Translational components and sources against closed forms, energy balances and
scipy's solve_ivp on the hand-written equations."""
import numpy as np
from scipy.integrate import solve_ivp

import acausal as ac
from acausal.library import translational as tr
from acausal.library.blocks import Sine
from acausal.library.translational.examples.mass_spring_damper import MassSpringDamper


class SpringAndDamperSeparately(ac.Component):
    wall = tr.Fixed()
    spring = tr.Spring(c=4.0)
    damper = tr.Damper(d=0.4)
    mass = tr.Mass(m=1.0, s={"start": 0.1, "fixed": True}, v={"start": 0.0, "fixed": True})

    def equations(self):
        return [ac.connect(self.wall.flange, self.spring.flange_a, self.damper.flange_a),
                ac.connect(self.spring.flange_b, self.damper.flange_b, self.mass.flange_a)]


class SpringDamperCombined(ac.Component):
    wall = tr.Fixed()
    spring_damper = tr.SpringDamper(c=4.0, d=0.4)
    mass = tr.Mass(m=1.0, s={"start": 0.1, "fixed": True}, v={"start": 0.0, "fixed": True})

    def equations(self):
        return [ac.connect(self.wall.flange, self.spring_damper.flange_a),
                ac.connect(self.spring_damper.flange_b, self.mass.flange_a)]


def test_spring_and_damper_in_parallel_equal_spring_damper():
    t = np.linspace(0, 10, 201)
    a = ac.simulate(SpringAndDamperSeparately(), t_end=10, rtol=1e-10, t_eval=t)
    b = ac.simulate(SpringDamperCombined(), t_end=10, rtol=1e-10, t_eval=t)
    # two formulations of one ODE: they agree to the global error, 10-100 rtol of x0
    assert np.max(np.abs(a["mass.s"] - b["mass.s"])) < 1e-8 * 0.1


class MassSpringDamperWithLoss(MassSpringDamper):
    """The example plus the energy dissipated in the damper, E_d' = d v^2."""

    E_d = ac.Variable(start=0.0, fixed=True)

    def equations(self):
        return [ac.Eq(ac.der(self.E_d), self.damper.d * self.mass.v**2)]


def test_mass_spring_damper_energy_balance_2_60():
    # the balance is as good as the global error of the states: 6e-8 relative at
    # rtol 1e-10, 2e-9 at rtol 1e-12 (the same as the error in x against the closed form)
    t = np.linspace(0, 10, 201)
    res = ac.simulate(MassSpringDamperWithLoss(), t_end=10, rtol=1e-12, t_eval=t)
    x, v, a = res["mass.s"], res["mass.v"], res["mass.a"]
    V = 0.5 * 1.0 * v**2 + 0.5 * 4.0 * x**2                      # (2.58)
    # pointwise: dV/dt = m v a + k x v = -d v^2  (2.60), terms that cancel: judged on
    # the size of the spring's power
    power = np.max(np.abs(4.0 * x * v))
    assert np.max(np.abs(1.0 * v * a + 4.0 * x * v + 0.4 * v**2)) < 1e-8 * power
    # integrated along the solution: V(t) + E_d(t) = V(0)
    assert np.max(np.abs(V + res["E_d"] - V[0])) < 1e-8 * V[0]
    assert res["E_d"][-1] > 0.9 * V[0]


class SineForceOnMass(ac.Component):
    reference = Sine(amplitude=3.0, f=2.0)
    push = tr.Force()
    mass = tr.Mass(m=1.5)
    speed = tr.SpeedSensor()
    position = tr.PositionSensor()

    def equations(self):
        return [ac.connect(self.reference.y, self.push.f),
                ac.connect(self.push.flange, self.mass.flange_a),
                ac.connect(self.mass.flange_b, self.speed.flange, self.position.flange)]


def test_signal_force_on_free_mass():
    t = np.linspace(0, 1, 51)
    res = ac.simulate(SineForceOnMass(), t_end=1, rtol=1e-10, t_eval=t)
    w = 4 * np.pi
    v = 3.0 / 1.5 * (1 - np.cos(w * t)) / w
    s = 3.0 / 1.5 * (t - np.sin(w * t) / w) / w
    assert np.max(np.abs(res["speed.v.signal"] - v)) < 1e-8
    assert np.max(np.abs(res["position.s.signal"] - s)) < 1e-8


class PositionDrivenMass(ac.Component):
    reference = Sine(amplitude=0.2, f=1.0)
    drive = tr.Position()
    force = tr.ForceSensor()
    power = tr.PowerSensor()
    mass = tr.Mass(m=2.0)

    def equations(self):
        return [ac.connect(self.reference.y, self.drive.s_ref),
                ac.connect(self.drive.flange, self.force.flange_a),
                ac.connect(self.force.flange_b, self.power.flange_a),
                ac.connect(self.power.flange_b, self.mass.flange_a)]


def test_position_source_force_and_power():
    t = np.linspace(0, 1, 41)
    res = ac.simulate(PositionDrivenMass(), t_end=1, rtol=1e-10, t_eval=t)
    w = 2 * np.pi
    f = -2.0 * 0.2 * w**2 * np.sin(w * t)
    v = 0.2 * w * np.cos(w * t)
    assert np.max(np.abs(res["force.f.signal"] - f)) < 1e-8
    assert np.max(np.abs(res["power.power.signal"] - f * v)) < 1e-8


class TowedMass(ac.Component):
    """A mass towed at constant speed through a spring-damper, with a step force."""

    tow = tr.ConstantSpeed(v_fixed=0.5)
    rope = tr.SpringDamper(c=20.0, d=1.0)
    mass = tr.Mass(m=2.0)
    push = tr.ForceStep(stepForce=-3.0, startTime=1.0)
    stretch = tr.RelPositionSensor()

    def equations(self):
        return [ac.connect(self.tow.flange, self.rope.flange_b, self.stretch.flange_b),
                ac.connect(self.rope.flange_a, self.mass.flange_b, self.stretch.flange_a),
                ac.connect(self.mass.flange_a, self.push.flange)]


def test_towed_mass_against_solve_ivp():
    def rhs(t, y):
        s_tow, s, v = y
        f = 20.0 * (s_tow - s) + 1.0 * (0.5 - v) + (-3.0 if t >= 1.0 else 0.0)
        return [0.5, v, f / 2.0]

    t = np.linspace(0, 3, 61)
    ref1 = solve_ivp(rhs, (0, 1), [0, 0, 0], rtol=1e-10, atol=1e-12, dense_output=True)
    ref2 = solve_ivp(rhs, (1, 3), ref1.y[:, -1], rtol=1e-10, atol=1e-12, dense_output=True)
    exact = np.where(t < 1, ref1.sol(np.minimum(t, 1))[1], ref2.sol(np.maximum(t, 1))[1])
    res = ac.simulate(TowedMass(), t_end=3, rtol=1e-10, t_eval=t)
    assert np.max(np.abs(res["mass.s"] - exact)) < 1e-8
    assert np.max(np.abs(res["stretch.s_rel.signal"] - (0.5 * t - exact))) < 1e-8
