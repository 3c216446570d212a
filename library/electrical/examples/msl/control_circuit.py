"""Modelica.Electrical.Analog.Examples.OpAmps.ControlCircuit (MSL v4.0.0): a PI
controller of a plant of two first-order lags with a disturbance added between them,
built of operational amplifier circuits (A) and of blocks (B), the two compared.

The blocks start with their outputs at 0 (the MSL's initType = InitialOutput, y_start
= 0), written as initial equations on their outputs.  The MSL's Blocks.Continuous.PI
(state x, y = k (x + u)) is not acausal.library.blocks.PI (a limited PI with
anti-windup); the block below is its equations, for this example."""
import acausal as ac
from acausal.library.blocks import Add, Feedback, FirstOrder, Step
from acausal.library.blocks.interfaces import SISO
from acausal.library.electrical import Ground, StepVoltage

from . import op_amp_circuits as circuits

__all__ = ["PI", "ControlCircuit"]


class PI(SISO):
    """Proportional-integral controller (Modelica.Blocks.Continuous.PI):

        der(x) = u/T,   y = k (x + u)
    """

    k = ac.Parameter(1.0, description="gain")
    T = ac.Parameter(1.0, unit="s", min=1e-60, description="time constant (T > 0 required)")
    x = ac.Variable(start=0.0, description="state of block")

    def equations(self):
        return [ac.Eq(ac.der(self.x), self.u / self.T), ac.Eq(self.y, self.k * (self.x + self.u))]


T1 = 0.01              # small time constant (s)
T2 = 0.01              # large time constant (s)
Ti = T2                # integral time constant (s)
kp = T2 / (2 * T1)     # proportional gain


class ControlCircuit(ac.Component):
    """T1 = T2 = Ti = 10 ms, kp = T2/(2 T1); the reference steps to 10 at 0.1 s, the
    disturbance to 1 at 0.5 s."""

    msl_name = "Modelica.Electrical.Analog.Examples.OpAmps.ControlCircuit"
    stop_time = 1.0
    tolerance = 1e-07

    ground = Ground()
    stepA = StepVoltage(V=10.0, startTime=0.1)
    feedbackA = circuits.Feedback(p1={"i": {"start": 0.0}})
    PIA = circuits.PI(v2={"fixed": True}, k=kp, T=Ti, opAmp={"v_in": {"start": 0.0}})
    firstOrder1A = circuits.FirstOrder(v2={"fixed": True}, T=T1,
                                       opAmp={"v_in": {"start": 0.0}})
    addA = circuits.Add(i1_2={"start": 0.0}, r={"i": {"start": 0.0}})
    step1A = StepVoltage(V=1.0, startTime=0.5)
    firstOrder2A = circuits.FirstOrder(v2={"fixed": True}, T=T2,
                                       opAmp={"v_in": {"start": 0.0}})
    stepB = Step(height=10.0, startTime=0.1)
    feedbackB = Feedback()
    PIB = PI(k=kp, T=Ti)
    firstOrder1B = FirstOrder(T=T1)
    addB = Add()
    step1B = Step(height=1.0, startTime=0.5)
    firstOrder2B = FirstOrder(T=T2)

    def initial_equations(self):
        # initType = InitialOutput, y_start = 0
        return [ac.Eq(self.PIB.y, 0), ac.Eq(self.firstOrder1B.y, 0),
                ac.Eq(self.firstOrder2B.y, 0)]

    def equations(self):
        c = ac.connect
        return [c(self.stepA.n, self.ground.p),
                c(self.feedbackA.p2, self.PIA.p1), c(self.feedbackA.n2, self.PIA.n1),
                c(self.PIA.p2, self.firstOrder1A.p1), c(self.PIA.n2, self.firstOrder1A.n1),
                c(self.stepB.y, self.feedbackB.u1), c(self.feedbackB.y, self.PIB.u),
                c(self.PIB.y, self.firstOrder1B.u), c(self.firstOrder1B.y, self.addB.u1),
                c(self.addB.y, self.firstOrder2B.u), c(self.step1B.y, self.addB.u2),
                c(self.firstOrder2B.y, self.feedbackB.u2),
                c(self.stepA.p, self.feedbackA.p1_2), c(self.firstOrder2A.p2, self.feedbackA.p1),
                c(self.ground.p, self.feedbackA.n1), c(self.ground.p, self.step1A.n),
                c(self.firstOrder1A.n2, self.addA.n1), c(self.firstOrder1A.p2, self.addA.p1),
                c(self.step1A.p, self.addA.p1_2), c(self.addA.p2, self.firstOrder2A.p1),
                c(self.addA.n2, self.firstOrder2A.n1)]


if __name__ == "__main__":
    res = ac.simulate(ControlCircuit(), t_end=1.0, rtol=1e-7)
    print(f"firstOrder2B.y at {res.t[-1]:g} s: {res['firstOrder2B.y'][-1]:.6g}")
