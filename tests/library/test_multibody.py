"""Planar multibody systems assembled from frames, joints, bars and bodies, checked
against hand-written Cartesian models, angle-coordinate ODEs, the book's closed forms
and energy balances."""
import numpy as np
import pytest
from scipy.integrate import cumulative_trapezoid, solve_ivp

import acausal as ac
from acausal.library import multibody as mb
from acausal.library import rotational as rot
from acausal.library.examples.pendulum import DoublePendulum as CartesianDoublePendulum
from acausal.library.multibody.examples.ball_and_beam import BallAndBeam
from acausal.library.multibody.examples.cart_pendulum import CartPendulumMotor
from acausal.library.multibody.examples.pendulums import (DoublePendulum, PendulumChain,
                                                          PointMassChain, SinglePendulum)
from acausal.library.multibody.examples.slider_crank import SliderCrank, slider_position

G = 9.81


def _differentiated(report, fragment):
    return [e["differentiated"] for e in report.equations
            if e["order"] == 0 and fragment in e["text"]]


def _double_pendulum_ode(t, s, m1=1.0, m2=1.0, L1=1.0, L2=1.0):
    """Lagrange's equations in the absolute angles from the downward vertical."""
    th1, th2, w1, w2 = s
    c, sn = np.cos(th1 - th2), np.sin(th1 - th2)
    M = np.array([[(m1 + m2) * L1**2, m2 * L1 * L2 * c], [m2 * L1 * L2 * c, m2 * L2**2]])
    rhs = np.array([-m2 * L1 * L2 * w2**2 * sn - (m1 + m2) * G * L1 * np.sin(th1),
                    m2 * L1 * L2 * w1**2 * sn - m2 * G * L2 * np.sin(th2)])
    return [w1, w2, *np.linalg.solve(M, rhs)]


def _angles(res, prefix="link"):
    th1 = res[f"{prefix}1.joint.phi"]
    return th1, th1 + res[f"{prefix}2.joint.phi"]


def test_single_pendulum_report_index_3_joint_angle_is_the_state():
    rep = ac.compile(SinglePendulum()).report
    assert rep.differential_index == 3
    assert _differentiated(rep, "link.bar.frame_b.x =") == [2]
    assert _differentiated(rep, "link.bar.frame_b.y =") == [2]
    assert rep.states == ["link.joint.phi", "link.joint.w"]
    assert not rep.state_sets             # the joint angle is a state everywhere


def test_single_pendulum_full_rotations_against_angle_ode():
    """7 rad/s at the bottom: over the top several times (through x = 0 both ways)."""
    model = SinglePendulum(link={"joint": {"phi": {"start": 0.0, "fixed": True},
                                           "w": {"start": 7.0, "fixed": True}}})
    t = np.linspace(0, 3.0, 301)
    res = ac.simulate(model, t_end=3.0, rtol=1e-10, atol=1e-10, t_eval=t)
    ode = solve_ivp(lambda _, s: [s[1], -G * np.sin(s[0])], (0, 3.0), [0.0, 7.0],
                    method="DOP853", rtol=1e-12, atol=1e-12, t_eval=t)
    assert res["link.joint.phi"][-1] > 4 * np.pi             # more than two full turns
    assert np.max(np.abs(res["link.joint.phi"] - ode.y[0])) < 1e-6
    x, y = res["link.mass.x"], res["link.mass.y"]
    assert np.max(np.abs(x**2 + y**2 - 1.0)) < 1e-8
    assert np.min(x) < -0.99 and np.max(x) > 0.99 and np.max(y) > 0.99
    energy = 0.5 * (res["link.mass.vx"]**2 + res["link.mass.vy"]**2) + G * y
    assert np.max(np.abs(energy - energy[0])) / abs(energy[0]) < 1e-6


def test_double_pendulum_report_two_bars_differentiated_twice():
    rep = ac.compile(DoublePendulum()).report
    assert rep.differential_index == 3
    for link in ("link1", "link2"):
        assert _differentiated(rep, f"{link}.bar.frame_b.x =") == [2]
        assert _differentiated(rep, f"{link}.bar.frame_b.y =") == [2]
    # link2's absolute angle is link1's plus its joint angle: a third constraint
    assert _differentiated(rep, "link2.joint.frame_b.phi =") == [2]
    assert rep.states == ["link1.joint.phi", "link1.joint.w", "link2.joint.phi",
                          "link2.joint.w"]
    assert not rep.state_sets


