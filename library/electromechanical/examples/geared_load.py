"""DC motor driving a load inertia through an ideal gear (Egeland & Gravdahl 3.2.3-3.2.4).

With the book's ratio n_b = w_L/w_m (a reduction gear has n_b < 1) the motor sees

    (J_m + n_b^2 J_L) dw_m/dt = T - n_b T_e                          (3.12)

and the gear is lossless: T_in w_in = T_out w_out (3.6).  ``IdealGear.ratio`` is the
ratio phi_m/phi_L = 1/n_b.  The gear couples the angles of two inertias (index 3):
index reduction differentiates the gear constraint twice and keeps one state pair.
"""
import acausal as ac
from acausal.library.electrical import Ground, StepVoltage
from acausal.library.electromechanical import DCMotor
from acausal.library.rotational import ConstantTorque, IdealGear, Inertia, PowerSensor

__all__ = ["MotorGearLoad"]


class MotorGearLoad(ac.Component):
    """24 V step; reduction 1:10; load J_L = 5e-3 kg m^2 against T_e = 0.2 N m."""

    stop_time = 0.5
    source = StepVoltage(V=24.0)
    ground = Ground()
    motor = DCMotor(R=1.0, L=1e-3, k=0.05, J=1e-4)
    power_in = PowerSensor()
    gear = IdealGear(ratio=10.0)
    power_out = PowerSensor()
    load = Inertia(J=5e-3)
    disturbance = ConstantTorque(tau_constant=-0.2)

    def equations(self):
        return [ac.connect(self.source.p, self.motor.p),
                ac.connect(self.source.n, self.motor.n, self.ground.p),
                ac.connect(self.motor.flange, self.power_in.flange_a),
                ac.connect(self.power_in.flange_b, self.gear.flange_a),
                ac.connect(self.gear.flange_b, self.power_out.flange_a),
                ac.connect(self.power_out.flange_b, self.load.flange_a),
                ac.connect(self.load.flange_b, self.disturbance.flange)]


if __name__ == "__main__":
    res = ac.simulate(MotorGearLoad(), t_end=MotorGearLoad.stop_time, rtol=1e-8)
    print(f"load speed at t_end: {res['load.w'][-1]:.4f} rad/s")
