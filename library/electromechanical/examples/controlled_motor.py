"""Current-, velocity- and position-controlled DC motor (Egeland & Gravdahl 3.4), the
controllers built from signal blocks.

* ``CurrentLoop``: PI current controller on a voltage-driven motor, Example 44 (3.60):
  u_a = K_i (1 + T_i s)/s (i_0 - i_a) with T_i = T_m, i.e. PI(k = K_i T_m, Ti = T_m).
* ``VelocityLoop``: current-controlled motor (3.59) and P speed controller (3.63),
  i_d = K_w (w_d - w_m):  w_m/w_d = 1/(1 + s/K_a),  K_a = K_T K_w/J_m  (3.64)-(3.65).
* ``PositionLoop``: the velocity loop inside a P position loop (3.67),
  w_d = K_v (theta_d - theta_m):  theta_m/theta_d = 1/(1 + s/K_v + s^2/(K_v K_a)) (3.68).
"""
import acausal as ac
from acausal.library.blocks import PI, Feedback, Gain, Step
from acausal.library.electrical import CurrentSensor, Ground, SignalVoltage
from acausal.library.electromechanical import CurrentControlledDCMotor, DCMotor
from acausal.library.rotational import AngleSensor, SpeedSensor

__all__ = ["CurrentLoop", "VelocityLoop", "PositionLoop"]

_R, _L, _K, _J = 1.0, 1e-3, 0.05, 1e-4     # T_a = 1 ms, T_m = J R / K^2 = 40 ms
_T_M = _J * _R / _K**2


class CurrentLoop(ac.Component):
    """1 A current step; PI current controller with K_i = 50 V/A and T_i = T_m."""

    stop_time = 0.02
    reference = Step(height=1.0, startTime=0.0)
    error = Feedback()
    controller = PI(k=50.0 * _T_M, Ti=_T_M)
    amplifier = SignalVoltage()
    sensor = CurrentSensor()
    ground = Ground()
    motor = DCMotor(R=_R, L=_L, k=_K, J=_J)

    def equations(self):
        return [ac.connect(self.reference.y, self.error.u1),
                ac.connect(self.sensor.i, self.error.u2),
                ac.connect(self.error.y, self.controller.u),
                ac.connect(self.controller.y, self.amplifier.v),
                ac.connect(self.amplifier.p, self.sensor.p),
                ac.connect(self.sensor.n, self.motor.p),
                ac.connect(self.amplifier.n, self.motor.n, self.ground.p)]


class VelocityLoop(ac.Component):
    """10 rad/s speed step on a current-controlled motor, K_w = 0.4 A s/rad
    (K_a = K_T K_w / J_m = 200 rad/s)."""

    stop_time = 0.05
    reference = Step(height=10.0, startTime=0.0)
    error = Feedback()
    controller = Gain(k=0.4)
    speed = SpeedSensor()
    motor = CurrentControlledDCMotor(R=_R, L=_L, k=_K, J=_J)

    def equations(self):
        return [ac.connect(self.reference.y, self.error.u1),
                ac.connect(self.speed.w, self.error.u2),
                ac.connect(self.error.y, self.controller.u),
                ac.connect(self.controller.y, self.motor.i_d),
                ac.connect(self.motor.flange, self.speed.flange)]


class PositionLoop(ac.Component):
    """1 rad position step; P position loop K_v = 20 1/s around the velocity loop of
    ``VelocityLoop`` (K_a = 200 rad/s)."""

    stop_time = 0.5
    reference = Step(height=1.0, startTime=0.0)
    position_error = Feedback()
    position_controller = Gain(k=20.0)
    speed_error = Feedback()
    speed_controller = Gain(k=0.4)
    angle = AngleSensor()
    speed = SpeedSensor()
    motor = CurrentControlledDCMotor(R=_R, L=_L, k=_K, J=_J)

    def equations(self):
        return [ac.connect(self.reference.y, self.position_error.u1),
                ac.connect(self.angle.phi, self.position_error.u2),
                ac.connect(self.position_error.y, self.position_controller.u),
                ac.connect(self.position_controller.y, self.speed_error.u1),
                ac.connect(self.speed.w, self.speed_error.u2),
                ac.connect(self.speed_error.y, self.speed_controller.u),
                ac.connect(self.speed_controller.y, self.motor.i_d),
                ac.connect(self.motor.flange, self.angle.flange, self.speed.flange)]


if __name__ == "__main__":
    for model in (CurrentLoop(), VelocityLoop(), PositionLoop()):
        res = ac.simulate(model, t_end=model.stop_time, rtol=1e-8)
        print(f"{type(model).__name__}: phi = {res['motor.flange.phi'][-1]:.4f} rad, "
              f"w = {res['motor.motor.rotor.w' if 'motor.motor.rotor.w' in res else 'motor.rotor.w'][-1]:.4f} rad/s at t_end")
