"""The spatial multibody components that the MSL's MultiBody.Examples.Elementary use,
each checked on its own physics: point gravity against Kepler's laws and an independent
ODE solution, a user-defined field, point masses, a spring with a mass on it against
its closed form, the two line forces with point masses against each other, ForceAndTorque
against the momentum balance, the free-motion scalar initialization against the
geometry, and the rolling wheels against energy conservation and straight rolling."""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal as ac
from acausal._sympy import sympy as sp
from acausal.library import multibody3d as mb
from acausal.library.blocks import Constant
from acausal.library.translational import Spring as Spring1D
from acausal.library.multibody3d.examples.msl.double_pendulum_init_tip import (
    DoublePendulumInitTip)
from acausal.library.multibody3d.examples.msl.line_force_with_two_masses import (
    LineForceWithTwoMasses)

G = 9.80665


def _ode(f, y0, t):
    return solve_ivp(f, (t[0], t[-1]), y0, method="DOP853", rtol=1e-12, atol=1e-12,
                     t_eval=t)


# -- point gravity ----------------------------------------------------------------------

class Orbit(ac.Component):
    """A point mass (free, so it sets its own orientation) and a Body on a FreeMotion in
    the point field mu = 1 of the World, started alike on an ellipse."""

    world = mb.World(gravityType="PointGravity", mu=1.0)
    mass = mb.PointMass(m=2.0, connected=False, r_0={"start": [1.0, 0.0, 0.0], "fixed": True},
                        v_0={"start": [0.0, 0.8, 0.3], "fixed": True})
    joint = mb.FreeMotion(r_rel_a={"start": [1.0, 0.0, 0.0], "fixed": True},
                          v_rel_a={"start": [0.0, 0.8, 0.3], "fixed": True},
                          angles_fixed=True, w_rel_b={"fixed": True})
    body = mb.Body(m=3.0, I_11=0.1, I_22=0.2, I_33=0.3)

    def equations(self):
        return [ac.connect(self.world.frame_b, self.joint.frame_a),
                ac.connect(self.joint.frame_b, self.body.frame_a)]


def test_point_gravity_keeps_energy_and_angular_momentum_and_matches_kepler():
    t = np.linspace(0.0, 6.0, 301)
    res = ac.simulate(Orbit(), t_end=6.0, rtol=1e-10, atol=1e-10, t_eval=t)

    def kepler(_, s):
        r = s[:3]
        return [*s[3:], *(-r / np.linalg.norm(r)**3)]

    ref = _ode(kepler, [1.0, 0.0, 0.0, 0.0, 0.8, 0.3], t)
    for name in ("mass.r_0", "body.r_0"):
        r = np.asarray(res[name]).T
        assert np.max(np.abs(r - ref.y[:3])) < 1e-7
    r, v = np.asarray(res["mass.r_0"]).T, np.asarray(res["mass.v_0"]).T
    E = 0.5 * np.sum(v**2, axis=0) - 1.0 / np.linalg.norm(r, axis=0)
    H = np.cross(r.T, v.T)
    assert np.ptp(E) < 1e-8 * abs(E[0])
    assert np.max(np.abs(H - H[0])) < 1e-8 * np.linalg.norm(H[0])
    # the field at the body's centre of mass, as the body reads it
    g = np.asarray(res["body.g_0"]).T
    rb = np.asarray(res["body.r_0"]).T
    assert np.max(np.abs(g + rb / np.linalg.norm(rb, axis=0)**3)) < 1e-12 * np.max(np.abs(g))


def test_gravity_type_is_checked_and_a_body_without_world_is_named():
    with pytest.raises(ac.InvalidValue, match="did you mean 'PointGravity'"):
        mb.World(gravityType="pointgravity")

    class Lost(ac.Component):
        mass = mb.PointMass(connected=False)

    with pytest.raises(ac.NotInModel, match=r"'mass' \(PointMass\).*World"):
        ac.compile(Lost())


