"""Valve-controlled cylinder servo whose spool starts exactly at x_v = 0.

A matched, symmetric critical-centre valve (Egeland & Gravdahl (4.18)-(4.20)) feeds a
symmetric double-acting cylinder (4.83)-(4.85) carrying a 10 kg mass; supply 100 bar,
tank 0, the book's oil (rho = 900 kg/m3, nu = 30 cSt, C_d = 0.6, (4.13) with F_tr of
(4.42)).  A P controller drives the spool directly, x_v = K_p (x_d - x), and the set
point steps by 20 mm at t_s = 10 ms; before the step the spool sits at exactly 0.

Parameters: A = 1e-3 m2, V_0 = 1e-4 m3 per chamber, beta = 7e8 Pa, port width b = 10 mm,
so K_q0 = C_d b sqrt(p_s/rho) = 0.632 m2/s (4.37) at p_a = p_b = p_s/2.  K_p is chosen
for a loop gain K_v = K_p K_q0 / A = 20 1/s, far below the hydraulic frequency
w_h = sqrt(4 beta A^2/(V_t m)) = 1183 rad/s; an internal leakage C_i gives zeta_h = 0.3
(zeta_h = (C_i/A) sqrt(beta m / V_t), (4.101) with D_m -> A, J_t -> m).

References, none of which goes through acausal:

* the first-order estimate of the loop, A x' = K_q0 x_v: x = x_d (1 - exp(-K_v (t-t_s)))
  while the spool is open enough for turbulent flow (within a few % of the step);
* the same hydraulic equations written by hand and integrated by scipy (LSODA,
  rtol 1e-11), valve law (4.13) included;
* the mass balance of each chamber, V/beta dp/dt = q - A v - C_i (p_a - p_b), with dp/dt
  the finite-difference slope of the integrated pressure and q the valve's reported flow.
"""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal as ac
from acausal.library import translational as tr
from acausal.library.blocks import Feedback, Gain, Step
from acausal.library.hydraulics.components import Cylinder
from acausal.library.hydraulics.sources import FixedPressure
from acausal.library.hydraulics.valves import CriticalCentreValve

P_S, A, V0, M, BETA, B = 1e7, 1e-3, 1e-4, 10.0, 7e8, 0.01
RHO, NU, C_D, RE_TR = 900.0, 30e-6, 0.6, 1000.0
K_Q0 = C_D * B * np.sqrt(P_S / RHO)
K_V = 20.0
K_P = K_V * A / K_Q0
C_I = 0.3 * A / np.sqrt(BETA * M / (2 * V0))
X_D, T_S, T_END = 0.02, 0.01, 0.3
F_TR = 9 * RE_TR**2 * RHO * NU**2 / (8 * C_D**2) * np.pi / 4      # (4.42)


class CylinderServo(ac.Component):
    """P position control of a mass on a valve-fed cylinder; the spool starts centred."""

    supply = FixedPressure(p=P_S)
    tank = FixedPressure(p=0.0)
    valve = CriticalCentreValve(b=B)
    cylinder = Cylinder(A_a=A, A_b=A, V_a0=V0, V_b0=V0, C_i=C_I,
                        p_a={"start": P_S / 2, "fixed": True},
                        p_b={"start": P_S / 2, "fixed": True})
    load = tr.Mass(m=M, s={"start": 0.0, "fixed": True}, v={"start": 0.0, "fixed": True})
    position = tr.PositionSensor()
    set_point = Step(height=X_D, startTime=T_S)
    error = Feedback()
    controller = Gain(k=K_P)

    def equations(self):
        return [ac.connect(self.supply.port, self.valve.port_s),
                ac.connect(self.tank.port, self.valve.port_r),
                ac.connect(self.valve.port_1, self.cylinder.port_a),
                ac.connect(self.valve.port_2, self.cylinder.port_b),
                ac.connect(self.cylinder.flange, self.load.flange_a, self.position.flange),
                ac.connect(self.set_point.y, self.error.u1),
                ac.connect(self.position.s, self.error.u2),
                ac.connect(self.error.y, self.controller.u),
                ac.connect(self.controller.y, self.valve.x_v)]


