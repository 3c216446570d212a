"""Spatial multibody systems assembled from the World, joints, bars and bodies, checked
against hand-derived equations of motion (Egeland & Gravdahl's Furuta pendulum), closed
forms (steady precession of the heavy top, free fall under a constant force, physical
pendulums), conservation laws (energy, angular momentum, the quaternion norm) and the
planar library."""
import numpy as np
import pytest
from scipy.integrate import cumulative_simpson, solve_ivp

import acausal as ac
from acausal.compiler.structure.matching import UnderdeterminedModel
from acausal.library import multibody3d as mb
from acausal.library.blocks import Constant
from acausal.library.multibody.examples.pendulums import DoublePendulum as PlanarDoublePendulum
from acausal.library.multibody3d.examples.furuta import FurutaPendulum
from acausal.library.multibody3d.examples.pendulums import DoublePendulum
from acausal.library.multibody3d.examples.slider_crank import SliderCrank, slider_position
from acausal.library.multibody3d.examples.tops import (RACKET, TOP, HeavyTop, TennisRacket,
                                                       top_precession_rate)

G = 9.80665


def _differentiated(report, fragment):
    return [e["differentiated"] for e in report.equations
            if e["order"] == 0 and fragment in e["text"]]


def _R(res, frame):
    """The orientation R (world -> frame) as an array [3, 3, n]."""
    return np.array([[res[f"{frame}.R{i}{j}"] for j in (1, 2, 3)] for i in (1, 2, 3)])


def _vec(res, name):
    """A vector variable (an array of 3) as an array [3, n]."""
    return np.asarray(res[name]).T


def _ode(f, y0, t, **kw):
    return solve_ivp(f, (t[0], t[-1]), y0, method="DOP853", rtol=1e-11, atol=1e-12,
                     t_eval=t, **kw)


# -- Furuta pendulum (Egeland & Gravdahl 7.6, 8.2.7) -----------------------------------

J_1, M_F, L_1, L_2 = 0.01, 0.1, 0.2, 0.3          # the example's values


def _torque(t):
    return 0.05 * np.sin(2 * np.pi * t)


def _furuta_lagrange(t, s):
    """(8.45)-(8.46) solved for the accelerations."""
    th1, th2, w1, w2 = s
    sn, c = np.sin(th2), np.cos(th2)
    M = np.array([[J_1 + M_F * L_1**2 + M_F * L_2**2 * sn**2, -M_F * L_1 * L_2 * c],
                  [-M_F * L_1 * L_2 * c, M_F * L_2**2]])
    rhs = np.array([_torque(t) - 2 * M_F * L_2**2 * w1 * w2 * sn * c
                    - M_F * L_1 * L_2 * w2**2 * sn,
                    M_F * L_2**2 * sn * c * w1**2 + M_F * G * L_2 * sn])
    return [w1, w2, *np.linalg.solve(M, rhs)]


def _furuta_energy(th2, w1, w2):
    """(7.195)."""
    sn, c = np.sin(th2), np.cos(th2)
    return (0.5 * (J_1 + M_F * L_1**2 + M_F * L_2**2 * sn**2) * w1**2
            + 0.5 * M_F * L_2**2 * w2**2 - M_F * L_1 * L_2 * w1 * w2 * c
            + M_F * G * L_2 * c)


@pytest.fixture(scope="module")
def furuta_run():
    t = np.linspace(0, 2.0, 2001)
    compiled = ac.compile(FurutaPendulum())
    res = ac.simulate(compiled, t_end=2.0, rtol=1e-10, atol=1e-10, t_eval=t)
    return t, compiled, res


def test_furuta_report_joint_angles_are_the_states(furuta_run):
    rep = furuta_run[1].report
    print(rep)
    assert rep.differential_index == 3
    assert rep.states == ["arm_joint.phi", "arm_joint.w", "pendulum_joint.phi",
                          "pendulum_joint.w"]
    # the bars place the mass: position level, differentiated twice
    assert _differentiated(rep, "pendulum_rod.frame_b.x =") == [2]
    assert not rep.state_sets


