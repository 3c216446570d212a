"""Valve-controlled hydraulic motor with P control of the angle (Egeland & Gravdahl
4.4.1-4.4.3).

A matched, symmetric critical-centre valve (4.18)-(4.20) feeds a symmetric motor; each
motor line is a volume V_0, so V_t = 2 V_0.  Linearized about an operating point the
load-pressure model (4.93), (4.90) gives

    theta_m = (K_q/D_m) x_v / (s (1 + 2 zeta_h s/w_h + s^2/w_h^2))           (4.100)
    w_h^2 = 4 beta D_m^2 / (V_t J_t),   zeta_h = (K_ce/D_m) sqrt(beta J_t/V_t)   (4.101)

with K_ce = K_c + C_tm, C_tm = C_im + C_em/2.  P control x_v = K_p (theta_d - theta_m)
closes the loop L(s) = K_v / (s (1 + 2 zeta_h s/w_h + s^2/w_h^2)), K_v = K_p K_q/D_m,
stable iff K_v < 2 zeta_h w_h (4.112).  The data give w_h = 400 rad/s and, at the
centred valve (K_c0 = 0), zeta_h = 0.1 from the leakage alone; K_p is set for
K_v = zeta_h w_h = 40 1/s, the 6 dB gain margin of (4.113).
"""
import acausal as ac
from acausal.library import rotational as rot
from acausal.library.blocks import Feedback, Gain, Step

from ..components import HydraulicMotor, Volume
from ..sources import FixedPressure
from ..valves import CriticalCentreValve

__all__ = ["ValveControlledMotor"]

P_S, B, RHO, C_D = 1e7, 1e-3, 900.0, 0.6
D_M, V_0, BETA, J_T = 1e-5, 1e-4, 7e8, 8.75e-3
C_IM = 0.1 * D_M / (BETA * J_T / (2 * V_0))**0.5     # zeta_h = 0.1 with K_c = 0
K_Q0 = C_D * B * (P_S / RHO)**0.5                     # (4.37)
K_P = 40.0 * D_M / K_Q0                               # K_v = zeta_h w_h = 40 1/s  (4.113)


class ValveControlledMotor(ac.Component):
    """p_s = 100 bar, b = 1 mm, D_m = 1e-5 m3/rad, V_0 = 1e-4 m3, J_t = 8.75e-3 kg m2;
    a 1 rad step of the reference at t = 0."""

    stop_time = 0.5
    supply = FixedPressure(p=P_S)
    tank = FixedPressure(p=0.0)
    valve = CriticalCentreValve(b=B, rho=RHO, C_d=C_D)
    line_1 = Volume(V=V_0, beta=BETA, p={"start": P_S / 2, "fixed": True})
    line_2 = Volume(V=V_0, beta=BETA, p={"start": P_S / 2, "fixed": True})
    motor = HydraulicMotor(D_m=D_M, C_i=C_IM)
    load = rot.Inertia(J=J_T, phi={"start": 0.0, "fixed": True}, w={"start": 0.0, "fixed": True})
    angle = rot.AngleSensor()
    reference = Step(height=1.0)
    error = Feedback()
    controller = Gain(k=K_P)

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


if __name__ == "__main__":
    res = ac.simulate(ValveControlledMotor(), t_end=ValveControlledMotor.stop_time, rtol=1e-6)
    print(f"angle at t_end: {res['load.phi'][-1]:.4f} rad; {len(res.events)} events")
