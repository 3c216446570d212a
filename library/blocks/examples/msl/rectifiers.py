"""Modelica.Blocks.Examples.Rectifier6pulseFFT and Rectifier12pulseFFT (MSL v4.0.0), and the
examples they extend, Modelica.Electrical.Machines.Examples.Transformers.Rectifier6pulse
and Rectifier12pulse: a star-connected three-phase source (100 sqrt(2/3) V, 50 Hz) feeds
through a Dy1 transformer (and, for 12 pulses, a Dd0 one in parallel) diode bridges into
two DC capacitors and a load; the FFT examples sample the source's first phase current
from 0.04 s (f_max = 2000 Hz, f_res = 5 Hz: 4000 samples every 50 us).

The capacitors start at half of sqrt(3) V each and the transformers' secondary currents
at 0, as the MSL's initial equations say (``transformer1.i2[1:2] = 0``; for the Dd0, its
core's primary pin currents).  The FFT is computed from the run
(``realFFT.spectrum(res)``, ``realFFT.write(res, path)``: the MSL writes it to
``resultFileName`` when the simulation terminates).
"""
import math

import acausal as ac
from acausal.library.blocks.fft import RealFFT
from acausal.library.electrical import Capacitor, Ground, Resistor
from acausal.library.electrical import multiphase as mp
from acausal.library.electrical.transformers import Dd00, Dy01, TransformerData

from . import MSLNames

__all__ = ["Rectifier6pulse", "Rectifier12pulse", "Rectifier6pulseFFT", "Rectifier12pulseFFT"]


def _transformer(cls, data):
    """A transformer of the vector group ``cls`` with the impedances of ``data``, its
    resistances at 20 degC with no temperature coefficient (alpha20Zero)."""
    return cls(n=data.n, R1=data.R1, L1sigma=data.L1sigma, R2=data.R2, L2sigma=data.L2sigma,
               T1Ref=293.15, alpha20_1=0.0, T2Ref=293.15, alpha20_2=0.0,
               T1Operational=293.15, T2Operational=293.15)


transformerData1 = TransformerData(C1=Dy01.VectorGroup[0], C2=Dy01.VectorGroup[1], f=50,
                                   V1=100, V2=100, SNominal=30e3, v_sc=0.05, P_sc=300)
transformerData2 = TransformerData(C1=Dd00.VectorGroup[0], C2=Dd00.VectorGroup[1], f=50,
                                   V1=100, V2=100, SNominal=30e3, v_sc=0.05, P_sc=300)
m = 3                        # number of phases


def _diode():
    return mp.IdealDiode(m=m, Ron=1e-5, Goff=1e-5, Vknee=0.0)


class Rectifier6pulse(ac.Component):
    """6-pulse rectifier with 1 transformer."""

    msl_name = "Modelica.Electrical.Machines.Examples.Transformers.Rectifier6pulse"
    stop_time = 0.1
    tolerance = 1e-7
    msl_signals = MSLNames()

    V = ac.Parameter(100 * math.sqrt(2 / 3), unit="V", description="amplitude of "
                                                                   "star-voltage")
    f = ac.Parameter(50.0, unit="Hz", description="frequency")
    RL = ac.Parameter(0.4, unit="Ohm", description="load resistance")
    C = ac.Parameter(0.005, unit="F", description="total DC-capacitance")
    VC0 = ac.Parameter(lambda c: math.sqrt(3) * c.V, unit="V",
                       description="initial voltage of capacitance")
    C_half = ac.Parameter(lambda c: 2 * c.C, unit="F", description="2 C")
    source = mp.SineVoltage(m=m, V=ac.ref("V"), f=ac.ref("f"))
    starAC = mp.Star(m=m)
    groundAC = Ground()
    currentSensor = mp.CurrentSensor(m=m)
    diode1 = _diode()
    star1 = mp.Star(m=m)
    diode2 = _diode()
    star2 = mp.Star(m=m)
    load = Resistor(R=ac.ref("RL"))
    cDC1 = Capacitor(C=ac.ref("C_half"))
    cDC2 = Capacitor(C=ac.ref("C_half"))
    groundDC = Ground()
    transformer1 = _transformer(Dy01, transformerData1)

    def initial_equations(self):
        return [ac.Eq(self.cDC1.v, self.VC0 / 2), ac.Eq(self.cDC2.v, self.VC0 / 2),
                ac.Eq(self.transformer1.i2[0], 0), ac.Eq(self.transformer1.i2[1], 0)]

    def equations(self):
        c = ac.connect
        return [c(self.cDC1.n, self.cDC2.p), c(self.cDC1.n, self.groundDC.p),
                c(self.starAC.plug_p, self.source.plug_n),
                c(self.diode1.plug_n, self.star1.plug_p),
                c(self.diode2.plug_p, self.star2.plug_p),
                c(self.diode2.plug_n, self.diode1.plug_p),
                c(self.starAC.pin_n, self.groundAC.p),
                c(self.source.plug_p, self.currentSensor.plug_p),
                c(self.load.p, self.cDC1.p), c(self.load.n, self.cDC2.n),
                c(self.star1.pin_n, self.cDC1.p), c(self.star2.pin_n, self.cDC2.n),
                c(self.transformer1.plug1, self.currentSensor.plug_n),
                c(self.transformer1.plug2, self.diode1.plug_p)]