def _orifice(area, dp):
    """Regularized orifice flow (4.13), the laminar branch below |A dp| = F_tr."""
    x = area * dp / F_TR
    if abs(x) >= 1.0:
        return np.sign(dp) * C_D * area * np.sqrt(2.0 / RHO) * (dp * dp + 1.0) ** 0.25
    return 3 * NU * RE_TR / 4 * np.sqrt(np.pi) / 2 * area**1.5 * dp / F_TR * (3 - abs(x))


def _servo_rhs(t, y):
    """(4.18)-(4.20) valve, (4.83)-(4.85) chambers and the mass, by hand."""
    p_a, p_b, x, v = y
    x_v = K_P * (X_D - x)                  # after the step
    open_1, open_2 = B * max(x_v, 0.0), B * max(-x_v, 0.0)
    q_1 = _orifice(open_1, P_S - p_a) - _orifice(open_2, p_a)
    q_2 = _orifice(open_1, p_b) - _orifice(open_2, P_S - p_b)
    leak = C_I * (p_a - p_b)
    return [BETA / (V0 + A * x) * (q_1 - A * v - leak),
            BETA / (V0 - A * x) * (-q_2 + A * v + leak),
            v, A * (p_a - p_b) / M]


@pytest.fixture(scope="module")
def servo():
    t = np.concatenate([np.linspace(0.0, T_S, 11)[:-1], np.linspace(T_S, T_END, 2901)])
    res = ac.simulate(CylinderServo(), t_end=T_END, rtol=1e-8, t_eval=t)
    # before the step nothing moves (x_v = 0 exactly), so the reference starts at t_s
    ref = solve_ivp(_servo_rhs, (T_S, T_END), [P_S / 2, P_S / 2, 0.0, 0.0], method="LSODA",
                    rtol=1e-11, atol=[1e-4, 1e-4, 1e-15, 1e-13], dense_output=True)
    assert ref.success
    return res, ref


def test_piston_follows_the_set_point_step(servo):
    res, _ = servo
    assert res.success, res.message
    x_end = res["load.s"][-1]
    # 14 time constants after the step the laminar tail is all that is left: >= 98 %
    assert x_end == pytest.approx(X_D, rel=0.02)


@pytest.mark.parametrize("k_tau", [0.5, 1.0, 2.0, 3.0])
def test_position_matches_the_first_order_loop(servo, k_tau):
    res, _ = servo
    t = T_S + k_tau / K_V
    estimate = X_D * (1.0 - np.exp(-k_tau))
    assert abs(res.at("load.s", t) - estimate) < 0.03 * X_D


def test_trajectory_matches_the_hand_written_hydraulics(servo):
    res, ref = servo
    after = res.t >= T_S
    y = ref.sol(res.t[after])
    assert np.max(np.abs(res["load.s"][after] - y[2])) < 1e-4 * X_D
    for name, row in (("cylinder.p_a", 0), ("cylinder.p_b", 1)):
        swing = np.max(np.abs(y[row] - P_S / 2))          # the pressures move by ~1 %
        assert np.max(np.abs(res[name][after] - y[row])) < 1e-3 * swing


def test_chamber_mass_balance_along_the_run(servo):
    """V/beta dp/dt = q - A v - C_i (p_a - p_b), chamber by chamber, with dp/dt the slope
    of the integrated pressure and q the flow the valve reports."""
    res, _ = servo
    t, x, v = res.t, res["load.s"], res["load.v"]
    leak = C_I * (res["cylinder.p_a"] - res["cylinder.p_b"])
    sides = (("cylinder.p_a", V0 + A * x, res["valve.q_1"] - A * v - leak),
             ("cylinder.p_b", V0 - A * x, -res["valve.q_2"] + A * v + leak))
    # central differences away from the step (the slopes jump there)
    inner = np.flatnonzero((t[1:-1] > T_S + 2e-3) & (t[1:-1] < T_END))
    scale = np.max(np.abs(res["valve.q_1"]))
    assert scale > 0.5 * K_Q0 * K_P * X_D          # the valve opened
    for name, volume, net_flow in sides:
        p = res[name]
        dpdt = (p[inner + 2] - p[inner]) / (t[inner + 2] - t[inner])
        lhs = volume[inner + 1] / BETA * dpdt
        assert np.max(np.abs(lhs - net_flow[inner + 1])) < 5e-3 * scale, name
