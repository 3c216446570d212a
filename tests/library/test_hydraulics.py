"""Hydraulics (Egeland & Gravdahl ch. 4, 11.2.10) against the book's formulas, closed
forms and scipy's solve_ivp on the hand-written equations."""
import numpy as np
import pytest
import scipy.linalg as sla
from scipy.integrate import solve_ivp

import acausal as ac
from acausal.library import hydraulics as hy
from acausal.library import rotational as rot
from acausal.library import translational as tr
from acausal.library.blocks import Constant, Feedback, Gain, Ramp
from acausal.library.hydraulics.examples import valve_motor as vm
from acausal.library.hydraulics.examples.cylinder import CylinderWithMass
from acausal.library.hydraulics.examples.hydrostatic import HydrostaticGear

RHO, NU, RE_TR, C_D = 900.0, 30e-6, 1000.0, 0.6


def _eigenvalues(compiled, z, t=0.0):
    """Finite eigenvalues of the model linearized at (t, z): F_z v + lambda F_z' v = 0.

    F_z and F_z' are the solver's Jacobian at cj = 0 and its cj-slope; columns are scaled
    by the nominal values and rows by their largest entry, as pressures (1e6) and flows
    (1e-4) would otherwise spoil the QZ algorithm."""
    zp = np.zeros(compiled.n)
    zp[compiled.state_index] = compiled.state_derivatives(t, z)
    J0 = compiled.jacobian(t, z, zp, 0.0).toarray()
    E = compiled.jacobian(t, z, zp, 1.0).toarray() - J0
    D = np.asarray(compiled.nominal, dtype=float)
    J0, E = J0 * D, E * D
    r = 1.0 / np.maximum(np.abs(J0).max(axis=1), np.abs(E).max(axis=1))
    w = sla.eig(-(J0 * r[:, None]), E * r[:, None], right=False)
    return w[np.isfinite(w)]


def _final_state(res):
    return np.array([res[n][-1] for n in res.compiled.names])


def _oscillatory_pair(w):
    lam = w[np.argmax(w.imag)]
    return abs(lam), -lam.real / abs(lam)


# -- orifice (4.2.3) -----------------------------------------------------------------------

class OrificeSweep(ac.Component):
    """An orifice of area 1 mm2 between a swept pressure and a tank: dp from -3 to 3 MPa."""

    sweep = Ramp(offset=-3e6, height=6e6, duration=1.0)
    source = hy.PressureSource()
    orifice = hy.TurbulentOrifice(A=1e-6)
    tank = hy.FixedPressure()

    def equations(self):
        return [ac.connect(self.sweep.y, self.source.p_ref),
                ac.connect(self.source.port, self.orifice.port_a),
                ac.connect(self.orifice.port_b, self.tank.port)]


def _ellman_piche(dp, D):
    """(4.9)-(4.10) in terms of the orifice diameter D, odd in dp."""
    A = np.pi * D**2 / 4
    p_tr = 9 * RE_TR**2 * RHO * NU**2 / (8 * C_D**2 * D**2)
    x = np.abs(dp) / p_tr
    laminar = 3 * NU * RE_TR / 4 * A / D * x * (3 - x)
    turbulent = C_D * A * np.sqrt(2 / RHO * np.abs(dp))
    return np.sign(dp) * np.where(x <= 1, laminar, turbulent), p_tr


