"""Motor and load with an elastic transmission (Egeland & Gravdahl 3.5.1-3.5.5).

    J_m theta_m'' = T_m - T_L,  J_L theta_L'' = T_L,  T_L = -K theta_e - D theta_e'  (3.70)-(3.73)

Resonance w_1 = sqrt(K/J_e), J_e = J_m J_L/J, J = J_m + J_L, zeta_1 = D/(2 sqrt(J_e K));
anti-resonance w_a = sqrt(J_m/J) w_1, zeta_a = sqrt(J_m/J) zeta_1  (3.87)-(3.88).  The
numbers are those of the book's Fig. 3.11: K = 0.5, J_m = J_L = 1, D = 0.01, so
w_1 = 1 rad/s and w_a = 0.7071 rad/s.

* ``ElasticTransmission``: a torque step on the motor.
* ``FreeElasticTransmission``: no torque, initial twist: theta_e rings at the resonance.
* ``LockedElasticTransmission``: motor held: the load rings at the anti-resonance (the
  zero of theta_m/T_m is the pole of the load on a locked motor).
"""
import acausal as ac
from acausal.library.blocks import Step
from acausal.library.rotational import Fixed, Inertia, SpringDamper, Torque

__all__ = ["ElasticTransmission", "FreeElasticTransmission", "LockedElasticTransmission"]


class ElasticTransmission(ac.Component):
    """Torque step T_m = 1 N m on the motor at t = 1 s."""

    stop_time = 40.0
    torque_reference = Step(height=1.0, startTime=1.0)
    drive = Torque()
    motor = Inertia(J=1.0)
    shaft = SpringDamper(c=0.5, d=0.01)
    load = Inertia(J=1.0)

    def equations(self):
        return [ac.connect(self.torque_reference.y, self.drive.tau),
                ac.connect(self.drive.flange, self.motor.flange_a),
                ac.connect(self.motor.flange_b, self.shaft.flange_a),
                ac.connect(self.shaft.flange_b, self.load.flange_a)]


class FreeElasticTransmission(ac.Component):
    """Motor and load free, shaft twisted by 0.1 rad at t = 0."""

    stop_time = 40.0
    motor = Inertia(J=1.0, phi={"start": 0.0, "fixed": True}, w={"start": 0.0, "fixed": True})
    shaft = SpringDamper(c=0.5, d=0.01)
    load = Inertia(J=1.0, phi={"start": 0.1, "fixed": True}, w={"start": 0.0, "fixed": True})

    def equations(self):
        return [ac.connect(self.motor.flange_b, self.shaft.flange_a),
                ac.connect(self.shaft.flange_b, self.load.flange_a)]


class LockedElasticTransmission(ac.Component):
    """Motor shaft held fixed, load displaced by 0.1 rad at t = 0."""

    stop_time = 40.0
    housing = Fixed()
    shaft = SpringDamper(c=0.5, d=0.01)
    load = Inertia(J=1.0, phi={"start": 0.1, "fixed": True}, w={"start": 0.0, "fixed": True})

    def equations(self):
        return [ac.connect(self.housing.flange, self.shaft.flange_a),
                ac.connect(self.shaft.flange_b, self.load.flange_a)]


if __name__ == "__main__":
    for model in (ElasticTransmission(), FreeElasticTransmission(), LockedElasticTransmission()):
        res = ac.simulate(model, t_end=model.stop_time, rtol=1e-8)
        print(f"{type(model).__name__}: load angle at t_end {res['load.phi'][-1]:.5f} rad")