class FieldWorld(mb.World):
    """A user-defined field: uniform, 2 m/s2 along +x."""

    def gravityAcceleration(self, r):
        return sp.Matrix([2.0, 0, 0])


class UserFieldPendulum(ac.Component):
    world = FieldWorld(gravityType="NoGravity")
    joint = mb.Revolute(phi={"start": 0.0, "fixed": True}, w={"start": 0.0, "fixed": True})
    body = mb.Body(m=1.0, r_CM_2=-1.0, I_11=0.0, I_22=0.0, I_33=0.0)

    def equations(self):
        return [ac.connect(self.world.frame_b, self.joint.frame_a),
                ac.connect(self.joint.frame_b, self.body.frame_a)]


def test_user_defined_field_drives_a_pendulum_as_its_own_ode():
    """A point mass 1 m below the pivot in a field 2 m/s2 along +x:
    phi'' = 2 cos(phi) (phi from the downward vertical, counter-clockwise)."""
    t = np.linspace(0.0, 3.0, 151)
    res = ac.simulate(UserFieldPendulum(), t_end=3.0, rtol=1e-10, atol=1e-10, t_eval=t)
    ode = _ode(lambda _, s: [s[1], 2.0 * np.cos(s[0])], [0.0, 0.0], t)
    assert np.max(np.abs(res["joint.phi"] - ode.y[0])) < 1e-7 * np.ptp(ode.y[0])


# -- a spring with a mass on it ---------------------------------------------------------

class HangingSpringWithMass(ac.Component):
    """A body M hanging on a spring (c, unstretched s0) with a mass m at h of its length
    from the world's origin, free to move in 3-D."""

    world = mb.World()
    spring = mb.Spring(c=40.0, s_unstretched=0.2, m=0.5, lengthFraction=0.3)
    joint = mb.FreeMotion(r_rel_a={"start": [0.0, -0.3, 0.0], "fixed": True},
                          v_rel_a={"fixed": True}, angles_fixed=True, w_rel_b={"fixed": True})
    body = mb.Body(m=1.0)

    def equations(self):
        return [ac.connect(self.world.frame_b, self.spring.frame_a, self.joint.frame_a),
                ac.connect(self.joint.frame_b, self.spring.frame_b, self.body.frame_a)]


def test_spring_mass_on_the_line_adds_h_squared_m_of_inertia_and_h_m_of_weight():
    """The mass sits at h r_b: kinetic energy m h^2 v^2/2, weight m h g on the body, so
    (M + m h^2) s'' = -c (s - s0) + (M + m h) g, a harmonic motion about its rest."""
    M, m, h, c, s0 = 1.0, 0.5, 0.3, 40.0, 0.2
    t = np.linspace(0.0, 3.0, 301)
    res = ac.simulate(HangingSpringWithMass(), t_end=3.0, rtol=1e-10, atol=1e-10, t_eval=t)
    s_rest = s0 + (M + m * h) * G / c
    w = np.sqrt(c / (M + m * h**2))
    exact = s_rest + (0.3 - s_rest) * np.cos(w * t)
    assert np.max(np.abs(res["spring.s"] - exact)) < 1e-7 * abs(0.3 - s_rest)
    assert np.max(np.abs(res["body.r_0[0]"])) == 0.0
    # the spring stores its strain energy and its mass's kinetic and potential energy
    audit = ac.energy_balance(res, HangingSpringWithMass())
    assert audit.ok, audit.violations


# -- line forces with masses: JointUPS against LineForceWithTwoMasses -------------------