@pytest.fixture(scope="module")
def double_pendulum_runs():
    t = np.linspace(0, 10, 501)
    th = (0.5, 0.9)
    res = ac.simulate(DoublePendulum(), t_end=10.0, rtol=1e-10, atol=1e-10, t_eval=t)
    cart = CartesianDoublePendulum(x1={"start": np.sin(th[0])},
                                   x2={"start": np.sin(th[0]) + np.sin(th[1])})
    ref = ac.simulate(cart, t_end=10.0, rtol=1e-10, atol=1e-10, t_eval=t)
    ode = solve_ivp(_double_pendulum_ode, (0, 10), [*th, 0, 0], method="DOP853",
                    rtol=1e-12, atol=1e-12, t_eval=t)
    return t, res, ref, ode


def test_double_pendulum_from_joints_against_angle_ode(double_pendulum_runs):
    _, res, _, ode = double_pendulum_runs
    th1, th2 = _angles(res)
    assert np.max(np.abs(th1 - ode.y[0])) < 1e-6
    assert np.max(np.abs(th2 - ode.y[1])) < 1e-6


def test_double_pendulum_from_joints_against_cartesian_model(double_pendulum_runs):
    _, res, ref, _ = double_pendulum_runs
    for name in ("x1", "y1", "x2", "y2", "vx1", "vy1", "vx2", "vy2"):
        mine = res[f"link{name[-1]}.mass.{name[:-1]}"]
        assert np.max(np.abs(mine - ref[name])) < 1e-6, name


def test_double_pendulum_constraints_and_vertical_crossings(double_pendulum_runs):
    _, res, _, _ = double_pendulum_runs
    x1, y1, x2, y2 = (res[f"link{i}.mass.{c}"] for i in (1, 2) for c in ("x", "y"))
    assert np.max(np.abs(x1**2 + y1**2 - 1)) < 1e-8
    assert np.max(np.abs((x2 - x1)**2 + (y2 - y1)**2 - 1)) < 1e-8
    # both bars pass the vertical (x1 = 0 and x2 = x1, the hand-reduced form's singularities)
    assert np.sum(np.diff(np.sign(x1)) != 0) >= 4
    assert np.sum(np.diff(np.sign(x2 - x1)) != 0) >= 4


def test_double_pendulum_energy_drift():
    t = np.linspace(0, 10, 201)
    res = ac.simulate(DoublePendulum(), t_end=10.0, rtol=1e-8, atol=1e-8, t_eval=t)
    energy = sum(0.5 * (res[f"link{i}.mass.vx"]**2 + res[f"link{i}.mass.vy"]**2)
                 + G * res[f"link{i}.mass.y"] for i in (1, 2))
    assert np.max(np.abs(energy - energy[0])) / abs(energy[0]) < 1e-6


# -- the n-mass pendulum (000 section 3.4) ---------------------------------------------

def test_point_mass_chain_report_one_constraint_per_rod_differentiated_twice():
    n = 4
    rep = ac.compile(PointMassChain(n)).report
    assert rep.differential_index == 3
    for i in range(n):
        assert _differentiated(rep, f"rods[{i}].s**2 =") == [2]
    twice = [e for e in rep.equations if e["order"] == 0 and e["differentiated"] == 2]
    assert len(twice) == n                    # exactly one constraint per joint
    assert len(rep.states) == 2 * n           # one coordinate and its velocity per mass
    assert rep.state_sets                     # x_i or y_i: chosen at run time


