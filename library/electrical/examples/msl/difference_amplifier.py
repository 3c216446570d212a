"""Modelica.Electrical.Analog.Examples.DifferenceAmplifier (MSL v4.0.0): a differential
pair of NPN transistors (with base and collector resistances, Utilities.Transistor)
fed by a ramp current source at the emitters, a 15 V ramp supply through 100 Ohm
collector resistors and a damped 200 MHz sine at one base."""
import acausal as ac
from acausal.library.electrical import (Capacitor, ExpSineVoltage, Ground, RampCurrent,
                                        RampVoltage, Resistor)

from .utilities import Transistor

__all__ = ["DifferenceAmplifier"]


class DifferenceAmplifier(ac.Component):
    """V1: 0.2 V, 200 MHz, damping 1e7 1/s; V2: 15 V over 1 ns; I1: 0.16 A over 1 ns."""

    msl_name = "Modelica.Electrical.Analog.Examples.DifferenceAmplifier"
    stop_time = 1.0
    tolerance = 1e-06

    V1 = ExpSineVoltage(V=0.2, f=0.2e9, damping=0.1e8)
    V2 = RampVoltage(V=15.0, duration=1e-9)
    I1 = RampCurrent(I=0.16, duration=1e-9)
    R1 = Resistor(R=0.0001)
    R2 = Resistor(R=100.0)
    R3 = Resistor(R=0.0001)
    R4 = Resistor(R=100.0)
    C1 = Capacitor(C=1e-10, v={"start": 0.0, "fixed": True})
    C4 = Capacitor(C=1e-10, v={"start": 0.0, "fixed": True})
    C5 = Capacitor(C=1e-10, v={"start": 0.0, "fixed": True})
    C2 = Capacitor(C=1e-10, v={"start": 0.0, "fixed": True})
    C3 = Capacitor(C=1e-10, v={"start": 0.0, "fixed": True})
    Gnd1 = Ground()
    Gnd9 = Ground()
    Gnd3 = Ground()
    Gnd2 = Ground()
    Gnd6 = Ground()
    Gnd7 = Ground()
    Gnd8 = Ground()
    Gnd5 = Ground()
    Gnd4 = Ground()
    Transistor1 = Transistor(ct={"v": {"start": 0.0, "fixed": True}})
    Transistor2 = Transistor(ct={"v": {"start": 0.0, "fixed": True}})

    def equations(self):
        c = ac.connect
        return [c(self.V1.n, self.Gnd1.p), c(self.C1.n, self.Gnd2.p), c(self.I1.n, self.Gnd7.p),
                c(self.C5.n, self.Gnd8.p), c(self.C3.n, self.Gnd5.p), c(self.R3.n, self.Gnd4.p),
                c(self.C2.n, self.Gnd3.p), c(self.C4.p, self.Gnd6.p), c(self.I1.p, self.C5.p),
                c(self.R1.p, self.V1.p), c(self.R2.p, self.V2.p), c(self.R4.p, self.V2.p),
                c(self.V2.n, self.Gnd9.p), c(self.R1.n, self.Transistor1.b),
                c(self.Transistor1.b, self.C1.p), c(self.Transistor1.c, self.C2.p),
                c(self.R2.n, self.Transistor1.c), c(self.Transistor1.e, self.I1.p),
                c(self.Transistor2.b, self.R3.p), c(self.Transistor2.b, self.C3.p),
                c(self.C4.n, self.Transistor2.c), c(self.R4.n, self.Transistor2.c),
                c(self.C5.p, self.Transistor2.e)]


if __name__ == "__main__":
    res = ac.simulate(DifferenceAmplifier(), t_end=1.0, rtol=1e-6)
    print(f"C2.v at {res.t[-1]:g} s: {res['C2.v'][-1]:.6g} V")