def test_furuta_against_lagrange_equations_8_45(furuta_run):
    t, _, res = furuta_run
    ode = _ode(_furuta_lagrange, [0.0, 0.2, 0.0, 0.0], t)
    th1, th2 = res["arm_joint.phi"], res["pendulum_joint.phi"]
    assert np.ptp(th2) > 2 * np.pi                  # the pendulum falls and turns over
    for mine, ref in ((th1, ode.y[0]), (th2, ode.y[1]), (res["arm_joint.w"], ode.y[2]),
                      (res["pendulum_joint.w"], ode.y[3])):
        assert np.max(np.abs(mine - ref)) < 1e-6 * np.max(np.abs(ref))


def test_furuta_power_balance_7_196(furuta_run):
    """V' = theta_1' T: the energy (7.195) on the model's angles changes by the motor's
    work, and it equals the energy of the model's bodies."""
    t, _, res = furuta_run
    th2, w1, w2 = res["pendulum_joint.phi"], res["arm_joint.w"], res["pendulum_joint.w"]
    V = _furuta_energy(th2, w1, w2)
    work = cumulative_simpson(w1 * _torque(t), x=t, initial=0.0)
    scale = np.max(np.abs(V - V[0]))
    assert np.max(np.abs(V - V[0] - work)) < 1e-6 * scale
    v = _vec(res, "mass.v_0")
    bodies = (0.5 * J_1 * res["arm.w_a[1]"]**2 + 0.5 * M_F * np.sum(v**2, axis=0)
              + M_F * G * (res["mass.frame_a.y"] - res["mass.frame_a.y"][0]
                           + L_2 * np.cos(0.2)))
    assert np.max(np.abs(bodies - V)) < 1e-8 * scale


def test_furuta_energy_audit_every_component(furuta_run):
    """The audit books the motor's work into the bodies' energy, and finds the joints
    and bars lossless through the spatial frame's power f . (R der(r_0)) + t . w."""
    _, compiled, _ = furuta_run
    model = FurutaPendulum()
    res = ac.simulate(compiled, t_end=2.0, rtol=1e-10, atol=1e-10, n_points=401)
    audit = ac.energy_balance(res, model)
    assert audit.ok, audit.violations
    assert audit.roles["arm_joint"] == "lossless" and audit.roles["mass"] == "storage"
    assert np.max(np.abs(audit.lossless["pendulum_joint"])) < 1e-6 * audit.power_scale


# -- heavy symmetric top on a spherical joint ------------------------------------------

def _top_invariants(res):
    """Energy and the angular momentum about the pivot, in the world (frame_a of the top
    is at the fixed pivot)."""
    R, w = _R(res, "top.frame_a"), _vec(res, "top.w_a")
    m, l, I1, I3 = TOP["m"], TOP["l"], TOP["I_1"], TOP["I_3"]
    I_o = np.diag([I1 + m * l**2, I3, I1 + m * l**2])     # about the pivot, r_CM = l e_y
    H = np.einsum("jin,jn->in", R, I_o @ w)                # R^T I_o w
    E = 0.5 * np.einsum("in,in->n", w, I_o @ w) + m * G * l * R[1, 1]
    return E, H


@pytest.fixture(scope="module")
def top_run():
    t = np.linspace(0, 0.6, 301)
    compiled = ac.compile(HeavyTop())
    res = ac.simulate(compiled, t_end=0.6, rtol=1e-9, atol=1e-9, t_eval=t)
    return t, compiled, res


def test_top_report_quaternion_and_angular_velocity_are_the_states(top_run):
    rep = top_run[1].report
    print(rep)
    assert rep.states == [f"pivot.Q[{i}]" for i in range(4)] + [f"pivot.w_rel[{i}]"
                                                                 for i in range(3)]
    assert _differentiated(rep, "pivot.frame_b.R22 =") == [2]
    assert not rep.state_sets