def test_point_mass_chain_falls_like_the_joint_chain():
    """The DAE notes' point masses on rods and the same chain from revolute joints,
    bars and bodies, both released horizontally: same motion."""
    n, t = 3, np.linspace(0, 1.5, 76)
    rods = ac.simulate(PointMassChain(n), t_end=1.5, rtol=1e-9, atol=1e-9, t_eval=t)
    joints = ac.simulate(PendulumChain(n), t_end=1.5, rtol=1e-9, atol=1e-9, t_eval=t)
    assert rods.success and joints.success
    for i in range(n):
        for c in ("x", "y"):
            assert np.max(np.abs(rods[f"masses[{i}].{c}"] - joints[f"links[{i}].mass.{c}"])) < 1e-6
    xs = [np.zeros_like(t)] + [rods[f"masses[{i}].x"] for i in range(n)]
    ys = [np.zeros_like(t)] + [rods[f"masses[{i}].y"] for i in range(n)]
    for i in range(n):
        assert np.max(np.abs(np.hypot(xs[i + 1] - xs[i], ys[i + 1] - ys[i]) - 1.0)) < 1e-8
    assert len(rods.compiled.dynamic.switches) >= 1     # states re-chosen as rods turn


def test_joint_chain_report_states_are_the_joint_angles():
    n = 4
    rep = ac.compile(PendulumChain(n)).report
    assert rep.differential_index == 3
    for i in range(n):
        assert _differentiated(rep, f"links[{i}].bar.frame_b.x =") == [2]
        assert _differentiated(rep, f"links[{i}].bar.frame_b.y =") == [2]
    assert rep.states == [f"links[{i}].joint.{v}" for i in range(n) for v in ("phi", "w")]
    assert not rep.state_sets


def test_joint_chain_energy_conserved():
    n, t = 5, np.linspace(0, 2.0, 101)
    res = ac.simulate(PendulumChain(n), t_end=2.0, rtol=1e-8, atol=1e-8, t_eval=t)
    energy = sum(0.5 * (res[f"links[{i}].mass.vx"]**2 + res[f"links[{i}].mass.vy"]**2)
                 + G * res[f"links[{i}].mass.y"] for i in range(n))
    drop = G * sum(range(1, n + 1))           # potential energy of the full fall
    assert np.max(np.abs(energy - energy[0])) / drop < 1e-6


# -- cart with inverted pendulum and DC motor (Egeland & Gravdahl 7.5.1) ---------------

M_V, M_B, L_B, K_T, J_M, R_P = 1.0, 0.2, 0.5, 0.1, 2e-4, 0.02     # the example's values


def _cart_pendulum_ode(t, s):
    """(7.161)-(7.162) with m = m_v + J_m/r^2 and u = cos(2 pi t)."""
    x, th, v, w = s
    m = M_V + J_M / R_P**2
    u = np.cos(2 * np.pi * t)
    M = np.array([[m + M_B, M_B * L_B * np.cos(th)], [M_B * L_B * np.cos(th), M_B * L_B**2]])
    rhs = np.array([M_B * w**2 * L_B * np.sin(th) + K_T / R_P * u,
                    M_B * L_B * G * np.sin(th)])
    return [v, w, *np.linalg.solve(M, rhs)]


@pytest.fixture(scope="module")
def cart_pendulum_run():
    t = np.linspace(0, 1.0, 1001)
    compiled = ac.compile(CartPendulumMotor())
    res = ac.simulate(compiled, t_end=1.0, rtol=1e-10, atol=1e-10, t_eval=t)
    return t, compiled, res


def test_cart_pendulum_report_pulley_constraint_differentiated_twice(cart_pendulum_run):
    rep = cart_pendulum_run[1].report
    assert rep.differential_index == 3
    # x = r theta_m joins the motor's and the cart's positions: the "incompatible
    # causalities" of the book, resolved by differentiating the pulley twice
    assert _differentiated(rep, "pulley.flangeT.s =") == [2]
    assert len(rep.states) == 4


def test_cart_pendulum_effective_mass_7_161(cart_pendulum_run):
    """Upright and at rest, (7.161)-(7.162) give x'' = (K_T/r) u / (m_v + J_m/r^2):
    the pendulum's mass drops out, the motor's inertia counts as J_m/r^2."""
    _, _, res = cart_pendulum_run
    m = M_V + J_M / R_P**2
    assert res["track.a"][0] == pytest.approx(K_T / R_P * 1.0 / m, rel=1e-8)


