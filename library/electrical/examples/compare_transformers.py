"""Modelica.Electrical.Analog.Examples.CompareTransformers (MSL v4.0.0): a transformer
of two coupled inductors (Basic.Transformer) beside an ideal transformer between
leakage inductances (Ideal.IdealTransformer without magnetization), both fed by a sine
with a DC offset through the primary resistance and loaded by RL.

MAP-LIB's reference of this example is not available here (its result file is missing
from the archive), so it is checked against an independent solution of its equations
(``tests/library/test_electrical_examples.py``)."""
import math

import acausal as ac
from acausal.library.electrical import (Ground, IdealTransformer, Inductor, Resistor,
                                        SineVoltage, Transformer)

__all__ = ["CompareTransformers"]

Vdc = 0.1                              # DC offset of the source (V)
Vpeak = 0.1                            # peak of the source (V)
f = 10.0                               # frequency (Hz)
phi0 = math.pi / 2                     # phase of the source (rad)
n = 2.0                                # turns ratio
R1 = 0.01                              # primary resistance (Ohm)
L1sigma = 0.05 / (2 * math.pi * f)     # primary leakage inductance (H)
Lm1 = 10.0 / (2 * math.pi * f)         # magnetizing inductance, primary side (H)
L2sigma = 0.05 / (2 * math.pi * f) / n**2
R2 = 0.01 / n**2
RL = 1 / n**2                          # load resistance (Ohm)
M = Lm1 / n                            # mutual inductance (H)
L1 = L1sigma + M * n                   # primary no-load inductance (H)
L2 = L2sigma + M / n                   # secondary no-load inductance (H)


class CompareTransformers(ac.Component):
    """The MSL's parameters; its outputs v1B ... i2I are read as resistor11.n.v etc."""

    stop_time = 50.0
    tolerance = 1e-6

    sineVoltage1 = SineVoltage(V=Vpeak, phase=phi0, f=f, offset=Vdc)
    ground11 = Ground()
    resistor11 = Resistor(R=R1)
    resistor12 = Resistor(R=R2)
    load1 = Resistor(R=RL)
    ground12 = Ground()
    sineVoltage2 = SineVoltage(V=Vpeak, phase=phi0, f=f, offset=Vdc)
    ground21 = Ground()
    resistor21 = Resistor(R=R1)
    inductor21 = Inductor(L=L1sigma)
    inductor22 = Inductor(L=L2sigma, i={"start": 0.0, "fixed": True})
    resistor22 = Resistor(R=R2)
    load2 = Resistor(R=RL)
    ground22 = Ground()
    basicTransformer = Transformer(L1=L1, L2=L2, M=M)
    idealTransformer = IdealTransformer(n=n, Lm1=Lm1, considerMagnetization=False)

    def initial_equations(self):
        return [ac.Eq(self.basicTransformer.i1, 0), ac.Eq(self.basicTransformer.i2, 0)]

    def equations(self):
        c = ac.connect
        return [c(self.sineVoltage1.n, self.ground11.p), c(self.sineVoltage1.p, self.resistor11.p),
                c(self.resistor11.n, self.basicTransformer.p1),
                c(self.basicTransformer.n1, self.ground11.p),
                c(self.basicTransformer.p2, self.resistor12.p),
                c(self.basicTransformer.n2, self.ground12.p),
                c(self.load1.n, self.ground12.p), c(self.resistor12.n, self.load1.p),
                c(self.sineVoltage2.n, self.ground21.p), c(self.sineVoltage2.p, self.resistor21.p),
                c(self.resistor21.n, self.inductor21.p),
                c(self.inductor21.n, self.idealTransformer.p1),
                c(self.idealTransformer.n1, self.ground21.p),
                c(self.idealTransformer.p2, self.inductor22.p),
                c(self.idealTransformer.n2, self.ground22.p),
                c(self.inductor22.n, self.resistor22.p), c(self.load2.n, self.ground22.p),
                c(self.resistor22.n, self.load2.p)]


if __name__ == "__main__":
    res = ac.simulate(CompareTransformers(), t_end=CompareTransformers.stop_time, rtol=1e-6)
    print(f"basicTransformer.i2 at {res.t[-1]:g} s: {res['basicTransformer.i2'][-1]:.6g} A")