def test_top_steady_precession_rate(top_run):
    t, _, res = top_run
    axis = _R(res, "top.frame_a")[1]                      # the symmetry axis R^T e_y
    azimuth = np.unwrap(np.arctan2(axis[2], -axis[0]))
    Omega = top_precession_rate(**TOP)
    assert np.max(np.abs(azimuth - Omega * t)) < 1e-7 * Omega * t[-1]
    assert np.max(np.abs(np.arccos(axis[1]) - TOP["theta"])) < 1e-6 * TOP["theta"]


def test_top_energy_and_vertical_angular_momentum_conserved(top_run):
    _, _, res = top_run
    E, H = _top_invariants(res)
    assert np.max(np.abs(E - E[0])) < 1e-7 * np.abs(E[0])
    assert np.max(np.abs(H[1] - H[1][0])) < 1e-7 * np.max(np.linalg.norm(H, axis=0))


# -- free body near its intermediate axis ----------------------------------------------

@pytest.fixture(scope="module")
def racket_run():
    t = np.linspace(0, 100.0, 2001)
    res = ac.simulate(TennisRacket(), t_end=100.0, rtol=1e-9, atol=1e-9, t_eval=t)
    return t, res


def test_racket_flips_with_energy_and_world_angular_momentum_conserved(racket_run):
    _, res = racket_run
    w = _vec(res, "body.w_a")
    assert np.sum(np.diff(np.sign(w[1])) != 0) >= 4       # flips over and over
    I = np.diag([RACKET["I_1"], RACKET["I_2"], RACKET["I_3"]])
    E = 0.5 * np.einsum("in,in->n", w, I @ w)
    H = np.einsum("jin,jn->in", _R(res, "body.frame_a"), I @ w)
    assert np.max(np.abs(E - E[0])) < 1e-6 * E[0]
    assert np.max(np.linalg.norm(H - H[:, :1], axis=0)) < 1e-6 * np.linalg.norm(H[:, 0])


def test_racket_quaternion_norm_kept_over_100_s(racket_run):
    _, res = racket_run
    Q = _vec(res, "joint.Q")
    drift = np.max(np.abs(np.sum(Q**2, axis=0) - 1.0))
    assert drift < 1e-7
    R = _R(res, "body.frame_a")                           # orthogonal whatever |Q|
    RRt = np.einsum("ikn,jkn->ijn", R, R)
    assert np.max(np.abs(RRt - np.eye(3)[:, :, None])) < 1e-12


# -- the planar double pendulum, in 3-D ------------------------------------------------

def test_double_pendulum_in_a_plane_equals_the_planar_library():
    t = np.linspace(0, 3.0, 151)
    kw = dict(t_end=3.0, rtol=1e-10, atol=1e-10, t_eval=t)
    spatial = ac.simulate(DoublePendulum(), **kw)
    planar = ac.simulate(PlanarDoublePendulum(), **kw)
    for i in (1, 2):
        assert np.max(np.abs(spatial[f"link{i}.joint.phi"] - planar[f"link{i}.joint.phi"])) < 1e-6
        for c in "xy":
            assert np.max(np.abs(spatial[f"link{i}.mass.frame_a.{c}"]
                                 - planar[f"link{i}.mass.{c}"])) < 1e-6
        assert np.max(np.abs(spatial[f"link{i}.mass.frame_a.z"])) == 0.0


# -- a closed loop: slider-crank ------------------------------------------------------

def test_slider_crank_loop_closed_in_the_plane_against_closed_form():
    t = np.linspace(0, 1.0, 2001)
    res = ac.simulate(SliderCrank(), t_end=1.0, rtol=1e-9, atol=1e-9, t_eval=t)
    theta = res["crank_joint.phi"]
    assert theta[-1] > 0.3 + 2 * np.pi                  # past both dead centres
    assert np.max(np.abs(res["guide.s"] - slider_position(theta))) < 1e-8 * 0.4
    assert np.max(np.abs(res["rod_b.frame_b.z"])) < 1e-12   # the loop stays in its plane
    # the drive's work is the mechanism's energy
    m_rod, I_rod, m_s = 0.5, 0.5 * 0.3**2 / 12, 1.0
    v_rod = _vec(res, "rod.v_0")
    E = (0.5 * m_rod * np.sum(v_rod**2, axis=0) + 0.5 * I_rod * res["rod.w_a[2]"]**2
         + m_rod * 9.81 * res["rod.frame_a.y"] + 0.5 * m_s * res["slider.v_0[0]"]**2)
    # Simpson's rule: the trapezoid's h^2 error is 1e-5 of the signal near the dead centres
    work = cumulative_simpson(-res["drive.flange.tau"] * 10.0, x=t, initial=0.0)
    assert np.max(np.abs(E - E[0] - work)) < 1e-6 * np.max(np.abs(E - E[0]))


