"""Pump-controlled hydraulic motor, a hydrostatic gear (Egeland & Gravdahl 4.4.5).

A variable-displacement pump turning at constant speed w_p feeds a motor through one
line of volume V_0 (the return line is held at tank pressure).  With total leakage
C_t = C_ip + C_im the linear model is

    (V_0/beta) p' = D_max w_p phi_p - D_m w_m - C_t p,   J_t w_m' = D_m p - T_L

and its characteristic polynomial gives (4.122):

    w_h^2 = beta D_m^2 / (V_0 J_t),   zeta_h = (C_t / (2 D_m)) sqrt(beta J_t / V_0)

In steady state p = T_L/D_m and w_m = (D_max w_p phi_p - C_t p)/D_m.
"""
import acausal as ac
from acausal.library import rotational as rot
from acausal.library.blocks import Constant

from ..components import HydraulicMotor, VariablePump, Volume
from ..sources import FixedPressure

__all__ = ["HydrostaticGear"]


class HydrostaticGear(ac.Component):
    """w_p = 150 rad/s, D_max = D_m = 1e-5 m3/rad, phi_p = 0.6, V_0 = 5e-4 m3,
    J_t = 0.05 kg m2, C_ip = C_im = 7.5e-12 m3/(s Pa), T_L = 20 N m."""

    stop_time = 0.5
    tank = FixedPressure(p=0.0)
    drive = rot.ConstantSpeed(w_fixed=150.0)
    swash = Constant(k=0.6)
    pump = VariablePump(D_max=1e-5, C_i=7.5e-12)
    line = Volume(V=5e-4, p={"start": 0.0, "fixed": True})
    motor = HydraulicMotor(D_m=1e-5, C_i=7.5e-12)
    load = rot.Inertia(J=0.05, w={"start": 0.0, "fixed": True})
    load_torque = rot.ConstantTorque(tau_constant=-20.0)

    def equations(self):
        return [ac.connect(self.drive.flange, self.pump.flange),
                ac.connect(self.swash.y, self.pump.phi_p),
                ac.connect(self.tank.port, self.pump.port_a, self.motor.port_b),
                ac.connect(self.pump.port_b, self.line.port, self.motor.port_a),
                ac.connect(self.motor.flange, self.load.flange_a),
                ac.connect(self.load.flange_b, self.load_torque.flange)]


if __name__ == "__main__":
    res = ac.simulate(HydrostaticGear(), t_end=HydrostaticGear.stop_time, rtol=1e-8)
    print(f"motor speed at t_end: {res['load.w'][-1]:.4f} rad/s")