def test_joint_ups_and_line_force_with_two_masses_move_their_pendulums_alike():
    """The MSL example builds one damped, massive rod twice: as a JointUPS with two
    bodies and a damper, and as a LineForceWithTwoMasses with a damper.  The two
    formulations must agree, cut forces included."""
    t = np.linspace(0.0, 3.0, 151)
    res = ac.simulate(LineForceWithTwoMasses(), t_end=3.0, rtol=1e-10, atol=1e-10,
                      t_eval=t)
    assert np.ptp(res["revolute1.phi"]) > 1.0
    for q in ("phi", "w"):
        a, b = res[f"revolute1.{q}"], res[f"revolute2.{q}"]
        assert np.max(np.abs(a - b)) < 1e-8 * np.ptp(a)
    scale = np.max(np.abs(res["rod1.frame_b.fy"]))
    assert np.max(np.abs(res["rod_f_diff"])) < 1e-7 * scale
    assert np.max(np.abs(res["body_f_diff"])) < 1e-7 * scale


# -- ForceAndTorque -----------------------------------------------------------------------

class PushedFromAFixedPoint(ac.Component):
    """A free body (no gravity) pushed and twisted by a ForceAndTorque whose frame_a is a
    fixed point; force and torque given in the world."""

    world = mb.World(gravityType="NoGravity")
    anchor = mb.Fixed(r_1=1.0, r_2=2.0, r_3=0.0)
    joint = mb.FreeMotion(r_rel_a={"start": [0.5, 0.0, 0.0], "fixed": True},
                          v_rel_a={"fixed": True}, angles_fixed=True, w_rel_b={"fixed": True})
    body = mb.Body(m=2.0, I_11=0.1, I_22=0.2, I_33=0.3)
    push = mb.ForceAndTorque(resolveInFrame="world")

    def build(self):
        self.F = [Constant(k=k) for k in (1.0, -2.0, 0.5)]
        self.T = [Constant(k=k) for k in (0.0, 0.0, 0.3)]

    def equations(self):
        return [ac.connect(self.world.frame_b, self.joint.frame_a),
                ac.connect(self.joint.frame_b, self.body.frame_a, self.push.frame_b),
                ac.connect(self.anchor.frame_b, self.push.frame_a),
                *(ac.connect(s.y, u) for s, u in zip(self.F, self.push.force)),
                *(ac.connect(s.y, u) for s, u in zip(self.T, self.push.torque))]


def test_force_and_torque_act_on_frame_b_and_react_on_frame_a():
    t = np.linspace(0.0, 1.0, 51)
    res = ac.simulate(PushedFromAFixedPoint(), t_end=1.0, rtol=1e-10, atol=1e-10, t_eval=t)
    F, T, m = np.array([1.0, -2.0, 0.5]), np.array([0.0, 0.0, 0.3]), 2.0
    r = np.asarray(res["body.r_0"]).T
    assert np.max(np.abs(r - (np.array([[0.5], [0.0], [0.0]]) + np.outer(F / m, t**2 / 2))))\
        < 1e-9
    # the reaction at the anchor (its frame is the world's orientation)
    fa = np.array([res[f"push.frame_a.f{c}"] for c in "xyz"])
    ta = np.array([res[f"push.frame_a.t{c}"] for c in "xyz"])
    lever = r - np.array([[1.0], [2.0], [0.0]])
    assert np.max(np.abs(fa - F[:, None])) < 1e-12
    assert np.max(np.abs(ta - (T[:, None] + np.cross(lever.T, F).T))) < 1e-9


# -- the scalar initialization of a free motion -------------------------------------------

def test_free_motion_scalar_init_puts_the_tip_where_it_belongs():
    res = ac.simulate(DoublePendulumInitTip(), t_end=0.01, rtol=1e-9, n_points=3)
    tip = [res[f"boxBody2.frame_b.{c}"][0] for c in "xy"]
    assert tip == pytest.approx([0.7, 0.3], abs=1e-9)
    # and the joint angles agree with the two links' geometry: |tip| by the cosine law
    p1, p2 = res["revolute1.phi"][0], res["revolute2.phi"][0]
    x = 0.5 * np.cos(p1) + 0.5 * np.cos(p1 + p2)
    y = 0.5 * np.sin(p1) + 0.5 * np.sin(p1 + p2)
    assert [x, y] == pytest.approx([0.7, 0.3], abs=1e-9)
    assert res["revolute1.w"][0] == pytest.approx(0.0, abs=1e-9)