# -- bodies whose frame is not at the centre of mass -----------------------------------

class BoxPendulum(ac.Component):
    """A steel box 0.5 x 0.1 x 0.05 m on a revolute about z at one end, released
    horizontal."""

    world = mb.World()
    joint = mb.Revolute(phi={"start": 0.0, "fixed": True}, w={"start": 0.0, "fixed": True})
    box = mb.BodyBox(r_1=0.5, width=0.1, height=0.05)

    def equations(self):
        return [ac.connect(self.world.frame_b, self.joint.frame_a),
                ac.connect(self.joint.frame_b, self.box.frame_a)]


class CylinderPendulum(BoxPendulum):
    box = mb.BodyCylinder(r_1=0.5, diameter=0.1, innerDiameter=0.04)


@pytest.mark.parametrize("model, m, I_zz", [
    (BoxPendulum, 7700 * 0.5 * 0.1 * 0.05, 7700 * 0.5 * 0.1 * 0.05 * (0.5**2 + 0.1**2) / 12),
    (CylinderPendulum, 7700 * np.pi * (0.1**2 - 0.04**2) / 4 * 0.5,
     7700 * np.pi * (0.1**2 - 0.04**2) / 4 * 0.5 * ((0.1**2 + 0.04**2) / 16 + 0.5**2 / 12)),
])
def test_shaped_body_physical_pendulum(model, m, I_zz):
    """phi'' = -m g (L/2) cos(phi) / (I_zz + m (L/2)^2): mass and inertia from density and
    dimensions, and Newton-Euler about a frame L/2 from the centre of mass."""
    t = np.linspace(0, 2.0, 201)
    res = ac.simulate(model(), t_end=2.0, rtol=1e-10, atol=1e-10, t_eval=t)
    I_o = I_zz + m * 0.25**2
    ode = _ode(lambda _, s: [s[1], -m * G * 0.25 * np.cos(s[0]) / I_o], [0.0, 0.0], t)
    assert np.max(np.abs(res["joint.phi"] - ode.y[0])) < 1e-7 * np.max(np.abs(ode.y[0]))
    # at release the pivot carries m (g + a_CM,y), a_CM,y = phi''(0) L/2 = -m g L^2/(4 I_o)
    reaction = -m * (G - m * G * 0.25**2 / I_o)
    assert res["world.frame_b.fy"][0] == pytest.approx(reaction, rel=1e-9)


# -- cut force, world force, line force, sensors ---------------------------------------

class Cantilever(ac.Component):
    """A 3 kg mass at the end of a rigid 2 m bar along x, clamped to the world through a
    cut-force sensor."""

    world = mb.World()
    cut = mb.CutForceAndTorque()
    bar = mb.FixedRotation(n_1=0.0, n_2=1.0, n_3=0.0, angle=90.0, r_1=2.0)
    mass = mb.Body(m=3.0)

    def equations(self):
        return [ac.connect(self.world.frame_b, self.cut.frame_a),
                ac.connect(self.cut.frame_b, self.bar.frame_a),
                ac.connect(self.bar.frame_b, self.mass.frame_a)]


