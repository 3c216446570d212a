"""Models of the persistence tests, in a module of their own (the compile cache keys a
model's classes by their source file).

RC: a capacitor charged to v0 = 1 V discharging through a resistor,
    v(t) = v0 exp(-t / (R C))            (first-order RC circuit, closed form).
SqrtOfStart: der(x) = -sqrt(x) from x = -1, outside the domain of sqrt: the run fails
    and names that equation.
"""
import math

import acausal as ac
from acausal.library.electrical import Capacitor, Ground, Resistor

__all__ = ["RC", "rc_voltage", "SqrtOfStart"]


class RC(ac.Component):
    """R = 2 Ohm, C = 0.5 F: time constant 1 s."""

    R1 = Resistor(R=2.0)
    C1 = Capacitor(C=0.5, v={"start": 1.0, "fixed": True})
    gnd = Ground()

    def equations(self):
        return [ac.connect(self.R1.p, self.C1.p), ac.connect(self.R1.n, self.C1.n, self.gnd.p)]


def rc_voltage(t, R=2.0, C=0.5, v0=1.0):
    return v0 * math.exp(-t / (R * C))


class SqrtOfStart(ac.Component):
    """der(x) = -sqrt(x), x(0) = -1: no real solution."""

    x = ac.Variable(start=-1.0, fixed=True)

    def equations(self):
        return [ac.Eq(ac.der(self.x), -ac.sqrt(self.x))]
