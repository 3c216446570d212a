"""Modelica.Electrical.Analog.Examples.OpAmps.OpAmpCircuits (MSL v4.0.0): operational
amplifier circuits of the OpAmps examples, each a four-pin (input p1-n1, output p2-n2,
n1 and n2 joined) around an IdealizedOpAmpLimited."""
import math

import acausal as ac
from acausal.library.electrical import (Capacitor, FourPin, IdealizedOpAmpLimited,
                                        Resistor)
from acausal.ports import PositivePin

__all__ = ["PartialOpAmp", "Add", "Buffer", "Der", "Derivative", "Feedback", "FirstOrder",
           "Gain", "Integrator", "PI"]


class PartialOpAmp(FourPin):
    """A four-pin with the op-amp (MSL OpAmpCircuits.PartialOpAmp): supply Vps, Vns,
    no-load amplification V0."""

    Vps = ac.Parameter(15.0, unit="V", description="positive supply")
    Vns = ac.Parameter(-15.0, unit="V", description="negative supply")
    V0 = ac.Parameter(15000.0, description="no-load amplification")
    opAmp = IdealizedOpAmpLimited(V0=ac.ref("V0"), Vps=ac.ref("Vps"), Vns=ac.ref("Vns"),
                                  out={"i": {"start": 0.0, "fixed": False}})


class Add(PartialOpAmp):
    """Inverting adder (MSL OpAmpCircuits.Add): v2 = -(k1 v1 + k2 v1_2), the inputs
    through R1 = R/k1 and R2 = R/k2, the feedback R."""

    k1 = ac.Parameter(1.0, min=0, description="weight of input 1")
    k2 = ac.Parameter(1.0, min=0, description="weight of input 2")
    R = ac.Parameter(1000.0, unit="Ohm", description="resistance at output of OpAmp")
    R1 = ac.Parameter(lambda c: c.R / c.k1, unit="Ohm",
                      description="calculated resistance to reach desired weight 1")
    R2 = ac.Parameter(lambda c: c.R / c.k2, unit="Ohm",
                      description="calculated resistance to reach desired weight 2")
    p1_2 = PositivePin()
    v1_2 = ac.Variable(unit="V", description="voltage drop of port 1_2 (p1_2.v - n1.v)")
    i1_2 = ac.Variable(unit="A", description="current flowing from pos. to neg. pin of port 1_2")
    r1 = Resistor(R=ac.ref("R1"))
    r2 = Resistor(R=ac.ref("R2"))
    r = Resistor(R=ac.ref("R"))

    def equations(self):
        c = ac.connect
        return [ac.Eq(self.v1_2, self.p1_2.v - self.n1.v), ac.Eq(self.i1_2, self.p1_2.i),
                c(self.n1, self.n2), c(self.p1, self.r1.p), c(self.p1_2, self.r2.p),
                c(self.n1, self.opAmp.in_p), c(self.r2.n, self.opAmp.in_n),
                c(self.opAmp.in_n, self.r1.n), c(self.opAmp.in_n, self.r.n),
                c(self.opAmp.out, self.r.p), c(self.opAmp.out, self.p2)]


class Buffer(PartialOpAmp):
    """Non-inverting amplifier (MSL OpAmpCircuits.Buffer): v2 = k v1, R2 = (k - 1) R1."""

    k = ac.Parameter(1.0, min=0, description="desired amplification")
    R1 = ac.Parameter(1000.0, unit="Ohm", description="resistance at negative pin(s)")
    R2 = ac.Parameter(lambda c: (c.k - 1) * c.R1, unit="Ohm",
                      description="calculated resistance to reach desired amplification k")
    r1 = Resistor(R=ac.ref("R1"))
    r2 = Resistor(R=ac.ref("R2"))

    def equations(self):
        c = ac.connect
        return [c(self.opAmp.out, self.p2), c(self.n1, self.n2), c(self.n1, self.r1.n),
                c(self.opAmp.out, self.r2.p), c(self.r2.n, self.r1.p),
                c(self.r2.n, self.opAmp.in_n), c(self.opAmp.in_p, self.p1)]