def test_cut_force_and_torque_hold_the_weight_and_its_moment():
    res = ac.simulate(Cantilever(), t_end=0.1, n_points=3)
    assert np.allclose(res["cut.force[1].signal"], 3.0 * G, rtol=1e-12)
    assert np.allclose(res["cut.torque[2].signal"], 3.0 * G * 2.0, rtol=1e-12)
    for c in ("force[0]", "force[2]", "torque[0]", "torque[1]"):
        assert np.max(np.abs(res[f"cut.{c}.signal"])) < 1e-12 * 3.0 * G * 2.0
    # the fixed rotation turned the mass's frame by 90 degrees about y: its x is world -z
    assert np.allclose(res["mass.frame_a.R13"], -1.0, rtol=1e-12)
    assert np.allclose(res["mass.frame_a.fy"], 3.0 * G, rtol=1e-12)   # the bar holds it up


class PushedSpinningBody(ac.Component):
    """A free body (no gravity) spinning about a non-principal direction, pushed by a
    constant force F and twisted by a constant torque T, both given in the world, at its
    centre of mass, with sensors on it."""

    world = mb.World(g=0.0)
    joint = mb.FreeMotion(angles_fixed=True,
                          w_rel_b={"start": [1.0, 2.0, -0.5], "fixed": True},
                          r_rel_a={"start": 0.0, "fixed": True},
                          v_rel_a={"start": 0.0, "fixed": True})
    body = mb.Body(m=2.0, I_11=0.1, I_22=0.2, I_33=0.3, I_21=0.01)
    push = mb.WorldForce()
    F_x, F_y, F_z = Constant(k=1.0), Constant(k=2.0), Constant(k=-1.0)
    twist = mb.WorldTorque()
    T_x, T_y, T_z = Constant(k=0.1), Constant(k=0.0), Constant(k=0.2)
    position = mb.AbsolutePosition()
    velocity = mb.AbsoluteVelocity()
    spin = mb.AbsoluteAngularVelocity()
    relative = mb.RelativePosition()

    def equations(self):
        b = self.body.frame_a
        return [ac.connect(self.world.frame_b, self.joint.frame_a, self.relative.frame_a),
                ac.connect(self.joint.frame_b, b, self.push.frame_b, self.position.frame_a,
                           self.velocity.frame_a, self.spin.frame_a, self.relative.frame_b),
                ac.connect(self.F_x.y, self.push.force[0]),
                ac.connect(self.F_y.y, self.push.force[1]),
                ac.connect(self.F_z.y, self.push.force[2]),
                ac.connect(b, self.twist.frame_b),
                ac.connect(self.T_x.y, self.twist.torque[0]),
                ac.connect(self.T_y.y, self.twist.torque[1]),
                ac.connect(self.T_z.y, self.twist.torque[2])]


def test_world_force_and_torque_on_spinning_body_and_sensors():
    """r = F t^2/(2 m) and the angular momentum in the world H = H_0 + T t, whatever
    the body's tumbling."""
    t = np.linspace(0, 2.0, 101)
    res = ac.simulate(PushedSpinningBody(), t_end=2.0, rtol=1e-10, atol=1e-10, t_eval=t)
    F, m = np.array([1.0, 2.0, -1.0]), 2.0
    r = np.array([res[f"position.r[{k}].signal"] for k in range(3)])
    assert np.max(np.abs(r - np.outer(F / m, t**2 / 2))) < 1e-8 * np.max(np.abs(r))
    v = np.array([res[f"velocity.v[{k}].signal"] for k in range(3)])
    assert np.max(np.abs(v - np.outer(F / m, t))) < 1e-8 * np.max(np.abs(v))
    w = np.array([res[f"spin.w[{k}].signal"] for k in range(3)])
    assert np.max(np.abs(w - _vec(res, "joint.w_rel_b"))) < 1e-8 * np.max(np.abs(w))
    assert np.ptp(w[2]) > 0.1                         # a torque-free body that tumbles
    I = np.array([[0.1, 0.01, 0.0], [0.01, 0.2, 0.0], [0.0, 0.0, 0.3]])
    H = np.einsum("jin,jn->in", _R(res, "body.frame_a"), I @ _vec(res, "body.w_a"))
    H_exact = H[:, :1] + np.outer([0.1, 0.0, 0.2], t)
    assert np.max(np.abs(H - H_exact)) < 1e-8 * np.max(np.abs(H))
    rel = np.array([res[f"relative.r_rel[{k}].signal"] for k in range(3)])
    assert np.max(np.abs(rel - r)) < 1e-12 * np.max(np.abs(r))     # world = frame_a here