class Rectifier12pulse(Rectifier6pulse):
    """12-pulse rectifier with 2 transformers (a Dd0 beside the Dy1, its bridge in
    parallel; the load 0.2 Ohm)."""

    msl_name = "Modelica.Electrical.Machines.Examples.Transformers.Rectifier12pulse"
    stop_time = 0.1
    tolerance = 1e-7
    msl_signals = MSLNames()

    RL = ac.Parameter(0.2, unit="Ohm", description="load resistance")
    diode3 = _diode()
    star3 = mp.Star(m=m)
    diode4 = _diode()
    star4 = mp.Star(m=m)
    transformer2 = _transformer(Dd00, transformerData2)

    def initial_equations(self):
        return [ac.Eq(pin.i, 0) for pin in self.transformer2.core.plug_p1.pin]

    def equations(self):
        c = ac.connect
        return [c(self.diode3.plug_n, self.star3.plug_p),
                c(self.diode4.plug_p, self.star4.plug_p),
                c(self.diode4.plug_n, self.diode3.plug_p),
                c(self.star4.pin_n, self.cDC2.n), c(self.star3.pin_n, self.cDC1.p),
                c(self.transformer2.plug2, self.diode4.plug_n),
                c(self.transformer2.plug1, self.currentSensor.plug_n)]


class Rectifier6pulseFFT(Rectifier6pulse):
    """Example of FFT block: the 6-pulse rectifier's first phase current sampled."""

    msl_name = "Modelica.Blocks.Examples.Rectifier6pulseFFT"
    stop_time = 0.25
    tolerance = 1e-6
    msl_signals = MSLNames()

    realFFT = RealFFT(startTime=0.04, f_max=2000.0, f_res=5.0)

    def equations(self):
        return [ac.connect(self.currentSensor.i[0], self.realFFT.u)]


class Rectifier12pulseFFT(Rectifier12pulse):
    """Example of FFT block: the 12-pulse rectifier's first phase current sampled."""

    msl_name = "Modelica.Blocks.Examples.Rectifier12pulseFFT"
    stop_time = 0.25
    tolerance = 1e-6
    msl_signals = MSLNames()

    realFFT = RealFFT(startTime=0.04, f_max=2000.0, f_res=5.0)

    def equations(self):
        return [ac.connect(self.currentSensor.i[0], self.realFFT.u)]


if __name__ == "__main__":
    model = Rectifier6pulseFFT()
    res = ac.simulate(model, t_end=Rectifier6pulseFFT.stop_time, rtol=1e-6)
    info, amplitudes, _ = model.realFFT.spectrum(res)
    print(f"the source current's fundamental (50 Hz): {amplitudes[10]:.4g} A")
