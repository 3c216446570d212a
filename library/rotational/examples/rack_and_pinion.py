"""Motor inertia driving a mass through a rack and pinion (Egeland & Gravdahl 3.2.5).

    v = r w_m,  F = T_L/r   (3.14)-(3.15),   m v' = F - F_e   (3.16)
    => (J_m + m r^2) w_m' = T - r F_e                           (3.18)
"""
import acausal as ac
from acausal.library.rotational import ConstantTorque, Inertia, RackAndPinion
from acausal.library.translational import ConstantForce, Mass

__all__ = ["RackAndPinionDrive"]


class RackAndPinionDrive(ac.Component):
    """T = 2 N m on J_m = 0.01 kg m^2, pinion r = 0.05 m, cart m = 10 kg, F_e = 5 N."""

    stop_time = 1.0
    torque = ConstantTorque(tau_constant=2.0)
    motor = Inertia(J=0.01)
    pinion = RackAndPinion(r=0.05)
    cart = Mass(m=10.0)
    resistance = ConstantForce(f_constant=-5.0)

    def equations(self):
        return [ac.connect(self.torque.flange, self.motor.flange_a),
                ac.connect(self.motor.flange_b, self.pinion.flangeR),
                ac.connect(self.pinion.flangeT, self.cart.flange_a),
                ac.connect(self.cart.flange_b, self.resistance.flange)]


if __name__ == "__main__":
    res = ac.simulate(RackAndPinionDrive(), t_end=RackAndPinionDrive.stop_time, rtol=1e-8)
    print(f"cart speed at t_end: {res['cart.v'][-1]:.5f} m/s")