class Der(PartialOpAmp):
    """Differentiating amplifier (MSL OpAmpCircuits.Der): the input through C = k/(2 pi
    f R), the feedback R; v is the capacitor's voltage (the state)."""

    k = ac.Parameter(1.0, min=0, description="desired amplification at frequency f")
    f = ac.Parameter(1.0, unit="Hz", description="frequency")
    R = ac.Parameter(1000.0, unit="Ohm", description="resistance at output of OpAmp")
    C = ac.Parameter(lambda c: c.k / (2 * math.pi * c.f * c.R), unit="F",
                     description="calculated capacitance to reach desired amplification k")
    v = ac.Variable(start=0.0, unit="V", description="capacitor voltage = state")
    c = Capacitor(C=ac.ref("C"))
    r = Resistor(R=ac.ref("R"))

    def equations(self):
        c = ac.connect
        return [ac.Eq(self.v, self.c.v),
                c(self.n1, self.n2), c(self.opAmp.out, self.p2), c(self.c.n, self.opAmp.in_n),
                c(self.opAmp.in_n, self.r.n), c(self.opAmp.out, self.r.p),
                c(self.c.p, self.p1), c(self.n1, self.opAmp.in_p)]


class Derivative(PartialOpAmp):
    """High-pass filter (MSL OpAmpCircuits.Derivative): the input through C = T/R1 and
    R1, the feedback R2 = k R1; v is the capacitor's voltage (the state)."""

    k = ac.Parameter(1.0, min=0, description="desired amplification")
    R1 = ac.Parameter(1000.0, unit="Ohm", description="resistance at negative input of OpAmp")
    R2 = ac.Parameter(lambda c: c.k * c.R1, unit="Ohm",
                      description="calculated resistance to reach k")
    T = ac.Parameter(1.0, unit="s", description="time constant")
    C = ac.Parameter(lambda c: c.T / c.R1, unit="F",
                     description="calculated capacitance to reach T")
    v = ac.Variable(start=0.0, unit="V", description="capacitor voltage = state")
    r1 = Resistor(R=ac.ref("R1"))
    r2 = Resistor(R=ac.ref("R2"))
    c = Capacitor(C=ac.ref("C"))

    def equations(self):
        c = ac.connect
        return [ac.Eq(self.v, self.c.v),
                c(self.n1, self.n2), c(self.opAmp.out, self.p2), c(self.n1, self.opAmp.in_p),
                c(self.r1.n, self.opAmp.in_n), c(self.opAmp.in_n, self.r2.n),
                c(self.opAmp.out, self.r2.p), c(self.c.n, self.r1.p), c(self.c.p, self.p1)]


class Feedback(PartialOpAmp):
    """Subtracter (MSL OpAmpCircuits.Feedback): v2 = k (v1_2 - v1), R3 = R1/k."""

    k = ac.Parameter(1.0, min=0, description="desired amplification")
    R1 = ac.Parameter(1000.0, unit="Ohm", description="resistance at inputs of OpAmp")
    R3 = ac.Parameter(lambda c: c.R1 / c.k, unit="Ohm",
                      description="calculated resistance to reach desired amplification k")
    p1_2 = PositivePin()
    v1_2 = ac.Variable(unit="V", description="voltage drop of port 1_2 (p1_2.v - n1.v)")
    i1_2 = ac.Variable(unit="A", description="current flowing from pos. to neg. pin of port 1_2")
    r1 = Resistor(R=ac.ref("R1"))
    r2 = Resistor(R=ac.ref("R1"))
    r3 = Resistor(R=ac.ref("R3"))
    r4 = Resistor(R=ac.ref("R3"))

    def equations(self):
        c = ac.connect
        return [ac.Eq(self.v1_2, self.p1_2.v - self.n1.v), ac.Eq(self.i1_2, self.p1_2.i),
                c(self.n1, self.n2), c(self.p1, self.r1.p), c(self.r1.n, self.opAmp.in_n),
                c(self.r1.n, self.r3.n), c(self.opAmp.out, self.r3.p),
                c(self.opAmp.out, self.p2), c(self.p1_2, self.r2.p),
                c(self.r2.n, self.opAmp.in_p), c(self.opAmp.in_p, self.r4.p),
                c(self.n1, self.r4.n)]


