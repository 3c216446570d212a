"""Planar multibody systems assembled from frames, joints, bars and bodies, checked
against hand-written Cartesian models, angle-coordinate ODEs, the book's closed forms
and energy balances."""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal as ac
from acausal.library.examples.pendulum import DoublePendulum as CartesianDoublePendulum
from acausal.library.multibody.examples.pendulums import (DoublePendulum, PendulumChain,
                                                          SinglePendulum)

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