def test_regularized_orifice_is_ellman_piche_4_9_in_area_form_4_13():
    t = np.linspace(0.0, 1.0, 241)
    res = ac.simulate(OrificeSweep(), t_end=1.0, t_eval=t)
    dp = res["orifice.dp"]
    expected, p_tr = _ellman_piche(dp, D=np.sqrt(4e-6 / np.pi))
    assert np.max(np.abs(res["orifice.q"] - expected)) < 1e-12 * np.max(np.abs(expected))
    # both regimes are swept; F_tr of (4.42) (no stray pi) is the transition force p_tr A
    assert np.sum(np.abs(dp) < p_tr) > 20 and np.sum(np.abs(dp) > p_tr) > 20
    assert abs(float(hy.F_tr(RE_TR, RHO, NU, C_D)) - p_tr * 1e-6) < 1e-12 * p_tr * 1e-6
    # the branches of (4.9) meet with equal value and slope at p_tr (C1), finite slope at 0
    h = 1e-3 * p_tr
    q = lambda x: _ellman_piche(np.array([x]), np.sqrt(4e-6 / np.pi))[0][0]
    assert abs(q(p_tr - 1e-9 * p_tr) - q(p_tr + 1e-9 * p_tr)) < 1e-8 * q(p_tr)
    left, right = (q(p_tr) - q(p_tr - h)) / h, (q(p_tr + h) - q(p_tr)) / h
    assert abs(left - right) < 2e-3 * left
    slope0 = 9 * NU * RE_TR / 4 * (1e-6 / np.sqrt(4e-6 / np.pi)) / p_tr
    assert abs((q(1.0) - q(-1.0)) / 2.0 - slope0) < 1e-6 * slope0


# -- volume, cylinder ----------------------------------------------------------------------

class FilledVolume(ac.Component):
    supply = hy.FixedPressure(p=1e7)
    orifice = hy.TurbulentOrifice(A=1e-6)
    volume = hy.Volume(V=1e-4, p={"start": 0.0, "fixed": True})

    def equations(self):
        return [ac.connect(self.supply.port, self.orifice.port_a),
                ac.connect(self.orifice.port_b, self.volume.port)]


def test_volume_filled_through_an_orifice_4_64():
    """(V/beta) p' = q(A, p_s - p), solved by solve_ivp with (4.9)."""
    t = np.linspace(0, 0.05, 51)
    res = ac.simulate(FilledVolume(), t_end=0.05, rtol=1e-9, t_eval=t)
    D = np.sqrt(4e-6 / np.pi)
    ref = solve_ivp(lambda _, p: 7e8 / 1e-4 * _ellman_piche(1e7 - p, D)[0], (0, 0.05), [0.0],
                    t_eval=t, rtol=1e-12, atol=1e-3, method="DOP853")
    assert np.max(np.abs(res["volume.p"] - ref.y[0])) < 1e-8 * 1e7
    assert res["volume.p"][-1] > 0.99e7


def _cylinder_rhs(t, y):
    """(4.83)-(4.85) by hand for CylinderWithMass: y = (p_a, p_b, x, v)."""
    p_a, p_b, x, v = y
    D = np.sqrt(4 * 2e-6 / np.pi)
    q_a = _ellman_piche(np.array([1e7 - p_a]), D)[0][0]
    q_b = _ellman_piche(np.array([p_b]), D)[0][0]
    return [7e8 / (2e-4 + 2e-3 * x) * (q_a - 2e-3 * v),
            7e8 / (3e-4 - 1.2e-3 * x) * (1.2e-3 * v - q_b),
            v, (2e-3 * p_a - 1.2e-3 * p_b - 2e5 * x - 50.0 * 9.81) / 50.0]


def test_cylinder_with_mass_load_4_83_to_4_85():
    t = np.linspace(0, CylinderWithMass.stop_time, 81)
    res = ac.simulate(CylinderWithMass(), t_end=t[-1], rtol=1e-9, t_eval=t)
    ref = solve_ivp(_cylinder_rhs, (0, t[-1]), [2e6, 2e6, 0.0, 0.0], t_eval=t, rtol=1e-10,
                    atol=[1.0, 1.0, 1e-10, 1e-9], method="LSODA")
    assert np.max(np.abs(res["load.s"] - ref.y[2])) < 1e-6 * np.max(np.abs(ref.y[2]))
    assert np.max(np.abs(res["cylinder.p_a"] - ref.y[0])) < 1e-5 * 1e7
    # the rod force is A_a p_a - A_b p_b  (4.85)
    force = 2e-3 * res["cylinder.p_a"] - 1.2e-3 * res["cylinder.p_b"]
    assert np.max(np.abs(-res["cylinder.flange.f"] - force)) < 1e-6


