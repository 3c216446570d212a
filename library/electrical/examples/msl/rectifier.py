"""Modelica.Electrical.Analog.Examples.Rectifier (MSL v4.0.0): a B6 diode bridge of
ideal diodes fed from a three-phase 400 V, 50 Hz supply through line inductors,
charging two DC capacitors in series loaded by a constant 500 A current."""
import math

import acausal as ac
from acausal.library.blocks import Constant
from acausal.library.electrical import (Capacitor, Ground, IdealDiode, Inductor,
                                        SignalCurrent, SineVoltage)

__all__ = ["Rectifier"]

VAC = 400.0          # RMS line-to-line (V)
f = 50.0             # line frequency (Hz)
LAC = 60e-6          # line inductor (H)
Ron = 1e-3           # diode forward resistance (Ohm)
Goff = 1e-3          # diode backward conductance (S)
Vknee = 2.0          # diode threshold voltage (V)
CDC = 15e-3          # DC capacitance (F)
IDC = 500.0          # load current (A)


def _diode():
    return IdealDiode(Ron=Ron, Goff=Goff, Vknee=Vknee)


class Rectifier(ac.Component):
    """VAC = 400 V, f = 50 Hz, LAC = 60 uH, Ron = 1 mOhm, Goff = 1 mS, Vknee = 2 V,
    CDC = 15 mF, IDC = 500 A; the outputs uDC, iAC, uAC and Losses as in the MSL."""

    msl_name = "Modelica.Electrical.Analog.Examples.Rectifier"
    stop_time = 0.1
    tolerance = 1e-6

    uDC = ac.Variable(unit="V", description="DC voltage")
    iAC = ac.Variable(shape=3, unit="A", description="line currents")
    uAC = ac.Variable(shape=3, unit="V", description="line-to-line voltages")
    Losses = ac.Variable(unit="W", description="losses of the diodes")
    SineVoltage1 = SineVoltage(f=f, V=VAC * math.sqrt(2 / 3))
    SineVoltage2 = SineVoltage(f=f, phase=-2 / 3 * math.pi, V=VAC * math.sqrt(2 / 3))
    SineVoltage3 = SineVoltage(f=f, phase=-4 / 3 * math.pi, V=VAC * math.sqrt(2 / 3))
    Inductor1 = Inductor(L=LAC)
    Inductor2 = Inductor(L=LAC, i={"start": 0.0, "fixed": True})
    Inductor3 = Inductor(L=LAC, i={"start": 0.0, "fixed": True})
    IdealDiode1 = _diode()
    IdealDiode2 = _diode()
    IdealDiode3 = _diode()
    IdealDiode4 = _diode()
    IdealDiode5 = _diode()
    IdealDiode6 = _diode()
    Capacitor1 = Capacitor(C=2 * CDC)
    Capacitor2 = Capacitor(C=2 * CDC)
    Ground1 = Ground()
    SignalCurrent1 = SignalCurrent()
    Constant1 = Constant(k=IDC)

    def initial_equations(self):
        return [ac.Eq(self.Capacitor1.v, VAC * math.sqrt(2) / 2),
                ac.Eq(self.Capacitor2.v, VAC * math.sqrt(2) / 2)]

    def equations(self):
        c = ac.connect
        diodes = [self.IdealDiode1, self.IdealDiode2, self.IdealDiode3, self.IdealDiode4,
                  self.IdealDiode5, self.IdealDiode6]
        L = [self.Inductor1, self.Inductor2, self.Inductor3]
        return [ac.Eq(self.uDC, self.Capacitor1.v + self.Capacitor2.v),
                *(ac.Eq(self.iAC[k], L[k].i) for k in range(3)),
                *(ac.Eq(self.uAC[k], L[k].n.v - L[(k + 1) % 3].n.v) for k in range(3)),
                ac.Eq(self.Losses, sum(d.v * d.i for d in diodes)),
                c(self.SineVoltage1.n, self.SineVoltage2.n),
                c(self.SineVoltage2.n, self.SineVoltage3.n),
                c(self.SineVoltage1.p, self.Inductor1.p),
                c(self.SineVoltage2.p, self.Inductor2.p),
                c(self.SineVoltage3.p, self.Inductor3.p),
                c(self.IdealDiode1.p, self.IdealDiode4.n),
                c(self.IdealDiode2.p, self.IdealDiode5.n),
                c(self.IdealDiode3.p, self.IdealDiode6.n),
                c(self.IdealDiode1.n, self.IdealDiode2.n),
                c(self.IdealDiode2.n, self.IdealDiode3.n),
                c(self.IdealDiode4.p, self.IdealDiode5.p),
                c(self.IdealDiode5.p, self.IdealDiode6.p),
                c(self.Capacitor2.n, self.IdealDiode6.p),
                c(self.IdealDiode3.n, self.Capacitor1.p),
                c(self.Capacitor1.n, self.Capacitor2.p),
                c(self.Capacitor2.p, self.Ground1.p),
                c(self.Capacitor1.p, self.SignalCurrent1.p),
                c(self.SignalCurrent1.n, self.Capacitor2.n),
                c(self.Constant1.y, self.SignalCurrent1.i),
                c(self.Inductor1.n, self.IdealDiode1.p),
                c(self.Inductor2.n, self.IdealDiode2.p),
                c(self.Inductor3.n, self.IdealDiode3.p)]


if __name__ == "__main__":
    res = ac.simulate(Rectifier(), t_end=Rectifier.stop_time, rtol=Rectifier.tolerance)
    print(f"uDC at {res.t[-1]:g} s: {res['uDC'][-1]:.6g} V")
