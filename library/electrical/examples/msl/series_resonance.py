"""Modelica.Electrical.Analog.Examples.SeriesResonance (MSL v4.0.0): a series R-L-C
circuit (resonance at 100 Hz) driven by a sine (upper) and a cosine (lower) voltage of
1 V whose frequency a ramp sweeps from 0 to 200 Hz in 1 s."""
import math

import acausal as ac
from acausal.library.blocks import Ramp
from acausal.library.electrical import (Capacitor, CosineVoltageVariableFrequencyAndAmplitude,
                                        CurrentSensor, Ground, Inductor, Resistor,
                                        SineVoltageVariableFrequencyAndAmplitude)

__all__ = ["SeriesResonance"]


class SeriesResonance(ac.Component):
    """R = 0.5 Ohm, L = 0.1/(2 pi) H, C = 0.001/(2 pi) F."""

    msl_name = "Modelica.Electrical.Analog.Examples.SeriesResonance"
    stop_time = 1.0
    tolerance = 1e-6

    sineVoltage = SineVoltageVariableFrequencyAndAmplitude(useConstantAmplitude=True,
                                                           phi={"fixed": True})
    ground1 = Ground()
    resistor1 = Resistor(R=0.5)
    inductor1 = Inductor(i={"fixed": True}, L=0.1 / (2 * math.pi))
    capacitor1 = Capacitor(v={"fixed": True}, C=0.001 / (2 * math.pi))
    currentSensor1 = CurrentSensor()
    ramp = Ramp(height=200.0, duration=1.0, offset=0.0, startTime=0.0)
    cosineVoltage = CosineVoltageVariableFrequencyAndAmplitude(useConstantAmplitude=True,
                                                               phi={"fixed": True})
    ground2 = Ground()
    resistor2 = Resistor(R=0.5)
    inductor2 = Inductor(i={"fixed": True}, L=0.1 / (2 * math.pi))
    capacitor2 = Capacitor(v={"fixed": True}, C=0.001 / (2 * math.pi))
    currentSensor2 = CurrentSensor()

    def equations(self):
        c = ac.connect
        return [c(self.sineVoltage.p, self.inductor1.p), c(self.inductor1.n, self.capacitor1.p),
                c(self.capacitor1.n, self.resistor1.p), c(self.sineVoltage.n, self.ground1.p),
                c(self.currentSensor1.p, self.resistor1.n),
                c(self.ground1.p, self.currentSensor1.n),
                c(self.ramp.y, self.sineVoltage.f),
                c(self.cosineVoltage.p, self.inductor2.p),
                c(self.inductor2.n, self.capacitor2.p), c(self.capacitor2.n, self.resistor2.p),
                c(self.cosineVoltage.n, self.ground2.p),
                c(self.currentSensor2.p, self.resistor2.n),
                c(self.ground2.p, self.currentSensor2.n),
                c(self.ramp.y, self.cosineVoltage.f)]


if __name__ == "__main__":
    res = ac.simulate(SeriesResonance(), t_end=1.0, rtol=1e-6)
    print(f"inductor1.i at {res.t[-1]:g} s: {res['inductor1.i'][-1]:.6g} A")