# -- valve-controlled motor (4.4.1-4.4.3) --------------------------------------------------

class OpenLoopValveMotor(ac.Component):
    """The example's valve and motor with the spool held at x_v = 1 mm."""

    supply = hy.FixedPressure(p=vm.P_S)
    tank = hy.FixedPressure(p=0.0)
    valve = hy.CriticalCentreValve(b=vm.B, rho=vm.RHO, C_d=vm.C_D)
    line_1 = hy.Volume(V=vm.V_0, beta=vm.BETA, p={"start": vm.P_S / 2, "fixed": True})
    line_2 = hy.Volume(V=vm.V_0, beta=vm.BETA, p={"start": vm.P_S / 2, "fixed": True})
    motor = hy.HydraulicMotor(D_m=vm.D_M, C_i=vm.C_IM)
    load = rot.Inertia(J=vm.J_T, w={"start": 0.0, "fixed": True})
    spool = Constant(k=1e-3)

    def equations(self):
        return [ac.connect(self.supply.port, self.valve.port_s),
                ac.connect(self.tank.port, self.valve.port_r),
                ac.connect(self.valve.port_1, self.line_1.port, self.motor.port_a),
                ac.connect(self.valve.port_2, self.line_2.port, self.motor.port_b),
                ac.connect(self.motor.flange, self.load.flange_a),
                ac.connect(self.spool.y, self.valve.x_v)]


def test_valve_motor_hydraulic_frequency_and_damping_4_101():
    """Linearized at its steady running point the motor has the pair of poles
    w_h^2 = 4 beta D_m^2/(V_t J_t), zeta_h = (K_ce/D_m) sqrt(beta J_t/V_t), with
    K_ce = K_c + C_tm and K_c of (4.36) at the operating point."""
    res = ac.simulate(OpenLoopValveMotor(), t_end=0.4, rtol=1e-9)
    z = _final_state(res)
    w_n, zeta = _oscillatory_pair(_eigenvalues(res.compiled, z, res.t[-1]))
    V_t, x_v = 2 * vm.V_0, 1e-3
    p_L = res["line_1.p"][-1] - res["line_2.p"][-1]
    K_c = vm.C_D * vm.B * x_v * np.sqrt((vm.P_S - p_L) / vm.RHO) / (2 * (vm.P_S - p_L))
    w_h = np.sqrt(4 * vm.BETA * vm.D_M**2 / (V_t * vm.J_T))
    zeta_h = (K_c + vm.C_IM) / vm.D_M * np.sqrt(vm.BETA * vm.J_T / V_t)
    assert abs(w_h - 400.0) < 1e-12 * 400.0
    assert abs(w_n - w_h) < 1e-6 * w_h
    assert abs(zeta - zeta_h) < 1e-6 * zeta_h
    # and the motor runs at the valve's load flow (4.31) over D_m
    q_L = vm.C_D * vm.B * x_v * np.sqrt((vm.P_S - p_L) / vm.RHO)
    assert abs(res["load.w"][-1] - (q_L - vm.C_IM * p_L) / vm.D_M) < 1e-6


def test_valve_controlled_motor_example_settles_at_the_reference():
    res = ac.simulate(vm.ValveControlledMotor(), t_end=vm.ValveControlledMotor.stop_time,
                      rtol=1e-6)
    assert res.success
    phi = res["load.phi"]
    assert abs(phi[-1] - 1.0) < 1e-3
    assert phi.max() < 1.0 + 1e-3     # K_v = zeta_h w_h: well damped, no overshoot