class UniversalPendulum(ac.Component):
    """A 1 kg point mass on a 1 m rod hanging from a universal joint (x, then z)."""

    world = mb.World()
    joint = mb.Universal(n_b_2=0.0, n_b_3=1.0,
                         revolute_a={"phi": {"start": 0.3, "fixed": True},
                                     "w": {"start": 0.0, "fixed": True}},
                         revolute_b={"phi": {"start": 0.4, "fixed": True},
                                     "w": {"start": 1.0, "fixed": True}})
    rod = mb.FixedTranslation(r_2=-1.0)
    mass = mb.Body(m=1.0, I_11=0.0, I_22=0.0, I_33=0.0)

    def equations(self):
        return [ac.connect(self.world.frame_b, self.joint.frame_a),
                ac.connect(self.joint.frame_b, self.rod.frame_a),
                ac.connect(self.rod.frame_b, self.mass.frame_a)]


def _universal_lagrange():
    """Lagrange's equations of the point mass at R_x(a) R_z(b) (0, -1, 0), derived here
    with sympy: M(q) q'' = rhs(q, q')."""
    import sympy as sp
    a, b, da, db = sp.symbols("a b da db")
    Rx = sp.Matrix([[1, 0, 0], [0, sp.cos(a), -sp.sin(a)], [0, sp.sin(a), sp.cos(a)]])
    Rz = sp.Matrix([[sp.cos(b), -sp.sin(b), 0], [sp.sin(b), sp.cos(b), 0], [0, 0, 1]])
    r = Rx * Rz * sp.Matrix([0, -1, 0])
    q, dq = sp.Matrix([a, b]), sp.Matrix([da, db])
    v = r.jacobian(q) * dq
    L = v.dot(v) / 2 - G * r[1]
    M = sp.hessian(L, dq)
    rhs = sp.Matrix([sp.diff(L, qi) for qi in q]) - sp.Matrix(
        [sum(sp.diff(sp.diff(L, dqi), qj) * dqj for qj, dqj in zip(q, dq)) for dqi in dq])
    return sp.lambdify((a, b, da, db), M), sp.lambdify((a, b, da, db), rhs)


def test_universal_joint_pendulum_against_lagrange():
    M, rhs = _universal_lagrange()

    def f(_, s):
        return [s[2], s[3], *np.linalg.solve(M(*s), np.ravel(rhs(*s)))]

    t = np.linspace(0, 2.0, 201)
    res = ac.simulate(UniversalPendulum(), t_end=2.0, rtol=1e-10, atol=1e-10, t_eval=t)
    ode = _ode(f, [0.3, 0.4, 0.0, 1.0], t)
    for name, ref in (("joint.revolute_a.phi", ode.y[0]), ("joint.revolute_b.phi", ode.y[1])):
        assert np.max(np.abs(res[name] - ref)) < 1e-6 * np.max(np.abs(ref))


class ElasticPendulum(ac.Component):
    """A free body on a spring from the world origin, started off the plane."""

    world = mb.World()
    spring = mb.Spring(c=100.0, s_unstretched=1.0)
    joint = mb.FreeMotion(angles_fixed=True,
                          r_rel_a={"start": [0.6, -1.0, 0.2], "fixed": True},
                          v_rel_a={"start": [0.0, 0.5, 0.3], "fixed": True},
                          w_rel_b={"start": [1.0, 0.0, 0.0], "fixed": True})
    body = mb.Body(m=1.0, I_11=0.1, I_22=0.1, I_33=0.1)

    def equations(self):
        return [ac.connect(self.world.frame_b, self.spring.frame_a, self.joint.frame_a),
                ac.connect(self.joint.frame_b, self.spring.frame_b, self.body.frame_a)]


