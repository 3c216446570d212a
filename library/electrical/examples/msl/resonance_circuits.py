"""Modelica.Electrical.Analog.Examples.ResonanceCircuits (MSL v4.0.0): a parallel
(upper) and a series (lower) resonance circuit whose elements are joined not directly
but through adaptors between pins and signals, as input/output blocks (FMUs) would
be."""
import math

import acausal as ac
from acausal.library.electrical import (Capacitor, Conductor, GeneralCurrentToVoltageAdaptor,
                                        GeneralVoltageToCurrentAdaptor, Ground, Inductor,
                                        Resistor, SineCurrent, SineVoltage)

__all__ = ["ResonanceCircuits"]

C = 0.01                                     # capacitance (F)
L = 0.01                                     # inductance (H)
fRes = 1 / (2 * math.pi * math.sqrt(L * C))  # resonance frequency (Hz)
res = 1.0                                    # f / fRes
f = res * fRes                               # source frequency (Hz)


class ResonanceCircuits(ac.Component):
    """C = L = 0.01 (F, H), the sources at the resonance frequency 1/(2 pi sqrt(L C))."""

    msl_name = "Modelica.Electrical.Analog.Examples.ResonanceCircuits"
    stop_time = 1.0
    tolerance = 1e-06

    current1 = SineCurrent(I=1.0, f=f)
    ground1 = Ground()
    inductor1 = Inductor(i={"fixed": True, "start": 0.0}, L=L)
    conductor1 = Conductor(G=1.0)
    capacitor1 = Capacitor(v={"start": 0.0, "fixed": True}, C=C)
    voltage2 = SineVoltage(V=1.0, f=f)
    ground2 = Ground()
    inductor2 = Inductor(i={"fixed": True, "start": 0.0}, L=L)
    resistor2 = Resistor(R=1.0)
    capacitor2 = Capacitor(v={"start": 0.0, "fixed": True}, C=C)
    voltageToCurrentAdaptor1a = GeneralVoltageToCurrentAdaptor(use_pder=False)
    currentToVoltageAdaptor1a = GeneralCurrentToVoltageAdaptor(use_pder=False)
    ground1a = Ground()
    currentToVoltageAdaptor1b = GeneralCurrentToVoltageAdaptor(use_pder=False)
    voltageToCurrentAdaptor1b = GeneralVoltageToCurrentAdaptor(use_pder=False)
    ground1b = Ground()
    voltageToCurrentAdaptor1c = GeneralVoltageToCurrentAdaptor(use_pder=False)
    currentToVoltageAdaptor1c = GeneralCurrentToVoltageAdaptor(use_pder=False)
    ground1c = Ground()
    currentToVoltageAdaptor2a = GeneralCurrentToVoltageAdaptor(use_fder=False)
    voltageToCurrentAdaptor2a = GeneralVoltageToCurrentAdaptor(use_fder=False)
    ground2a = Ground()
    voltageToCurrentAdaptor2b = GeneralVoltageToCurrentAdaptor(use_fder=False)
    currentToVoltageAdaptor2b = GeneralCurrentToVoltageAdaptor(use_fder=False)
    ground2b = Ground()
    currentToVoltageAdaptor2c = GeneralCurrentToVoltageAdaptor(use_fder=False)
    voltageToCurrentAdaptor2c = GeneralVoltageToCurrentAdaptor(use_fder=False)
    ground2c = Ground()

    def equations(self):
        c = ac.connect
        v1a, c1a = self.voltageToCurrentAdaptor1a, self.currentToVoltageAdaptor1a
        c1b, v1b = self.currentToVoltageAdaptor1b, self.voltageToCurrentAdaptor1b
        v1c, c1c = self.voltageToCurrentAdaptor1c, self.currentToVoltageAdaptor1c
        c2a, v2a = self.currentToVoltageAdaptor2a, self.voltageToCurrentAdaptor2a
        v2b, c2b = self.voltageToCurrentAdaptor2b, self.currentToVoltageAdaptor2b
        c2c, v2c = self.currentToVoltageAdaptor2c, self.voltageToCurrentAdaptor2c
        return [c(self.voltage2.n, self.ground2.p), c(self.ground1.p, self.current1.p),
                c(self.current1.n, v1a.pin_p), c(self.current1.p, v1a.pin_n),
                c(c1a.p, v1a.p), c(v1a.f, c1a.f), c(v1a.fder, c1a.fder),
                c(c1a.pin_p, self.inductor1.p), c(c1a.pin_n, self.inductor1.n),
                c(self.inductor1.p, c1b.pin_p), c(c1b.pin_n, self.inductor1.n),
                c(self.inductor1.n, self.ground1a.p),
                c(c1b.p, v1b.p), c(c1b.fder, v1b.fder), c(c1b.f, v1b.f),
                c(v1b.pin_p, self.conductor1.p), c(v1b.pin_n, self.conductor1.n),
                c(self.conductor1.n, self.ground1b.p), c(self.capacitor1.n, self.ground1c.p),
                c(self.conductor1.p, v1c.pin_p), c(self.conductor1.n, v1c.pin_n),
                c(v1c.p, c1c.p), c(v1c.fder, c1c.fder), c(v1c.f, c1c.f),
                c(self.capacitor1.n, c1c.pin_n), c(c1c.pin_p, self.capacitor1.p),
                c(self.voltage2.p, c2a.pin_p), c(self.voltage2.n, c2a.pin_n),
                c(v2a.pin_p, self.inductor2.p), c(c2a.p, v2a.p), c(c2a.pder, v2a.pder),
                c(c2a.f, v2a.f), c(v2b.p, c2b.p), c(v2b.pder, c2b.pder),
                c(self.inductor2.n, v2b.pin_p), c(v2a.pin_n, self.ground2a.p),
                c(self.ground2a.p, v2b.pin_n), c(v2b.f, c2b.f),
                c(self.capacitor2.n, self.ground2c.p), c(c2b.pin_p, self.resistor2.p),
                c(c2c.pin_p, self.resistor2.n), c(v2c.pin_p, self.capacitor2.p),
                c(self.capacitor2.n, v2c.pin_n), c(c2c.pin_n, self.ground2b.p),
                c(self.ground2b.p, c2b.pin_n), c(c2c.p, v2c.p), c(c2c.pder, v2c.pder),
                c(c2c.f, v2c.f)]


if __name__ == "__main__":
    result = ac.simulate(ResonanceCircuits(), t_end=1.0, rtol=1e-6)
    print(f"capacitor2.v at {result.t[-1]:g} s: {result['capacitor2.v'][-1]:.6g} V")