class OpenCentreServo(ac.Component):
    """P control of the motor through an open-centre valve (U = 1 mm), at rest at the
    reference: a linearization point where the valve is turbulent and K_q, K_c > 0."""

    supply = hy.FixedPressure(p=vm.P_S)
    tank = hy.FixedPressure(p=0.0)
    valve = hy.OpenCentreValve(b=vm.B, U=1e-3, rho=vm.RHO, C_d=vm.C_D)
    line_1 = hy.Volume(V=vm.V_0, beta=vm.BETA, p={"start": vm.P_S / 2, "fixed": True})
    line_2 = hy.Volume(V=vm.V_0, beta=vm.BETA, p={"start": vm.P_S / 2, "fixed": True})
    motor = hy.HydraulicMotor(D_m=vm.D_M, C_i=vm.C_IM)
    load = rot.Inertia(J=vm.J_T, phi={"start": 0.5, "fixed": True},
                       w={"start": 0.0, "fixed": True})
    angle = rot.AngleSensor()
    reference = Constant(k=0.5)
    error = Feedback()
    controller = Gain(k=1.0)

    def equations(self):
        return [ac.connect(self.supply.port, self.valve.port_s),
                ac.connect(self.tank.port, self.valve.port_r),
                ac.connect(self.valve.port_1, self.line_1.port, self.motor.port_a),
                ac.connect(self.valve.port_2, self.line_2.port, self.motor.port_b),
                ac.connect(self.motor.flange, self.load.flange_a, self.angle.flange),
                ac.connect(self.reference.y, self.error.u1),
                ac.connect(self.angle.phi, self.error.u2),
                ac.connect(self.error.y, self.controller.u),
                ac.connect(self.controller.y, self.valve.x_v)]


@pytest.mark.parametrize("fraction", [0.5, 1.5])
def test_p_controlled_motor_poles_and_stability_limit_4_107_to_4_112(fraction):
    """Closed loop 1 + K_v/(s (1 + 2 zeta_h s/w_h + s^2/w_h^2)) = 0 (4.107), stable iff
    K_v < 2 zeta_h w_h (4.112); K_q = 2 C_d b sqrt(p_s/rho), K_c = C_d b U/sqrt(p_s rho)."""
    V_t, U = 2 * vm.V_0, 1e-3
    K_q = 2 * vm.C_D * vm.B * np.sqrt(vm.P_S / vm.RHO)
    K_c = vm.C_D * vm.B * U / np.sqrt(vm.P_S * vm.RHO)
    w_h = np.sqrt(4 * vm.BETA * vm.D_M**2 / (V_t * vm.J_T))
    zeta_h = (K_c + vm.C_IM) / vm.D_M * np.sqrt(vm.BETA * vm.J_T / V_t)
    K_v = fraction * 2 * zeta_h * w_h
    compiled = ac.compile(OpenCentreServo(controller={"k": K_v * vm.D_M / K_q}))
    w = _eigenvalues(compiled, ac.initial_values(compiled))
    expected = np.roots([1.0, 2 * zeta_h * w_h, w_h**2, K_v * w_h**2])
    for lam in expected:
        assert np.min(np.abs(w - lam)) < 1e-6 * w_h
    assert (np.max(expected.real) < 0) == (fraction < 1)


# -- pump-controlled motor (4.4.5) ---------------------------------------------------------

def _hydrostatic_rhs(t, y, beta=7e8, V0=5e-4, D=1e-5, C_t=1.5e-11, J=0.05):
    p, w = y
    return [beta / V0 * (D * 150.0 * 0.6 - D * w - C_t * p), (D * p - 20.0) / J]


def test_hydrostatic_gear_4_122():
    t = np.linspace(0, HydrostaticGear.stop_time, 101)
    res = ac.simulate(HydrostaticGear(), t_end=t[-1], rtol=1e-9, t_eval=t)
    ref = solve_ivp(_hydrostatic_rhs, (0, t[-1]), [0.0, 0.0], t_eval=t, rtol=1e-11,
                    atol=[1e-3, 1e-9])
    assert np.max(np.abs(res["load.w"] - ref.y[1])) < 1e-6 * 87.0
    w_n, zeta = _oscillatory_pair(_eigenvalues(res.compiled, _final_state(res)))
    w_h = np.sqrt(7e8 * 1e-10 / (5e-4 * 0.05))
    zeta_h = 1.5e-11 / (2 * 1e-5) * np.sqrt(7e8 * 0.05 / 5e-4)
    assert abs(w_n - w_h) < 1e-6 * w_h and abs(zeta - zeta_h) < 1e-6 * zeta_h