def test_cart_pendulum_against_book_equations_7_161(cart_pendulum_run):
    t, _, res = cart_pendulum_run
    ode = solve_ivp(_cart_pendulum_ode, (0, 1.0), [0, 0, 0, 0], method="DOP853",
                    rtol=1e-12, atol=1e-12, t_eval=t)
    assert np.max(np.abs(res["track.s"] - ode.y[0])) < 1e-6
    assert np.max(np.abs(-res["joint.phi"] - ode.y[1])) < 1e-6
    assert np.max(np.abs(res["track.s"] - R_P * res["motor.motor.rotor.phi"])) < 1e-10


def test_cart_pendulum_energy_balance_7_156(cart_pendulum_run):
    """V' = F x' for the cart and pendulum (7.155)-(7.156), F the string's force; the
    motor's rotor stores the rest of the electrical power K_T u theta_m'."""
    t, _, res = cart_pendulum_run
    V = (0.5 * M_V * res["cart.vx"]**2
         + 0.5 * M_B * (res["bob.vx"]**2 + res["bob.vy"]**2) + M_B * G * res["bob.y"])
    work = cumulative_trapezoid(res["track.flange.f"] * res["track.v"], t, initial=0.0)
    scale = np.max(np.abs(V - V[0]))
    assert np.max(np.abs(V - V[0] - work)) < 1e-5 * scale
    w_m = res["motor.motor.rotor.w"]
    rotor = 0.5 * J_M * w_m**2
    motor_work = cumulative_trapezoid(K_T * np.cos(2 * np.pi * t) * w_m, t, initial=0.0)
    assert np.max(np.abs(V - V[0] + rotor - motor_work)) < 1e-5 * scale


# -- ball and beam (Egeland & Gravdahl 7.4) --------------------------------------------

J_1, M_2, R_B = 0.05, 0.1, 0.02


def _book_torque(t):
    return 0.05 * np.sin(np.pi * t)


def _ball_and_beam_ode(t, s):
    """(7.133)-(7.134) with J_2 = (2/5) m_2 R^2."""
    th, x, w, v = s
    k = 7 / 5 * M_2 * R_B**2                            # (7.127)
    M = np.array([[J_1 + M_2 * x**2, 0.0], [k, k / R_B]])
    rhs = np.array([_book_torque(t) + M_2 * G * x * np.cos(th) - 2 * M_2 * x * w * v
                    - M_2 * w**2 * x * R_B,
                    M_2 * R_B * x * w**2 + R_B * M_2 * G * np.sin(th)])
    return [w, v, *np.linalg.solve(M, rhs)]


@pytest.fixture(scope="module")
def ball_and_beam_run():
    t = np.linspace(0, 1.0, 1001)
    res = ac.simulate(BallAndBeam(), t_end=1.0, rtol=1e-10, atol=1e-10, t_eval=t)
    return t, res


def test_ball_and_beam_initial_acceleration_7_142(ball_and_beam_run):
    """Ball at rest at the pivot, beam at theta0 = 0.1 rad with no torque: theta'' = 0
    by (7.133), so x'' = (5/7) g sin(theta0) by (7.134), (5/7) g theta0 for small angles."""
    _, res = ball_and_beam_run
    theta0 = 0.1
    x_acc = 5 / 7 * G * np.sin(theta0)          # the scale of the accelerations, 0.7 m/s2
    assert res["pivot.a"][0] == pytest.approx(0.0, abs=1e-9 * x_acc)
    assert res["track.a"][0] == pytest.approx(x_acc, rel=1e-8)
    assert res["track.a"][0] == pytest.approx(5 / 7 * G * theta0, rel=theta0**2 / 6 * 1.01)


def test_ball_and_beam_against_book_equations_7_133(ball_and_beam_run):
    t, res = ball_and_beam_run
    ode = solve_ivp(_ball_and_beam_ode, (0, 1.0), [0.1, 0, 0, 0], method="DOP853",
                    rtol=1e-12, atol=1e-12, t_eval=t)
    assert np.max(np.abs(-res["pivot.phi"] - ode.y[0])) < 1e-6
    assert np.max(np.abs(res["track.s"] - ode.y[1])) < 1e-6


