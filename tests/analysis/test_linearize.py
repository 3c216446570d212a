"""Linearization of compiled models against the closed forms of Egeland & Gravdahl."""
import numpy as np
import pytest
import scipy.linalg as sla

import acausal as ac
from acausal.analysis import linearize, steady_state
from acausal.library.electrical import ConstantVoltage, Ground, SignalVoltage
from acausal.library.electromechanical import DCMotor
from acausal.library.electromechanical.examples.elastic_transmission import ElasticTransmission
from acausal.library.rotational import Damper, Fixed, IdealGear, Inertia
from acausal.library.rotational.interfaces import PartialCompliant
from acausal.ports import RealInput
from acausal.solvers import integrate

R, L, K, J = 1.5, 2e-3, 0.06, 2e-4          # T_a = 1.33 ms, T_m = 83 ms


class VoltageDrivenMotor(ac.Component):
    """DC motor (3.29)-(3.31) on a voltage u_a given as a top-level input."""

    u_a = RealInput()
    amplifier = SignalVoltage()
    ground = Ground()
    motor = DCMotor(R=R, L=L, k=K, J=J)

    def equations(self):
        return [ac.connect(self.u_a, self.amplifier.v),
                ac.connect(self.amplifier.p, self.motor.p),
                ac.connect(self.amplifier.n, self.motor.n, self.ground.p)]


class MotorWithFriction(ac.Component):
    """DC motor on a constant voltage against viscous friction T_L = B w_m."""

    source = ConstantVoltage(V=12.0)
    ground = Ground()
    motor = DCMotor(R=R, L=L, k=K, J=J)
    friction = Damper(d=3e-4)
    housing = Fixed()

    def equations(self):
        return [ac.connect(self.source.p, self.motor.p),
                ac.connect(self.source.n, self.motor.n, self.ground.p),
                ac.connect(self.motor.flange, self.friction.flange_a),
                ac.connect(self.friction.flange_b, self.housing.flange)]


def _rel(a, b):
    a, b = np.sort_complex(np.asarray(a)), np.sort_complex(np.asarray(b))
    return np.max(np.abs(a - b) / np.abs(b))


def test_dc_motor_speed_poles_are_those_of_2_31():
    sys = linearize(VoltageDrivenMotor(), ["u_a"], ["motor.rotor.w"])
    assert set(sys.states) == {"motor.La.i", "motor.emf.flange.phi", "motor.rotor.w"}
    T_a, T_m = L / R, J * R / K**2                                   # (3.49), (3.50)
    speed = sys.minimal()
    assert speed.n_states == 2                                       # the angle is unobservable
    assert _rel(speed.poles(), np.roots([T_a * T_m, T_m, 1.0])) < 1e-9
    num, den = sys.tf()
    assert num[-1] / den[-1] == pytest.approx(1.0 / K, rel=1e-9)     # H(0) = 1/K  (2.31)


def test_dc_motor_angle_transfer_function_3_48():
    sys = linearize(VoltageDrivenMotor(), ["u_a"], ["motor.flange.phi"])
    T_a, T_m = L / R, J * R / K**2
    num, den = sys.tf()
    # theta_m/u_a = (1/K_E) / (s (T_a T_m s^2 + T_m s + 1)), monic denominator
    assert np.allclose(den, np.array([1.0, 1 / T_a, 1 / (T_a * T_m), 0.0]), rtol=1e-9, atol=0)
    assert num == pytest.approx([1.0 / (K * T_a * T_m)], rel=1e-9)


def test_dc_motor_with_viscous_friction_poles():
    """T_L = B w_m in (3.46): (L_a s + R_a)(J_m s + B) + K_E K_T = 0; the input is the
    source's voltage parameter."""
    sys = linearize(MotorWithFriction(), ["source.V"], ["motor.rotor.w"])
    B = 3e-4
    exact = np.roots(np.polyadd(np.polymul([L, R], [J, B]), [K * K]))
    assert _rel(sys.minimal().poles(), exact) < 1e-9
    assert sys.dcgain()[0, 0] == pytest.approx(K / (R * B + K * K), rel=1e-9)


def test_linearization_is_independent_of_the_operating_point_of_a_linear_model():
    res = ac.simulate(MotorWithFriction(), t_end=0.05, rtol=1e-8)
    a = linearize(res.compiled, ["source.V"], ["motor.La.i"], at=(res, 0.03))
    b = linearize(res.compiled, ["source.V"], ["motor.La.i"], at={"motor.rotor.w": 50.0})
    assert np.allclose(a.A, b.A, rtol=1e-12) and np.allclose(a.B, b.B, rtol=1e-8)
    assert a.D[0, 0] == pytest.approx(0.0, abs=1e-9 / R)    # no feedthrough, on 1/R's scale


