"""Modelica.Electrical.Analog.Examples.CauerLowPassOPV (MSL v4.0.0): the fifth-order
Cauer low-pass filter of CauerLowPassAnalog realized with five ideal operational
amplifiers, capacitors and 1 Ohm resistors (four of them -1 Ohm), fed by a 1 V step
at t = 1 s.  The MSL's protected pins n1 ... n14, p1 ... p4 and out1 are the nodes
they join."""
import acausal as ac
from acausal.library.electrical import (Capacitor, Ground, IdealOpAmp3Pin, Resistor,
                                        StepVoltage)
from acausal.ports import NegativePin, PositivePin

__all__ = ["CauerLowPassOPV"]

l1, l2 = 1.304, 0.8586                     # filter coefficients
c1, c3, c5 = 1.072, 1.682, 0.7262
c2 = 1 / (1.704992**2 * l1)
c4 = 1 / (1.179945**2 * l2)


class CauerLowPassOPV(ac.Component):
    """l1 = 1.304, l2 = 0.8586, c1 = 1.072, c3 = 1.682, c5 = 0.7262 (F),
    c2 = 1/(1.704992^2 l1), c4 = 1/(1.179945^2 l2)."""

    msl_name = "Modelica.Electrical.Analog.Examples.CauerLowPassOPV"
    stop_time = 60.0
    tolerance = 1e-6

    C1 = Capacitor(C=c1 + c2, v={"start": 0.0, "fixed": True})
    C2 = Capacitor(C=c2, v={"start": 0.0, "fixed": True})
    C3 = Capacitor(C=l1, v={"start": 0.0, "fixed": True})
    C4 = Capacitor(C=c4, v={"start": 0.0, "fixed": True})
    C5 = Capacitor(C=c2)
    R1 = Resistor(R=1.0)
    R2 = Resistor(R=1.0)
    R3 = Resistor(R=1.0)
    Op1 = IdealOpAmp3Pin()
    G = Ground()
    R4 = Resistor(R=-1.0)
    R5 = Resistor(R=-1.0)
    Op2 = IdealOpAmp3Pin()
    Op3 = IdealOpAmp3Pin()
    G1 = Ground()
    R6 = Resistor(R=1.0)
    R7 = Resistor(R=1.0)
    C6 = Capacitor(C=c2 + c3 + c4)
    R8 = Resistor(R=-1.0)
    R9 = Resistor(R=-1.0)
    R10 = Resistor(R=1.0)
    Op4 = IdealOpAmp3Pin()
    Op5 = IdealOpAmp3Pin()
    C7 = Capacitor(C=l2, v={"start": 0.0, "fixed": True})
    C8 = Capacitor(C=c4)
    C9 = Capacitor(C=c4 + c5)
    R11 = Resistor(R=1.0)
    n1, n2, n3, n4, n5 = (NegativePin() for _ in range(5))
    p1 = PositivePin()
    n6, n7, n8 = (NegativePin() for _ in range(3))
    p2 = PositivePin()
    out1 = PositivePin()
    p3 = PositivePin()
    n9, n10, n11 = (NegativePin() for _ in range(3))
    G2 = Ground()
    n12, n13 = NegativePin(), NegativePin()
    p4 = PositivePin()
    n14 = NegativePin()
    G3 = Ground()
    G4 = Ground()
    V = StepVoltage(startTime=1.0, V=1.0)
    Ground1 = Ground()

    def equations(self):
        c = ac.connect
        return [c(self.Op1.in_p, self.G.p), c(self.G1.p, self.Op2.in_p),
                c(self.R1.n, self.n1), c(self.n1, self.Op1.in_n), c(self.C2.n, self.n1),
                c(self.R2.n, self.n2), c(self.n1, self.n2), c(self.n2, self.n3),
                c(self.n3, self.C1.p), c(self.n3, self.R3.p), c(self.C1.n, self.n4),
                c(self.R3.n, self.n4), c(self.n4, self.Op1.out), c(self.R4.p, self.Op1.out),
                c(self.C5.p, self.Op1.out), c(self.R4.n, self.n5), c(self.n5, self.Op2.in_n),
                c(self.C3.p, self.n5), c(self.R5.n, self.n5), c(self.R5.p, self.p1),
                c(self.C2.p, self.p1), c(self.C3.n, self.n6), c(self.n6, self.Op2.out),
                c(self.R2.p, self.n6), c(self.Op2.out, self.R7.p), c(self.R7.n, self.n7),
                c(self.n7, self.Op3.in_n), c(self.C5.n, self.n7), c(self.R6.n, self.n8),
                c(self.n7, self.n8), c(self.C6.p, self.p2), c(self.n8, self.p2),
                c(self.C4.n, self.p2), c(self.C6.n, self.Op3.out), c(self.R9.p, self.Op3.out),
                c(self.Op3.out, self.out1), c(self.p1, self.out1), c(self.out1, self.C8.p),
                c(self.C4.p, self.p3), c(self.p3, self.R8.p), c(self.R8.n, self.n9),
                c(self.n9, self.n10), c(self.R9.n, self.n10), c(self.n10, self.Op4.in_n),
                c(self.n9, self.C7.p), c(self.C7.n, self.n11), c(self.R6.p, self.n11),
                c(self.n11, self.Op4.out), c(self.Op4.out, self.R10.p),
                c(self.G2.p, self.Op3.in_p), c(self.R11.n, self.n12), c(self.p3, self.n12),
                c(self.C9.n, self.n13), c(self.n12, self.n13), c(self.n13, self.Op5.out),
                c(self.C9.p, self.p4), c(self.R11.p, self.p4), c(self.R10.n, self.n14),
                c(self.p4, self.n14), c(self.Op5.in_n, self.n14), c(self.C8.n, self.n14),
                c(self.Op4.in_p, self.G3.p), c(self.Op5.in_p, self.G4.p),
                c(self.V.p, self.Ground1.p), c(self.V.n, self.R1.p)]


if __name__ == "__main__":
    res = ac.simulate(CauerLowPassOPV(), t_end=CauerLowPassOPV.stop_time,
                      rtol=CauerLowPassOPV.tolerance)
    print(f"C7.v at {res.t[-1]:g} s: {res['C7.v'][-1]:.6g} V")