def test_ball_and_beam_energy_balance_7_136(ball_and_beam_run):
    t, res = ball_and_beam_run
    th, w = -res["pivot.phi"], -res["pivot.w"]
    x, v = res["track.s"], res["track.v"]
    J_2 = 2 / 5 * M_2 * R_B**2
    V = (0.5 * J_1 * w**2 + 0.5 * J_2 * (w + v / R_B)**2
         + 0.5 * M_2 * ((v + w * R_B)**2 + (w * x)**2)
         + M_2 * G * (-x * np.sin(th) + R_B * np.cos(th)))          # (7.135)
    work = cumulative_trapezoid(w * _book_torque(t), t, initial=0.0)  # (7.136)
    assert np.max(np.abs(V - V[0] - work)) < 1e-5 * np.max(np.abs(V - V[0]))


# -- slider-crank: a closed kinematic loop ---------------------------------------------

def test_slider_crank_against_closed_form_kinematics():
    t = np.linspace(0, 1.0, 2001)
    res = ac.simulate(SliderCrank(), t_end=1.0, rtol=1e-9, atol=1e-9, t_eval=t)
    theta = res["crank_joint.phi"]
    assert np.max(np.abs(theta - (0.3 + 10.0 * t))) < 1e-8
    assert np.max(np.abs(res["guide.s"] - slider_position(theta))) < 1e-8
    assert theta[-1] > 0.3 + 2 * np.pi          # past both dead centres
    # the drive's work is the mechanism's energy
    m_rod, J_rod, m_s = 0.5, 0.5 * 0.3**2 / 12, 1.0
    E = (0.5 * m_rod * (res["rod.vx"]**2 + res["rod.vy"]**2) + 0.5 * J_rod * res["rod.w"]**2
         + m_rod * G * res["rod.y"] + 0.5 * m_s * res["slider.vx"]**2)
    work = cumulative_trapezoid(-res["drive.flange.tau"] * 10.0, t, initial=0.0)
    assert np.max(np.abs(E - E[0] - work)) < 1e-5 * np.max(np.abs(E - E[0]))


# -- components: sign conventions, Prismatic, Spring, Damper --------------------------

class DrivenWheel(ac.Component):
    """A wheel (J = 0.5) on a revolute to the world, driven by 2 N m through the flange."""

    world = mb.FixedFrame()
    joint = mb.Revolute()
    drive = rot.ConstantTorque(tau_constant=2.0)
    wheel = mb.Body(m=1.0, J=0.5)

    def equations(self):
        return [ac.connect(self.world.frame, self.joint.frame_a),
                ac.connect(self.joint.frame_b, self.wheel.frame),
                ac.connect(self.drive.flange, self.joint.flange)]


def test_revolute_flange_torque_turns_frame_b_and_reacts_on_frame_a():
    res = ac.simulate(DrivenWheel(), t_end=1.0, rtol=1e-9, n_points=11)
    assert np.allclose(res["joint.a"], 4.0, rtol=1e-9)
    assert np.allclose(res["wheel.phi"], 2.0 * res.t**2, rtol=1e-8, atol=1e-12)
    assert np.allclose(res["world.frame.tau"], -2.0, rtol=1e-9)    # the reaction
    assert np.allclose(res["world.frame.fy"], -G, rtol=1e-9)       # the wheel's weight


class HorizontalBar(ac.Component):
    """A 3 kg mass at the end of a 2 m horizontal bar, its revolute locked."""

    world = mb.FixedFrame()
    joint = mb.Revolute()
    lock = rot.Fixed()
    bar = mb.FixedTranslation(rx=2.0, ry=0.0)
    mass = mb.Body(m=3.0, J=0.0)

    def equations(self):
        return [ac.connect(self.world.frame, self.joint.frame_a),
                ac.connect(self.joint.frame_b, self.bar.frame_a),
                ac.connect(self.bar.frame_b, self.mass.frame),
                ac.connect(self.joint.flange, self.lock.flange)]


