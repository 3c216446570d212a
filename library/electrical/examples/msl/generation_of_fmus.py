"""Modelica.Electrical.Analog.Examples.GenerationOfFMUs (MSL v4.0.0): circuits cut into
input/output blocks (as they would be exported as FMUs) and joined through signals,
each beside the same circuit written directly: two capacitors with a resistor between
them, driven by a sine current, and two inductors with a conductor between them,
driven by a sine voltage."""
import acausal as ac
from acausal.library.blocks import Sine
from acausal.library.electrical import (Capacitor, GeneralCurrentToVoltageAdaptor,
                                        GeneralVoltageToCurrentAdaptor, Ground, Inductor,
                                        SignalCurrent, SignalVoltage)

from .utilities import (Conductor, DirectCapacitor, DirectInductor, InverseCapacitor,
                        InverseInductor, Resistor)

__all__ = ["GenerationOfFMUs"]


class GenerationOfFMUs(ac.Component):
    """C = 1 mF and 2 mF with 10 Ohm between; L = 1 mH and 2 mH with 10 S between;
    both driven by 1 (A or V) sines of 2 Hz."""

    msl_name = "Modelica.Electrical.Analog.Examples.GenerationOfFMUs"
    msl_known_failure = (
        "alias elimination refuses two aliases with the same fixed start 0 (sympy's Zero "
        '!= 0.0)')
    stop_time = 1.0
    tolerance = 1e-06

    sine12 = Sine(f=2.0, amplitude=1.0)
    directCapacitor1 = DirectCapacitor(C=1e-3)
    inverseCapacitor1 = InverseCapacitor(C=2e-3)
    resistor2 = Resistor(R=10.0)
    capacitor2a = Capacitor(v={"start": 0.0, "fixed": True}, C=1e-3)
    current2 = SignalCurrent()
    currentToVoltage2a = GeneralCurrentToVoltageAdaptor(use_pder=False, use_fder=False)
    capacitor2b = Capacitor(v={"fixed": True, "start": 0.0}, C=2e-3)
    currentToVoltage2b = GeneralCurrentToVoltageAdaptor(use_pder=False, use_fder=False)
    ground2a = Ground()
    ground3b = Ground()
    sine34 = Sine(f=2.0, amplitude=1.0)
    directInductor3 = DirectInductor(L=1e-3)
    inverseInductor3 = InverseInductor(L=2e-3)
    voltage4 = SignalVoltage()
    ground4a = Ground()
    inductor4a = Inductor(i={"fixed": True, "start": 0.0}, L=1e-3)
    voltageToCurrent4a = GeneralVoltageToCurrentAdaptor(use_pder=False, use_fder=False)
    conductor4 = Conductor(G=10.0)
    voltageToCurrent4b = GeneralVoltageToCurrentAdaptor(use_pder=False, use_fder=False)
    inductor4b = Inductor(i={"fixed": True, "start": 0.0}, L=2e-3)
    ground4b = Ground()

    def equations(self):
        c = ac.connect
        return [c(self.sine12.y, self.directCapacitor1.iDrive),
                c(self.directCapacitor1.v, self.inverseCapacitor1.v),
                c(self.directCapacitor1.dv, self.inverseCapacitor1.dv),
                c(self.directCapacitor1.i, self.inverseCapacitor1.i),
                c(self.sine12.y, self.current2.i), c(self.current2.n, self.capacitor2a.p),
                c(self.capacitor2a.p, self.currentToVoltage2a.pin_p),
                c(self.capacitor2a.n, self.currentToVoltage2a.pin_n),
                c(self.currentToVoltage2a.p, self.resistor2.v1),
                c(self.currentToVoltage2a.f, self.resistor2.i1),
                c(self.resistor2.v2, self.currentToVoltage2b.p),
                c(self.resistor2.i2, self.currentToVoltage2b.f),
                c(self.currentToVoltage2b.pin_p, self.capacitor2b.p),
                c(self.current2.p, self.ground2a.p), c(self.ground2a.p, self.capacitor2a.n),
                c(self.currentToVoltage2b.pin_n, self.ground3b.p),
                c(self.ground3b.p, self.capacitor2b.n),
                c(self.sine34.y, self.directInductor3.vDrive),
                c(self.directInductor3.v, self.inverseInductor3.v),
                c(self.directInductor3.di, self.inverseInductor3.di),
                c(self.directInductor3.i, self.inverseInductor3.i),
                c(self.inductor4a.n, self.voltageToCurrent4a.pin_p),
                c(self.ground4a.p, self.voltageToCurrent4a.pin_n),
                c(self.voltageToCurrent4b.pin_p, self.inductor4b.p),
                c(self.voltageToCurrent4b.pin_n, self.ground4b.p),
                c(self.ground4b.p, self.inductor4b.n), c(self.sine34.y, self.voltage4.v),
                c(self.voltageToCurrent4a.f, self.conductor4.i1),
                c(self.voltageToCurrent4a.p, self.conductor4.v1),
                c(self.conductor4.v2, self.voltageToCurrent4b.p),
                c(self.conductor4.i2, self.voltageToCurrent4b.f),
                c(self.voltage4.p, self.inductor4a.p), c(self.ground4a.p, self.voltage4.n)]


if __name__ == "__main__":
    res = ac.simulate(GenerationOfFMUs(), t_end=1.0, rtol=1e-6)
    print(f"capacitor2b.v at {res.t[-1]:g} s: {res['capacitor2b.v'][-1]:.6g} V")