def test_spring_pendulum_energy_and_torque_free_spin():
    t = np.linspace(0, 1.0, 101)
    res = ac.simulate(ElasticPendulum(), t_end=1.0, rtol=1e-10, atol=1e-10, t_eval=t)
    r, v = np.array([res[f"body.frame_a.{c}"] for c in "xyz"]), _vec(res, "body.v_0")
    s = np.linalg.norm(r, axis=0)
    assert np.allclose(res["spring.s"], s, rtol=1e-10)
    E = (0.5 * np.sum(v**2, axis=0) + 0.5 * 0.1 * np.sum(_vec(res, "body.w_a")**2, axis=0)
         + G * r[1] + 0.5 * 100.0 * (s - 1.0)**2)
    assert np.max(np.abs(E - E[0])) < 1e-7 * np.max(np.abs(E))
    assert np.allclose(res["body.w_a[0]"], 1.0, rtol=1e-10)     # the spring takes no torque
    assert np.ptp(r[2]) > 0.1                                # it leaves the plane


class HangingSpringMass(ac.Component):
    """A 2 kg body on a vertical Prismatic (s downwards), on a spring and a damper."""

    world = mb.World(g=9.81)
    guide = mb.Prismatic(n_1=0.0, n_2=-1.0, s={"start": 0.698, "fixed": True},
                         v={"start": 0.0, "fixed": True})
    body = mb.Body(m=2.0)
    spring = mb.SpringDamperParallel(c=200.0, d=4.0, s_unstretched=0.5)

    def equations(self):
        return [ac.connect(self.world.frame_b, self.guide.frame_a, self.spring.frame_a),
                ac.connect(self.guide.frame_b, self.body.frame_a, self.spring.frame_b)]


def test_prismatic_spring_damper_oscillator_closed_form():
    m, c, d = 2.0, 200.0, 4.0
    s_eq = 0.5 + m * 9.81 / c
    t = np.linspace(0, 3.0, 301)
    res = ac.simulate(HangingSpringMass(), t_end=3.0, rtol=1e-10, atol=1e-10, t_eval=t)
    w0, zeta = np.sqrt(c / m), d / (2 * np.sqrt(c * m))
    wd = w0 * np.sqrt(1 - zeta**2)
    exact = s_eq + (0.698 - s_eq) * np.exp(-zeta * w0 * t) * (
        np.cos(wd * t) + zeta * w0 / wd * np.sin(wd * t))
    assert np.max(np.abs(res["guide.s"] - exact)) < 1e-7 * abs(0.698 - s_eq)
    assert np.allclose(res["body.frame_a.y"], -res["guide.s"], atol=1e-12)


# -- what the connector cannot express ------------------------------------------------

class ParallelJoints(ac.Component):
    """Two revolutes between the World and one bar: a kinematic loop closed without a
    RevolutePlanarLoopConstraint."""

    world = mb.World()
    joint1 = mb.Revolute()
    joint2 = mb.Revolute()
    bar = mb.FixedTranslation(r_1=1.0)

    def equations(self):
        return [ac.connect(self.world.frame_b, self.joint1.frame_a, self.joint2.frame_a),
                ac.connect(self.joint1.frame_b, self.joint2.frame_b, self.bar.frame_a)]


class UnattachedBody(ac.Component):
    world = mb.World()
    spring = mb.Spring()
    body = mb.Body()

    def equations(self):
        return [ac.connect(self.world.frame_b, self.spring.frame_a),
                ac.connect(self.spring.frame_b, self.body.frame_a)]


@pytest.mark.parametrize("model, error", [(ParallelJoints, ac.ModelError),
                                          (UnattachedBody, UnderdeterminedModel)])
def test_loop_or_unattached_body_is_refused_with_the_frame_hint(model, error):
    with pytest.raises(error, match="kinematic loop") as err:
        ac.compile(model())
    assert "FreeMotion" in str(err.value)


# -- animation ------------------------------------------------------------------------