def test_fixed_translation_transmits_the_moment_of_the_weight():
    res = ac.simulate(HorizontalBar(), t_end=0.1, n_points=3)
    assert np.allclose(res["joint.flange.tau"], 3.0 * G * 2.0, rtol=1e-10)
    assert np.allclose(res["bar.frame_a.tau"], 3.0 * G * 2.0, rtol=1e-10)
    assert np.allclose(res["world.frame.fy"], -3.0 * G, rtol=1e-10)


class HangingSpringMass(ac.Component):
    """A 2 kg body on a vertical Prismatic (s downwards), hung from the world origin by
    a spring (c = 200 N/m, 0.5 m unstretched) and a damper in parallel."""

    world = mb.FixedFrame()
    guide = mb.Prismatic(ex=0.0, ey=-1.0, s={"start": 0.698, "fixed": True},
                         v={"start": 0.0, "fixed": True})
    body = mb.Body(m=2.0, J=0.1)
    spring = mb.Spring(c=200.0, s_unstretched=0.5)
    damper = mb.Damper(d=4.0)

    def equations(self):
        return [ac.connect(self.world.frame, self.guide.frame_a, self.spring.frame_a,
                           self.damper.frame_a),
                ac.connect(self.guide.frame_b, self.body.frame, self.spring.frame_b,
                           self.damper.frame_b)]


class HangingSpringDamperMass(HangingSpringMass):
    """The same with one SpringDamper."""

    spring = mb.SpringDamper(c=200.0, d=4.0, s_unstretched=0.5)
    damper = mb.Damper(d=0.0)


def test_prismatic_spring_damper_oscillator_closed_form():
    m, c, d = 2.0, 200.0, 4.0
    s_eq = 0.5 + m * G / c
    t = np.linspace(0, 3.0, 301)
    res = ac.simulate(HangingSpringMass(), t_end=3.0, rtol=1e-10, atol=1e-10, t_eval=t)
    w0, zeta = np.sqrt(c / m), d / (2 * np.sqrt(c * m))
    wd = w0 * np.sqrt(1 - zeta**2)
    a0 = 0.698 - s_eq
    exact = s_eq + a0 * np.exp(-zeta * w0 * t) * (np.cos(wd * t)
                                                   + zeta * w0 / wd * np.sin(wd * t))
    assert np.max(np.abs(res["guide.s"] - exact)) < 1e-7
    assert np.allclose(res["body.y"], -res["guide.s"], atol=1e-12)
    assert np.allclose(res["spring.s"], res["guide.s"], atol=1e-12)
    both = ac.simulate(HangingSpringDamperMass(), t_end=3.0, rtol=1e-10, atol=1e-10, t_eval=t)
    assert np.max(np.abs(both["guide.s"] - res["guide.s"])) < 1e-8


class SpringPendulum(ac.Component):
    """A free body on a spring from the world origin: elastic pendulum in the plane."""

    world = mb.FixedFrame()
    spring = mb.Spring(c=100.0, s_unstretched=1.0)
    body = mb.Body(m=1.0, J=0.1, x={"start": 0.6, "fixed": True},
                   y={"start": -1.0, "fixed": True}, vx={"start": 0.0, "fixed": True},
                   vy={"start": 0.5, "fixed": True}, phi={"start": 0.0, "fixed": True},
                   w={"start": 1.0, "fixed": True})

    def equations(self):
        return [ac.connect(self.world.frame, self.spring.frame_a),
                ac.connect(self.spring.frame_b, self.body.frame)]


def test_spring_pendulum_energy_and_free_rotation():
    t = np.linspace(0, 5.0, 501)
    res = ac.simulate(SpringPendulum(), t_end=5.0, rtol=1e-10, atol=1e-10, t_eval=t)
    s = np.hypot(res["body.x"], res["body.y"])
    energy = (0.5 * (res["body.vx"]**2 + res["body.vy"]**2) + 0.5 * 0.1 * res["body.w"]**2
              + G * res["body.y"] + 0.5 * 100.0 * (s - 1.0)**2)
    assert np.max(np.abs(energy - energy[0])) / np.max(np.abs(energy)) < 1e-7
    assert np.allclose(res["body.w"], 1.0, rtol=1e-10)           # the spring takes no torque

