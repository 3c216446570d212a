"""Small models with closed-form responses for the result tests."""
import numpy as np

import acausal as ac
from acausal.library.electrical import Capacitor, Ground, Resistor, StepVoltage

T_STEP = 0.1          # the source steps at this time (a time event)


class StepRC(ac.Component):
    """A step of V volts at T_STEP on R in series with C: after the step
    v_C = V (1 - exp(-(t - T_STEP) / (R C))), i = (V - v_C) / R."""

    src = StepVoltage(V=2.0, startTime=T_STEP)
    R1 = Resistor(R=0.5)
    C1 = Capacitor(C=2.0)
    gnd = Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.R1.p), ac.connect(self.R1.n, self.C1.p),
                ac.connect(self.C1.n, self.src.n, self.gnd.p)]


def rc_voltage(t, V=2.0, R=0.5, C=2.0):
    t = np.asarray(t, dtype=float)
    return np.where(t >= T_STEP, V * (1.0 - np.exp(-(t - T_STEP) / (R * C))), 0.0)


G, E = 9.81, 0.8


class BouncingBall(ac.Component):
    """h'' = -g; when h < 0: v := -e pre(v)."""

    g = ac.Parameter(G, unit="m/s2", description="gravity")
    e = ac.Parameter(E, min=0, description="coefficient of restitution")
    h = ac.Variable(start=1.0, fixed=True, unit="m", description="height")
    v = ac.Variable(start=0.0, fixed=True, unit="m/s")

    def equations(self):
        return [ac.Eq(ac.der(self.h), self.v), ac.Eq(ac.der(self.v), -self.g),
                ac.when(self.h < 0, ac.reinit(self.v, -self.e * ac.pre(self.v)))]


def bounce_times(n, h0=1.0):
    """t1 = sqrt(2 h0 / g), then flights of 2 e^k v1 / g."""
    t1 = np.sqrt(2 * h0 / G)
    v1 = G * t1
    return t1 + np.concatenate([[0.0], np.cumsum(2 * E ** np.arange(1, n) * v1 / G)])