def test_animation_of_the_furuta_pendulum_is_written_and_moves(furuta_run, tmp_path):
    from acausal.display.animation import spatial_frames
    _, _, res = furuta_run
    frames = spatial_frames(res)
    assert "mass.frame_a" in frames
    # frames joined at one point with one orientation are drawn once
    assert not {"pendulum_rod.frame_a", "pendulum_joint.frame_b"} <= set(frames)
    out = ac.animate(res, tmp_path / "furuta.gif", n_frames=4,
                     links=[("arm_rod.frame_a", "arm_rod.frame_b"),
                            ("pendulum_rod.frame_a", "pendulum_rod.frame_b")])
    assert out.exists() and out.stat().st_size > 0
    if out.suffix == ".gif":
        Image = pytest.importorskip("PIL.Image")
        with Image.open(out) as im:
            assert im.n_frames == 4
            first = np.asarray(im.convert("RGB"), dtype=float)
            im.seek(3)
            last = np.asarray(im.convert("RGB"), dtype=float)
        below_title = slice(first.shape[0] // 6, None)
        change = np.abs(first[below_title] - last[below_title])
        assert np.mean(change) > 0.1                    # the pendulum moved in the picture
    else:                                               # no Pillow: the HTML player
        assert "<script" in out.read_text()


def test_joint_axis_without_direction_is_named():
    class ZeroAxis(ac.Component):
        world = mb.World()
        joint = mb.Revolute(n_3=0.0)
        body = mb.Body()

        def equations(self):
            return [ac.connect(self.world.frame_b, self.joint.frame_a),
                    ac.connect(self.joint.frame_b, self.body.frame_a)]

    with pytest.raises(ac.InvalidValue, match=r"'joint' \(Revolute\): n_1, n_2, n_3 are all 0"):
        ac.compile(ZeroAxis())
    with pytest.raises(ac.ModelError, match="not a nonzero 3-vector"):
        mb.RevolutePlanarLoopConstraint(n=(0.0, 0.0, 0.0))


class ShapePendulum(ac.Component):
    """A BodyShape on a revolute about z, its centre of mass off the bar (r_CM = (0.25,
    0.05, 0)), a point mass Body at its frame_b (r = (0.5, 0, 0)); released horizontal."""

    world = mb.World()
    joint = mb.Revolute(phi={"start": 0.0, "fixed": True}, w={"start": 0.0, "fixed": True})
    link = mb.BodyShape(r_1=0.5, m=2.0, r_CM_1=0.25, r_CM_2=0.05, I_33=0.05)
    tip = mb.Body(m=0.5, I_11=0.0, I_22=0.0, I_33=0.0)

    def equations(self):
        return [ac.connect(self.world.frame_b, self.joint.frame_a),
                ac.connect(self.joint.frame_b, self.link.frame_a),
                ac.connect(self.link.frame_b, self.tip.frame_a)]


def test_body_shape_carries_a_second_frame_and_an_offset_centre_of_mass():
    """I_o phi'' = -g (m d cos(phi + alpha) + m_tip L cos(phi)), d = |r_CM|, alpha its angle
    above the bar, I_o = I_33 + m d^2 + m_tip L^2 (the bar carries the tip's weight)."""
    t = np.linspace(0, 1.5, 151)
    res = ac.simulate(ShapePendulum(), t_end=1.5, rtol=1e-10, atol=1e-10, t_eval=t)
    d, alpha = np.hypot(0.25, 0.05), np.arctan2(0.05, 0.25)
    I_o = 0.05 + 2.0 * d**2 + 0.5 * 0.5**2
    ode = _ode(lambda _, s: [s[1], -G * (2.0 * d * np.cos(s[0] + alpha)
                                         + 0.5 * 0.5 * np.cos(s[0])) / I_o], [0.0, 0.0], t)
    assert np.max(np.abs(res["joint.phi"] - ode.y[0])) < 1e-7 * np.max(np.abs(ode.y[0]))
    # the tip rides at frame_b, L from the pivot
    tip = np.hypot(res["tip.frame_a.x"], res["tip.frame_a.y"])
    assert np.max(np.abs(tip - 0.5)) < 1e-9 * 0.5