# -- rolling wheels -------------------------------------------------------------------------

class Coin(ac.Component):
    world = mb.World(n_1=0.0, n_2=0.0, n_3=-1.0)
    wheel = mb.RollingWheel(radius=0.3, m=2.0, I_axis=0.06, I_long=0.12,
                            der_angles={"start": [0.0, 5.0, 1.0]})


def test_rolling_wheel_keeps_its_energy_and_its_contact_point_at_rest():
    """Ideal rolling does no work: kinetic plus potential energy stay constant while the
    tilting wheel curves and speeds up its spin."""
    t = np.linspace(0.0, 2.0, 201)
    res = ac.simulate(Coin(), t_end=2.0, rtol=1e-9, atol=1e-9, t_eval=t)
    v = np.asarray(res["wheel.body.v_0"])
    w = np.asarray(res["wheel.body.w_a"])
    z = res["wheel.frame_a.z"]
    I = np.diag([0.12, 0.06, 0.12])
    E = 0.5 * 2.0 * np.sum(v**2, axis=1) + 0.5 * np.einsum("ni,ij,nj->n", w, I, w) \
        + 2.0 * G * z
    assert np.ptp(res["wheel.angles[2]"]) > 0.5            # it tips over
    assert np.ptp(E) < 1e-7 * E[0]
    # the wheel touches the ground: its centre is radius above the contact point
    j = "wheel.rollingWheel"
    gap = np.sqrt((res[f"{j}.s"] - res["wheel.frame_a.x"])**2
                  + (res[f"{j}.w"] - res["wheel.frame_a.y"])**2 + z**2)
    assert np.max(np.abs(gap - 0.3)) < 1e-9


class Axle(ac.Component):
    world = mb.World(n_1=0.0, n_2=0.0, n_3=-1.0)
    wheelSet = mb.RollingWheelSet(R_wheel=0.1, m_wheel=0.5, I_wheelAxis=0.01,
                                  I_wheelLong=0.02, track=0.5,
                                  der_theta1={"start": 2.0}, der_theta2={"start": 2.0})


def test_rolling_wheel_set_rolls_straight_at_radius_times_spin():
    t = np.linspace(0.0, 2.0, 101)
    res = ac.simulate(Axle(), t_end=2.0, rtol=1e-10, atol=1e-10, t_eval=t)
    assert np.max(np.abs(res["wheelSet.der_theta1"] - 2.0)) < 1e-9
    assert np.max(np.abs(res["wheelSet.phi"])) < 1e-9
    assert np.max(np.abs(np.abs(res["wheelSet.x"]) - 0.1 * 2.0 * t)) < 1e-9
    assert np.max(np.abs(res["wheelSet.y"])) < 1e-9


class HangingOnLineForceWithMass(HangingSpringWithMass):
    """The same system with the spring law as a 1-D translational spring on the flanges
    of a LineForceWithMass (the MSL's Forces.Spring is made so)."""

    spring = mb.LineForceWithMass(m=0.5, lengthFraction=0.3)
    law = Spring1D(c=40.0, s_rel0=0.2)

    def equations(self):
        return [ac.connect(self.spring.flange_a, self.law.flange_a),
                ac.connect(self.spring.flange_b, self.law.flange_b)]


def test_line_force_with_mass_and_a_1d_spring_equal_the_spring_with_mass():
    t = np.linspace(0.0, 2.0, 101)
    kw = dict(t_end=2.0, rtol=1e-10, atol=1e-10, t_eval=t)
    a = ac.simulate(HangingSpringWithMass(), **kw)
    b = ac.simulate(HangingOnLineForceWithMass(), **kw)
    assert np.ptp(a["spring.s"]) > 0.05
    assert np.max(np.abs(a["spring.s"] - b["spring.s"])) < 1e-9
    assert np.max(np.abs(b["law.s_rel"] - b["spring.length"])) < 1e-12