# -- valves (4.2.4-4.2.9) -------------------------------------------------------------------

class ValveWithSymmetricLoad(ac.Component):
    """Matched critical-centre valve with p_1, p_2 = (p_s +- p_L)/2 imposed (4.28), p_L
    swept from -2/3 p_s to 2/3 p_s."""

    supply = hy.FixedPressure(p=1e7)
    tank = hy.FixedPressure(p=0.0)
    sweep_1 = Ramp(offset=1e7 / 6, height=1e7 * 2 / 3, duration=1.0)
    sweep_2 = Ramp(offset=1e7 * 5 / 6, height=-1e7 * 2 / 3, duration=1.0)
    side_1 = hy.PressureSource()
    side_2 = hy.PressureSource()
    valve = hy.CriticalCentreValve(b=1e-3)

    def __init__(self, x_v=2e-3, **mods):
        super().__init__(**mods)
        self.spool = Constant(k=x_v)

    def equations(self):
        return [ac.connect(self.supply.port, self.valve.port_s),
                ac.connect(self.tank.port, self.valve.port_r),
                ac.connect(self.sweep_1.y, self.side_1.p_ref),
                ac.connect(self.sweep_2.y, self.side_2.p_ref),
                ac.connect(self.side_1.port, self.valve.port_1),
                ac.connect(self.side_2.port, self.valve.port_2),
                ac.connect(self.spool.y, self.valve.x_v)]


@pytest.mark.parametrize("x_v", [2e-3, -2e-3])
def test_matched_valve_load_flow_4_31_and_flow_gain_bounds_4_39(x_v):
    """q_L = C_d b x_v sqrt((p_s - sgn(x_v) p_L)/rho), both load flows equal (4.23);
    for |p_L| <= 2/3 p_s the flow gain stays within 0.577 and 1.29 of K_q0 (4.39).
    (x_v = 2 mm keeps every open orifice turbulent, A dp >= F_tr, down to dp = p_s/6.)"""
    t = np.linspace(0, 1, 41)
    res = ac.simulate(ValveWithSymmetricLoad(x_v=x_v), t_end=1.0, t_eval=t)
    p_s, p_L = 1e7, res["side_1.port.p"] - res["side_2.port.p"]
    q_L = C_D * 1e-3 * x_v * np.sqrt((p_s - np.sign(x_v) * p_L) / RHO)      # (4.31)
    assert np.max(np.abs(res["valve.q_1"] - q_L)) < 1e-12 * np.max(np.abs(q_L))
    assert np.max(np.abs(res["valve.q_2"] - q_L)) < 1e-12 * np.max(np.abs(q_L))
    gain = res["valve.q_1"] / (x_v * C_D * 1e-3 * np.sqrt(p_s / RHO))
    assert abs(gain.min() - np.sqrt(1 / 3)) < 1e-9 and abs(gain.max() - np.sqrt(5 / 3)) < 1e-9
    # continuity: what the supply delivers returns to the tank, or stays in the load
    # (sums of flows that cancel: to rounding of the flows' size)
    flow = np.max(np.abs(res["valve.port_s.q"]))
    assert np.allclose(res["valve.port_s.q"] + res["valve.port_r.q"],
                       res["valve.q_1"] - res["valve.q_2"], rtol=0, atol=1e-12 * flow)


class CompensatedValveRig(ac.Component):
    inlet = hy.PressureSource()
    sweep = Ramp(offset=3e6, height=7e6, duration=1.0)
    valve = hy.PressureCompensatedValve(K_c=200.0, F_c0=50.0, A_c=1e-4, b=0.01, b_c=0.01,
                                        p_c={"start": 1.4995e6}, x_c={"start": 5e-4})
    outlet = hy.FixedPressure(p=1e6)
    spool = Constant(k=1e-3)

    def equations(self):
        return [ac.connect(self.sweep.y, self.inlet.p_ref),
                ac.connect(self.inlet.port, self.valve.port_a),
                ac.connect(self.valve.port_b, self.outlet.port),
                ac.connect(self.spool.y, self.valve.x_v)]


