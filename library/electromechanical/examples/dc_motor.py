"""DC motor with constant field on a voltage step (Egeland & Gravdahl 3.3), with the
armature inductance (3.29)-(3.31) and without it (2.2.1, (2.36)-(2.39)).

Without load, the speed response to a step u_a = V is

    L_a > 0:  w(s)/u_a(s) = (1/k) / (1 + T_m s + T_a T_m s^2)      (2.31)
    L_a = 0:  T_m dw/dt = -w + u_a/k                                 (2.39)

with T_a = L_a/R_a, T_m = J R_a/k^2 (2.28).  ``python -m`` this module to simulate both.
"""
import acausal as ac
from acausal.library.electrical import Ground, Resistor, StepVoltage
from acausal.library.electromechanical import EMF, DCMotor
from acausal.library.rotational import Inertia

__all__ = ["DCMotorStep", "DCMotorStepNoInductance"]


class DCMotorStep(ac.Component):
    """24 V step at t = 0.01 s on an unloaded DC motor (T_a = 1 ms, T_m = 40 ms)."""

    stop_time = 0.2
    source = StepVoltage(V=24.0, startTime=0.01)
    ground = Ground()
    motor = DCMotor(R=1.0, L=1e-3, k=0.05, J=1e-4)

    def equations(self):
        return [ac.connect(self.source.p, self.motor.p),
                ac.connect(self.source.n, self.motor.n, self.ground.p)]


class DCMotorStepNoInductance(ac.Component):
    """The same motor with L_a = 0: the armature equation 0 = u_a - R_a i_a - k w is
    algebraic, so the only state is the rotor's (index 1 after alias elimination)."""

    stop_time = 0.2
    source = StepVoltage(V=24.0, startTime=0.01)
    ground = Ground()
    Ra = Resistor(R=1.0)
    emf = EMF(k=0.05)
    rotor = Inertia(J=1e-4)

    def equations(self):
        return [ac.connect(self.source.p, self.Ra.p),
                ac.connect(self.Ra.n, self.emf.p),
                ac.connect(self.source.n, self.emf.n, self.ground.p),
                ac.connect(self.emf.flange, self.rotor.flange_a)]


if __name__ == "__main__":
    for model in (DCMotorStep(), DCMotorStepNoInductance()):
        res = ac.simulate(model, t_end=model.stop_time, rtol=1e-8)
        w = res["motor.rotor.w" if "motor.rotor.w" in res else "rotor.w"]
        print(f"{type(model).__name__}: w(t_end) = {w[-1]:.6f} rad/s")
