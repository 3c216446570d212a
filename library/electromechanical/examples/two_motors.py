"""Two motors driving an elastic load, motor 2 under PD control (Egeland & Gravdahl
3.5.7-3.5.8, Example 45).

    J_1 theta_1'' = T_m1 - T_g1,   J_2 theta_2'' = T_m2 - T_g2              (3.107)-(3.108)
    J_L theta_L'' = (T_g1 + T_g2)/n_b - T_e                                (3.109)
    phi_i = theta_i - theta_L/n_b,   T_gi = K_i phi_i + D_i phi_i'          (3.110)
    T_m2 = -K_p2 theta_2 - K_d2 theta_2'                                    (3.113)

Each gear is a SpringDamper on the motor side followed by an IdealGear with
``n = 1/n_b``.  The PD controller is built from blocks (angle and speed sensors, Add,
Torque).  Energy: V_a' = T_m1 theta_1' - D_1 phi_1'^2 - D_2 phi_2'^2 - K_d2 theta_2'^2 (3.115).
"""
import acausal as ac
from acausal.library.blocks import Add, Step
from acausal.library.rotational import (AngleSensor, IdealGear, Inertia, SpeedSensor,
                                        SpringDamper, Torque)

__all__ = ["TwoMotorsElasticLoad"]


class TwoMotorsElasticLoad(ac.Component):
    """Torque step 0.5 N m on motor 1; motor 2 held near 0 by PD (K_p2 = 2, K_d2 = 0.2)."""

    stop_time = 2.0
    torque_reference = Step(height=0.5, startTime=0.1)
    drive1 = Torque()
    motor1 = Inertia(J=0.01)
    gear1_elasticity = SpringDamper(c=100.0, d=0.05)
    gear1 = IdealGear(ratio=10.0)
    motor2 = Inertia(J=0.01)
    gear2_elasticity = SpringDamper(c=100.0, d=0.05)
    gear2 = IdealGear(ratio=10.0)
    load = Inertia(J=1.0)
    angle2 = AngleSensor()
    speed2 = SpeedSensor()
    pd2 = Add(k1=-2.0, k2=-0.2)
    drive2 = Torque()

    def equations(self):
        return [ac.connect(self.torque_reference.y, self.drive1.tau),
                ac.connect(self.drive1.flange, self.motor1.flange_a),
                ac.connect(self.motor1.flange_b, self.gear1_elasticity.flange_a),
                ac.connect(self.gear1_elasticity.flange_b, self.gear1.flange_a),
                ac.connect(self.gear1.flange_b, self.load.flange_a),
                ac.connect(self.drive2.flange, self.motor2.flange_a, self.angle2.flange,
                           self.speed2.flange),
                ac.connect(self.motor2.flange_b, self.gear2_elasticity.flange_a),
                ac.connect(self.gear2_elasticity.flange_b, self.gear2.flange_a),
                ac.connect(self.gear2.flange_b, self.load.flange_b),
                ac.connect(self.angle2.phi, self.pd2.u1),
                ac.connect(self.speed2.w, self.pd2.u2),
                ac.connect(self.pd2.y, self.drive2.tau)]


if __name__ == "__main__":
    res = ac.simulate(TwoMotorsElasticLoad(), t_end=TwoMotorsElasticLoad.stop_time, rtol=1e-8)
    print(f"load speed at t_end: {res['load.w'][-1]:.5f} rad/s")