def test_pressure_compensated_valve_flow_4_57():
    """The compensator keeps p_c - p_2 = (F_c0 - K_c x_c)/A_c, so q stays near
    C_d sqrt(2 F_c0/(rho A_c)) b x_v (4.57) while p_1 - p_2 rises from 20 to 90 bar
    (K_c x_c <= 0.2 N against F_c0 = 50 N; both orifices turbulent)."""
    t = np.linspace(0, 1, 21)
    res = ac.simulate(CompensatedValveRig(), t_end=1.0, t_eval=t)
    q = res["valve.q"]
    held = (50.0 - 200.0 * res["valve.x_c"]) / 1e-4
    assert np.allclose(res["valve.p_c"] - 1e6, held, rtol=1e-9)
    q_457 = C_D * np.sqrt(2 * 50.0 / (RHO * 1e-4)) * 0.01 * 1e-3
    assert np.max(np.abs(q / q_457 - 1)) < 0.01
    assert np.ptp(q) < 0.01 * q_457


class ReliefRig(ac.Component):
    pump = hy.ConstantFlow(q0=2e-4)
    volume = hy.Volume(V=1e-3, p={"start": 0.0, "fixed": True})
    relief = hy.ReliefValve(p_crack=1e7, G_open=1e-10, G_closed=1e-14)
    tank = hy.FixedPressure()

    def equations(self):
        return [ac.connect(self.pump.port, self.volume.port, self.relief.port_a),
                ac.connect(self.relief.port_b, self.tank.port)]


def test_relief_valve_limits_the_pressure():
    """Closed: (V/beta) p' = q - G_closed p;
    open: p -> (q + G_open p_crack) / (G_open + G_closed)."""
    res = ac.simulate(ReliefRig(), t_end=0.5, rtol=1e-9)
    t, p = res.t, res["volume.p"]
    k = 7e8 / 1e-3
    t_crack = -np.log(1 - 1e7 * 1e-14 / 2e-4) / (k * 1e-14)
    early = t < t_crack
    closed = 2e-4 / 1e-14 * (1 - np.exp(-k * 1e-14 * t[early]))
    assert np.max(np.abs(p[early] - closed)) < 1e-7 * 1e7
    assert np.min(np.abs(np.array(res.events) - t_crack)) < 1e-8
    p_inf = (2e-4 + 1e-10 * 1e7) / (1e-10 + 1e-14)
    assert abs(p[-1] - p_inf) < 1e-6 * p_inf


class PistonOnSpring(ac.Component):
    """A chamber filled through an orifice pushes a mass against a spring."""

    supply = hy.FixedPressure(p=5e6)
    orifice = hy.TurbulentOrifice(A=1e-6)
    housing = tr.Fixed()
    spring = tr.Spring(c=1e5)
    mass = tr.Mass(m=5.0, s={"start": 0.0, "fixed": True}, v={"start": 0.0, "fixed": True})

    def equations(self):
        return [ac.connect(self.supply.port, self.orifice.port_a),
                ac.connect(self.housing.flange, self.spring.flange_a),
                ac.connect(self.spring.flange_b, self.mass.flange_b)]


class WithPistonVolume(PistonOnSpring):
    chamber = hy.PistonVolume(V0=1e-4, A=1e-3, p={"start": 1e5, "fixed": True})

    def equations(self):
        return [ac.connect(self.orifice.port_b, self.chamber.port),
                ac.connect(self.chamber.flange, self.mass.flange_a)]


class WithSingleActingCylinder(PistonOnSpring):
    chamber = hy.SingleActingCylinder(V_0=1e-4, A=1e-3, p={"start": 1e5, "fixed": True})

    def equations(self):
        return [ac.connect(self.orifice.port_b, self.chamber.port),
                ac.connect(self.chamber.flange, self.mass.flange_a)]