class FirstOrder(PartialOpAmp):
    """Low-pass filter (MSL OpAmpCircuits.FirstOrder): gain -k (R2 = k R1), time
    constant T (C = T/R2 across R2); v is the capacitor's voltage (the state)."""

    k = ac.Parameter(1.0, min=0, description="desired amplification")
    R1 = ac.Parameter(1000.0, unit="Ohm", description="resistance at negative input of OpAmp")
    R2 = ac.Parameter(lambda c: c.k * c.R1, unit="Ohm",
                      description="calculated resistance to reach k")
    T = ac.Parameter(1.0, unit="s", description="time constant")
    C = ac.Parameter(lambda c: c.T / c.R2, unit="F",
                     description="calculated capacitance to reach T")
    v2 = ac.Variable(start=0.0, unit="V", description="voltage drop of port 2 (p2.v - n2.v)")
    v = ac.Variable(start=0.0, unit="V", description="capacitor voltage = state")
    r1 = Resistor(R=ac.ref("R1"))
    r2 = Resistor(R=ac.ref("R2"))
    c = Capacitor(C=ac.ref("C"))

    def equations(self):
        c = ac.connect
        return [ac.Eq(self.v, self.c.v),
                c(self.n1, self.n2), c(self.opAmp.out, self.p2), c(self.n1, self.opAmp.in_p),
                c(self.r1.p, self.p1), c(self.r1.n, self.opAmp.in_n),
                c(self.opAmp.in_n, self.r2.n), c(self.opAmp.in_n, self.c.n),
                c(self.opAmp.out, self.r2.p), c(self.opAmp.out, self.c.p)]


class Gain(PartialOpAmp):
    """Inverting amplifier (MSL OpAmpCircuits.Gain): v2 = -k v1, R2 = k R1."""

    k = ac.Parameter(1.0, min=0, description="desired amplification")
    R1 = ac.Parameter(1000.0, unit="Ohm", description="resistance at negative input of OpAmp")
    R2 = ac.Parameter(lambda c: c.k * c.R1, unit="Ohm",
                      description="calculated resistance to reach desired amplification k")
    r1 = Resistor(R=ac.ref("R1"))
    r2 = Resistor(R=ac.ref("R2"))

    def equations(self):
        c = ac.connect
        return [c(self.opAmp.out, self.r2.p), c(self.opAmp.out, self.p2),
                c(self.r1.n, self.opAmp.in_n), c(self.r1.n, self.r2.n), c(self.r1.p, self.p1),
                c(self.n1, self.opAmp.in_p), c(self.n1, self.n2)]


class Integrator(PartialOpAmp):
    """Integrating amplifier (MSL OpAmpCircuits.Integrator): the input through R, the
    feedback C = 1/(k 2 pi f R); v is the capacitor's voltage (the state)."""

    k = ac.Parameter(1.0, min=0, description="desired amplification at frequency f")
    f = ac.Parameter(1.0, unit="Hz", description="frequency")
    R = ac.Parameter(1000.0, unit="Ohm", description="resistance at negative input of OpAmp")
    C = ac.Parameter(lambda c: 1 / c.k / (2 * math.pi * c.f * c.R), unit="F",
                     description="calculated capacitance to reach desired amplification k")
    v2 = ac.Variable(start=0.0, unit="V", description="voltage drop of port 2 (p2.v - n2.v)")
    v = ac.Variable(start=0.0, unit="V", description="capacitor voltage = state")
    c = Capacitor(C=ac.ref("C"))
    r = Resistor(R=ac.ref("R"))

    def equations(self):
        c = ac.connect
        return [ac.Eq(self.v, self.c.v),
                c(self.n1, self.n2), c(self.opAmp.out, self.p2), c(self.n1, self.opAmp.in_p),
                c(self.r.p, self.p1), c(self.r.n, self.opAmp.in_n),
                c(self.opAmp.in_n, self.c.n), c(self.opAmp.out, self.c.p)]


class PI(PartialOpAmp):
    """PI controller (MSL OpAmpCircuits.PI): the input through R1, the feedback R2 = k
    R1 in series with C = T/(k R1)."""

    k = ac.Parameter(1.0, min=0, description="desired amplification")
    R1 = ac.Parameter(1000.0, unit="Ohm", description="resistance at negative input of OpAmp")
    R2 = ac.Parameter(lambda c: c.k * c.R1, unit="Ohm",
                      description="calculated resistance to reach k")
    T = ac.Parameter(1.0, unit="s", description="time constant")
    C = ac.Parameter(lambda c: c.T / c.k / c.R1, unit="F",
                     description="calculated capacitance to reach T")
    v2 = ac.Variable(start=0.0, unit="V", description="voltage drop of port 2 (p2.v - n2.v)")
    r1 = Resistor(R=ac.ref("R1"))
    r2 = Resistor(R=ac.ref("R2"))
    c = Capacitor(C=ac.ref("C"))

    def equations(self):
        c = ac.connect
        return [c(self.n1, self.n2), c(self.opAmp.out, self.p2), c(self.n1, self.opAmp.in_p),
                c(self.r1.n, self.opAmp.in_n), c(self.opAmp.in_n, self.r2.n),
                c(self.p1, self.r1.p), c(self.r2.p, self.c.n), c(self.opAmp.out, self.c.p)]