def test_elastic_load_undamped_zeros_and_poles():
    """Egeland & Gravdahl (3.85)-(3.88): zeros at +-j w_a, poles at 0 and +-j w_1."""
    J_m, J_L, c = 1.0, 3.0, 0.5
    model = ElasticTransmission(motor={"J": J_m}, load={"J": J_L}, shaft={"c": c, "d": 0.0})
    sys = linearize(model, ["drive.tau.signal"], ["motor.w"])   # driven by a Step block
    J_e = J_m * J_L / (J_m + J_L)
    w_1, w_a = np.sqrt(c / J_e), np.sqrt(J_m / (J_m + J_L)) * np.sqrt(c / J_e)
    assert _rel(sys.zeros(), [-1j * w_a, 1j * w_a]) < 1e-9
    poles = sys.minimal().poles()
    assert _rel(poles[np.abs(poles) > 1e-9], [-1j * w_1, 1j * w_1]) < 1e-9
    assert np.sum(np.abs(poles) < 1e-9) == 1                       # 1/(J s)


def test_elastic_load_damped_zero_damping_ratio():
    J_m, J_L, c, d = 1.0, 3.0, 0.5, 0.05
    model = ElasticTransmission(motor={"J": J_m}, load={"J": J_L}, shaft={"c": c, "d": d})
    sys = linearize(model, ["drive.tau.signal"], ["motor.w"])
    J_e = J_m * J_L / (J_m + J_L)
    zeta_1 = d / (2 * np.sqrt(J_e * c))                              # (3.87)
    z = sys.zeros()
    zeta_a = -z.real / np.abs(z)
    assert zeta_a == pytest.approx(np.full(2, np.sqrt(J_m / (J_m + J_L)) * zeta_1), rel=1e-9)
    p = sys.minimal().poles()
    p = p[np.abs(p) > 1e-9]
    assert -p.real / np.abs(p) == pytest.approx(np.full(2, zeta_1), rel=1e-9)


class CubicDamper(PartialCompliant):
    """tau = d w_rel^3 (a smooth nonlinear friction, for the finite-difference check)."""

    d = ac.Parameter(1e-3)

    def equations(self):
        return [ac.Eq(self.tau, self.d * ac.der(self.phi_rel) ** 3)]


class GearedMotor(ac.Component):
    """Motor, ideal gear (index 3: dummy derivatives) and a load with cubic friction."""

    u_a = RealInput()
    amplifier = SignalVoltage()
    ground = Ground()
    motor = DCMotor(R=R, L=L, k=K, J=J)
    gear = IdealGear(ratio=5.0)
    load = Inertia(J=4e-3)
    friction = CubicDamper(d=2e-5)
    housing = Fixed()

    def equations(self):
        return [ac.connect(self.u_a, self.amplifier.v),
                ac.connect(self.amplifier.p, self.motor.p),
                ac.connect(self.amplifier.n, self.motor.n, self.ground.p),
                ac.connect(self.motor.flange, self.gear.flange_a),
                ac.connect(self.gear.flange_b, self.load.flange_a),
                ac.connect(self.load.flange_b, self.friction.flange_a),
                ac.connect(self.friction.flange_b, self.housing.flange)]


def test_agrees_with_finite_differences_of_the_simulation():
    """e^{A T} and int_0^T e^{A s} ds B against central differences of the solver's flow."""
    op = steady_state(GearedMotor(), inputs={"u_a": 12.0}, hold=["motor.emf.flange.phi"])
    sys = linearize(op.compiled, ["u_a"], ["load.w"], at=op)
    c, T, n = op.compiled, 2e-3, sys.n_states
    k_u = c.param_names.index("input0.k")

    def flow(z0):
        zp0 = np.zeros(c.n)
        zp0[c.state_index] = c.state_derivatives(0.0, z0)
        out = integrate(c, (0.0, T), z0, zp0, rtol=1e-11, atol=1e-12, t_eval=[T])
        return out.y[-1][c.state_index]

    from acausal.analysis.operating import make_consistent
    Phi = np.empty((n, n))
    for j in range(n):
        h = 1e-4 * max(1.0, abs(op.z[c.state_index[j]]))
        zp, zm = op.z.copy(), op.z.copy()
        zp[c.state_index[j]] += h
        zm[c.state_index[j]] -= h
        ahead, behind = flow(make_consistent(c, 0.0, zp)), flow(make_consistent(c, 0.0, zm))
        Phi[:, j] = (ahead - behind) / (2 * h)
    assert np.allclose(Phi, sla.expm(sys.A * T), rtol=1e-5, atol=1e-6)
    u0 = c.p[k_u]
    c.p[k_u] = u0 + 1e-3
    up = flow(make_consistent(c, 0.0, op.z))
    c.p[k_u] = u0 - 1e-3
    um = flow(make_consistent(c, 0.0, op.z))
    c.p[k_u] = u0
    M = np.zeros((n + 1, n + 1))
    M[:n, :n], M[:n, n:] = sys.A, sys.B
    assert np.allclose((up - um) / 2e-3, sla.expm(M * T)[:n, n], rtol=1e-5, atol=1e-7)


# -- valve-controlled hydraulic motor (Egeland & Gravdahl 4.4.1-4.4.3) -----------------------
def _book_loop(K_v, w_h=400.0, zeta_h=0.1):
    """L(s) = K_v / (s (1 + 2 zeta_h s/w_h + s^2/w_h^2))  (4.107)."""
    from acausal.analysis import StateSpace
    return StateSpace.from_tf([K_v], [1 / w_h**2, 2 * zeta_h / w_h, 1.0, 0.0])


