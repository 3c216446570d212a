"""Modelica.Electrical.Analog.Examples.ParallelResonance (MSL v4.0.0): a parallel R-L-C
circuit (resonance at 100 Hz) driven by a sine (upper) and a cosine (lower) current of
1 A whose frequency a ramp sweeps from 0 to 200 Hz in 1 s."""
import math

import acausal as ac
from acausal.library.blocks import Ramp
from acausal.library.electrical import (Capacitor, CosineCurrentVariableFrequencyAndAmplitude,
                                        Ground, Inductor, Resistor,
                                        SineCurrentVariableFrequencyAndAmplitude, VoltageSensor)

__all__ = ["ParallelResonance"]


class ParallelResonance(ac.Component):
    """R = 0.5 Ohm in series with L = 0.1/(2 pi) H, C = 0.001/(2 pi) F in parallel."""

    msl_name = "Modelica.Electrical.Analog.Examples.ParallelResonance"
    stop_time = 1.0
    tolerance = 1e-6

    sineCurrent = SineCurrentVariableFrequencyAndAmplitude(useConstantAmplitude=True,
                                                           phi={"fixed": True})
    ground1 = Ground()
    resistor1 = Resistor(R=0.5)
    inductor1 = Inductor(i={"fixed": True}, L=0.1 / (2 * math.pi))
    capacitor1 = Capacitor(v={"fixed": True}, C=0.001 / (2 * math.pi))
    voltageSensor1 = VoltageSensor()
    ramp = Ramp(height=200.0, duration=1.0, offset=0.0, startTime=0.0)
    cosineCurrent = CosineCurrentVariableFrequencyAndAmplitude(useConstantAmplitude=True,
                                                               phi={"fixed": True})
    ground2 = Ground()
    resistor2 = Resistor(R=0.5)
    inductor2 = Inductor(i={"fixed": True}, L=0.1 / (2 * math.pi))
    capacitor2 = Capacitor(v={"fixed": True}, C=0.001 / (2 * math.pi))
    voltageSensor2 = VoltageSensor()

    def equations(self):
        c = ac.connect
        return [c(self.sineCurrent.p, self.ground1.p), c(self.ground1.p, self.inductor1.n),
                c(self.resistor1.n, self.inductor1.p), c(self.ground1.p, self.capacitor1.n),
                c(self.ground1.p, self.voltageSensor1.n),
                c(self.sineCurrent.n, self.resistor1.p),
                c(self.sineCurrent.n, self.capacitor1.p),
                c(self.sineCurrent.n, self.voltageSensor1.p),
                c(self.ramp.y, self.sineCurrent.f),
                c(self.cosineCurrent.p, self.ground2.p), c(self.ground2.p, self.inductor2.n),
                c(self.resistor2.n, self.inductor2.p), c(self.ground2.p, self.capacitor2.n),
                c(self.ground2.p, self.voltageSensor2.n),
                c(self.cosineCurrent.n, self.resistor2.p),
                c(self.cosineCurrent.n, self.capacitor2.p),
                c(self.cosineCurrent.n, self.voltageSensor2.p),
                c(self.ramp.y, self.cosineCurrent.f)]


if __name__ == "__main__":
    res = ac.simulate(ParallelResonance(), t_end=1.0, rtol=1e-6)
    print(f"capacitor1.v at {res.t[-1]:g} s: {res['capacitor1.v'][-1]:.6g} V")