def test_piston_volume_and_single_acting_cylinder_agree_4_64():
    """Two formulations of (4.64) with a moving boundary."""
    t = np.linspace(0, 0.5, 51)
    a = ac.simulate(WithPistonVolume(), t_end=0.5, rtol=1e-10, t_eval=t)
    b = ac.simulate(WithSingleActingCylinder(), t_end=0.5, rtol=1e-10, t_eval=t)
    assert np.max(np.abs(a["mass.s"] - b["mass.s"])) < 1e-8 * np.max(a["mass.s"])
    assert np.max(np.abs(a["chamber.p"] - b["chamber.p"])) < 1e-8 * 5e6
    # the chamber pushes the mass with p A
    assert np.max(np.abs(-a["chamber.flange.f"] - 1e-3 * a["chamber.p"])) < 1e-9 * 5e3


class BalanceValveRig(ac.Component):
    """A load at 100 bar held by a balance valve (preload 600 N) against a tank at 0 bar;
    the pilot pressure sweeps 0 -> 60 bar and opens it."""

    load = hy.FixedPressure(p=1e7)
    tank = hy.FixedPressure(p=0.0)
    pilot = hy.PressureSource()
    sweep = Ramp(height=6e6, duration=1.0)
    valve = hy.BalanceValve(A=2e-4, A_p=1.5e-4, K=1e5, F_0=600.0, x_v_max=2e-3, b=0.01)

    def equations(self):
        return [ac.connect(self.load.port, self.valve.port_a),
                ac.connect(self.valve.port_b, self.tank.port),
                ac.connect(self.sweep.y, self.pilot.p_ref),
                ac.connect(self.pilot.port, self.valve.port_p)]


def _balance_opening(t):
    A_r, R = 0.5e-4, 3.0
    return np.clip((A_r * (1e7 + R * 6e6 * t) - 600.0) / 1e5, 0.0, 2e-3)


def test_balance_valve_opening_4_59():
    """x_v = ((A - A_p)(p_1 - p_0 + R p_p - p_2 (R + 1)) - F_0)/K, clipped to the stroke;
    closed (q = 0) until the pilot pressure opens it, no pilot flow."""
    t = np.linspace(0, 1, 101)
    res = ac.simulate(BalanceValveRig(), t_end=1.0, t_eval=t)
    x_v = _balance_opening(t)
    # x_v = (forces - F_0)/K cancels near the opening: to rounding of the stroke 2 mm
    assert np.allclose(res["valve.x_v"], x_v, rtol=1e-12, atol=1e-12 * 2e-3)
    # exact zeros: a closed valve's area b x_v is 0 and every flow law multiplies it, and
    # the pilot port's flow is the constant 0 of its equation
    assert np.all(res["valve.q"][x_v == 0] == 0.0) and np.sum(x_v == 0) > 5
    assert res["pilot.port.q"].max() == 0.0 == res["pilot.port.q"].min()


def test_balance_valve_flow_4_60():
    t = np.linspace(0, 1, 101)
    res = ac.simulate(BalanceValveRig(), t_end=1.0, t_eval=t)
    D = np.sqrt(4 * 0.01 * _balance_opening(t) / np.pi)
    q = np.array([_ellman_piche(np.array([1e7]), d)[0][0] if d > 0 else 0.0 for d in D])
    # closed, both are exactly 0; open, relative (atol: rounding of the largest flow)
    assert np.allclose(res["valve.q"], q, rtol=1e-12, atol=1e-12 * np.max(q))


class PumpRig(ac.Component):
    drive = rot.ConstantSpeed(w_fixed=100.0)
    pump = hy.Pump(D_p=2e-6, C_i=1e-12)
    tank = hy.FixedPressure(p=0.0)
    load = hy.LaminarOrifice(C_l=1e-11)
    outlet = hy.Volume(V=1e-6, p={"start": 0.0, "fixed": True})
    torque = rot.TorqueSensor()

    def equations(self):
        return [ac.connect(self.drive.flange, self.torque.flange_a),
                ac.connect(self.torque.flange_b, self.pump.flange),
                ac.connect(self.tank.port, self.pump.port_a, self.load.port_b),
                ac.connect(self.pump.port_b, self.load.port_a, self.outlet.port)]