def test_hydraulic_loop_gain_margin_is_6_dB_at_K_v_40():
    m = _book_loop(40.0).margins()
    assert m.w_180 == pytest.approx(400.0, rel=1e-9)                 # w_180 = w_h  (4.109)
    assert m.gain == pytest.approx(2.0, rel=1e-9)                    # |L(j w_h)| = 1/2
    assert m.gain_db == pytest.approx(6.0206, abs=1e-4)


def test_hydraulic_closed_loop_stable_exactly_below_2_zeta_w():
    limit = 2 * 0.1 * 400.0                                          # (4.112)
    assert _book_loop(0.999 * limit).feedback().is_stable()
    assert not _book_loop(1.001 * limit).feedback().is_stable()
    p = _book_loop(limit).feedback().poles()
    assert np.min(np.abs(p.real)) < 1e-6 * 400 and np.max(np.abs(p.imag)) == pytest.approx(400)


def test_valve_controlled_motor_from_the_library():
    hyd = pytest.importorskip("acausal.library.hydraulics")
    if not hasattr(hyd, "CriticalCentreValve"):
        pytest.skip("the hydraulics library has no CriticalCentreValve")
    from acausal.library.hydraulics.examples import valve_motor as vm

    class OpenLoop(ac.Component):
        x_v = RealInput()
        supply = hyd.FixedPressure(p=vm.P_S)
        tank = hyd.FixedPressure(p=0.0)
        valve = hyd.CriticalCentreValve(b=vm.B, rho=vm.RHO, C_d=vm.C_D)
        line_1 = hyd.Volume(V=vm.V_0, beta=vm.BETA, p={"start": vm.P_S / 2})
        line_2 = hyd.Volume(V=vm.V_0, beta=vm.BETA, p={"start": vm.P_S / 2})
        motor = hyd.HydraulicMotor(D_m=vm.D_M, C_i=vm.C_IM)
        load = Inertia(J=vm.J_T)

        def equations(self):
            return [ac.connect(self.supply.port, self.valve.port_s),
                    ac.connect(self.tank.port, self.valve.port_r),
                    ac.connect(self.valve.port_1, self.line_1.port, self.motor.port_a),
                    ac.connect(self.valve.port_2, self.line_2.port, self.motor.port_b),
                    ac.connect(self.motor.flange, self.load.flange_a),
                    ac.connect(self.x_v, self.valve.x_v)]

    # in the turbulent range of the orifices (at x_v = 0 the regularized law's laminar
    # branch has zero flow gain), moving at the speed the flow gives, p_L = 0
    x_v, p_s = 5e-4, vm.P_S
    K_q = vm.C_D * vm.B * np.sqrt(p_s / vm.RHO)                      # (4.34), p_L = 0
    K_c = K_q * x_v / (2 * p_s)
    plant = linearize(OpenLoop(), ["x_v"], ["load.phi"],
                      at={"x_v": x_v, "line_1.p": p_s / 2, "line_2.p": p_s / 2,
                          "load.w": K_q * x_v / vm.D_M})
    V_t = 2 * vm.V_0
    w_h = np.sqrt(4 * vm.BETA * vm.D_M**2 / (V_t * vm.J_T))          # (4.101)
    zeta_h = (K_c + vm.C_IM) / vm.D_M * np.sqrt(vm.BETA * vm.J_T / V_t)
    from acausal.analysis import StateSpace
    book = StateSpace.from_tf([K_q / vm.D_M], [1 / w_h**2, 2 * zeta_h / w_h, 1.0, 0.0])
    w = np.logspace(0, 4, 9)
    assert np.allclose(plant.freqresp(w), book.freqresp(w), rtol=1e-9, atol=0)  # (4.103)
    assert plant.minimal().n_states == 3                             # p_1 + p_2 decouples
    loop = StateSpace(plant.A, plant.B * vm.K_P, plant.C, plant.D)
    margins = loop.margins()                                         # x_v = K_p e  (4.106)
    assert margins.w_180 == pytest.approx(w_h, rel=1e-9)             # (4.109)
    K_v = vm.K_P * K_q / vm.D_M
    assert 1 / margins.gain == pytest.approx(K_v / (2 * zeta_h * w_h), rel=1e-9)


def test_cartesian_pendulum_index_3_small_oscillations():
    """The index-3 pendulum (dynamic state selection) at its lower equilibrium: the
    linearization in the selected states has poles +-j sqrt(g/L)."""
    from acausal.library.examples.pendulum import Pendulum
    op = steady_state(Pendulum(L=2.0))
    assert op["y"] == pytest.approx(-2.0, rel=1e-12)
    sys = linearize(op.compiled, [], ["x"], at=op)
    assert _rel(sys.poles(), [-1j * np.sqrt(9.81 / 2.0), 1j * np.sqrt(9.81 / 2.0)]) < 1e-9
