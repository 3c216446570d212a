"""Sampled speed control of a DC motor: a discrete PI at 1 ms on the speed error, its
output through a zero-order hold to the armature voltage (the motor of Egeland &
Gravdahl (3.29)-(3.31), T_a = 1 ms, T_m = 40 ms).

Between the ticks the motor is a linear system driven by a constant voltage, so at the
ticks the loop is exactly the difference equation x_k+1 = A_d x_k + B_d u_k with
(A_d, B_d) the zero-order-hold discretization of the motor, closed by the PI's
difference equations (tests/models/test_sampled.py compares the two).  With the output
limited to +-1 V the controller saturates for the first ticks (k e = 5 V at the start,
the steady state needs k_m w_ref = 0.5 V) and its back-calculation brings the integral
back.  ``python -m`` this module to simulate both.
"""
import acausal as ac
from acausal.library.blocks import Constant, Feedback
from acausal.library.blocks.discrete import PI, ZeroOrderHold
from acausal.library.electrical import Ground, SignalVoltage
from acausal.library.electromechanical import DCMotor
from acausal.library.rotational import SpeedSensor

__all__ = ["SampledSpeedLoop", "h", "R", "L", "k_m", "J", "K", "Ti", "W_REF"]

h = 1e-3                                  # sample period [s]
R, L, k_m, J = 1.0, 1e-3, 0.05, 1e-4      # the motor [Ohm, H, N.m/A, kg.m2]
K, Ti = 0.5, 0.04                         # the PI [V/(rad/s), s]
W_REF = 10.0                              # speed reference [rad/s]


class SampledSpeedLoop(ac.Component):
    """Speed reference 10 rad/s; discrete PI (k = 0.5 V s/rad, Ti = 40 ms) sampled at
    1 ms, held by a zero-order hold onto the armature voltage."""

    stop_time = 0.08
    ref = Constant(k=W_REF)
    err = Feedback()
    pi = PI(k=K, Ti=Ti, samplePeriod=h, yMax=1e3, yMin=-1e3)
    zoh = ZeroOrderHold(samplePeriod=h)
    src = SignalVoltage()
    motor = DCMotor(R=R, L=L, k=k_m, J=J)
    speed = SpeedSensor()
    gnd = Ground()

    def equations(self):
        return [ac.connect(self.ref.y, self.err.u1), ac.connect(self.speed.w, self.err.u2),
                ac.connect(self.err.y, self.pi.u), ac.connect(self.pi.y, self.zoh.u),
                ac.connect(self.zoh.y, self.src.v),
                ac.connect(self.src.p, self.motor.p),
                ac.connect(self.src.n, self.motor.n, self.gnd.p),
                ac.connect(self.motor.flange, self.speed.flange)]


if __name__ == "__main__":
    compiled = ac.compile(SampledSpeedLoop())
    for limit in (1e3, 1.0):
        res = ac.simulate(compiled, t_end=SampledSpeedLoop.stop_time, rtol=1e-8,
                          parameters={"pi.yMax": limit, "pi.yMin": -limit})
        print(f"output limit {limit:g} V: w = {res['motor.rotor.w'][-1]:.4f} rad/s, "
              f"u = {res['zoh.y.signal'][-1]:.4f} V at t_end, {len(res.events)} ticks")