def test_fixed_pump_delivery_and_drive_torque():
    """(V/beta) p' = D_p w - (C_l + C_i) p: p -> D_p w/(C_l + C_i) with the time constant
    V/(beta (C_l + C_i)) = 0.13 s; the drive supplies T = D_p p."""
    res = ac.simulate(PumpRig(), t_end=3.0, rtol=1e-10)
    assert res.success
    p = 2e-6 * 100.0 / (1e-11 + 1e-12)
    tau = 1e-6 / (7e8 * 1.1e-11)
    assert abs(res.at("outlet.p", 0.2) - p * (1 - np.exp(-0.2 / tau))) < 1e-7 * p
    assert abs(res["pump.port_b.p"][-1] - p) < 1e-9 * p
    assert abs(res["torque.tau.signal"][-1] - 2e-6 * p) < 1e-9 * 2e-6 * p
    assert abs(res["load.q"][-1] - 1e-11 * p) < 1e-9 * 2e-4


class PumpControlledServo(ac.Component):
    """The hydrostatic gear with P control of the motor angle, phi_p = K_p (theta_d - theta),
    at rest at the reference."""

    tank = hy.FixedPressure(p=0.0)
    drive = rot.ConstantSpeed(w_fixed=150.0)
    pump = hy.VariablePump(D_max=1e-5, C_i=7.5e-12)
    line = hy.Volume(V=5e-4, p={"start": 0.0, "fixed": True})
    motor = hy.HydraulicMotor(D_m=1e-5, C_i=7.5e-12)
    load = rot.Inertia(J=0.05, phi={"start": 0.3, "fixed": True}, w={"start": 0.0, "fixed": True})
    angle = rot.AngleSensor()
    reference = Constant(k=0.3)
    error = Feedback()
    controller = Gain(k=1.0)

    def equations(self):
        return [ac.connect(self.drive.flange, self.pump.flange),
                ac.connect(self.tank.port, self.pump.port_a, self.motor.port_b),
                ac.connect(self.pump.port_b, self.line.port, self.motor.port_a),
                ac.connect(self.motor.flange, self.load.flange_a, self.angle.flange),
                ac.connect(self.reference.y, self.error.u1),
                ac.connect(self.angle.phi, self.error.u2),
                ac.connect(self.error.y, self.controller.u),
                ac.connect(self.controller.y, self.pump.phi_p)]


@pytest.mark.parametrize("fraction", [0.5, 1.5])
def test_pump_controlled_motor_stability_limit_4_125(fraction):
    """Loop K_v/(s (1 + 2 zeta_h s/w_h + s^2/w_h^2)) with (4.122); stable iff
    K_v <= 2 zeta_h w_h = w_0 = beta C_t / V_0 (4.125)."""
    w_h = np.sqrt(7e8 * 1e-10 / (5e-4 * 0.05))
    zeta_h = 1.5e-11 / (2 * 1e-5) * np.sqrt(7e8 * 0.05 / 5e-4)
    w_0 = 7e8 * 1.5e-11 / 5e-4
    assert abs(2 * zeta_h * w_h - w_0) < 1e-12 * w_0
    K_v = fraction * w_0
    compiled = ac.compile(PumpControlledServo(controller={"k": K_v * 1e-5 / (1e-5 * 150.0)}))
    w = _eigenvalues(compiled, ac.initial_values(compiled))
    expected = np.roots([1.0, 2 * zeta_h * w_h, w_h**2, K_v * w_h**2])
    for lam in expected:
        assert np.min(np.abs(w - lam)) < 1e-6 * w_h
    assert (np.max(expected.real) < 0) == (fraction < 1)
