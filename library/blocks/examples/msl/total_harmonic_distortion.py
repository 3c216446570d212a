"""Modelica.Blocks.Examples.TotalHarmonicDistortion (MSL v4.0.0): a voltage of 100 V RMS
at 50 Hz and 20 V RMS at 150 Hz, both from 0.02 s, measured and fed to two THD blocks:
relative to the first harmonic (THD = 0.2) and to the RMS (THD = 20/sqrt(100^2 + 20^2)).

The two series sine sources of the MSL are its SineVoltage sources with a start time.
Until the first full period after the sources start (0 .. 0.04 s) the THD blocks'
limiter input is 0, and its relation u < eps (2.2e-16) holds there: the side its value
says.
"""
import math

import acausal as ac
from acausal.library.blocks import TotalHarmonicDistortion
from acausal.library.electrical import Ground, SineVoltage, VoltageSensor

from . import MSLNames

__all__ = ["TotalHarmonicDistortionExample"]


class TotalHarmonicDistortionExample(ac.Component):
    """Calculation of total harmonic distortion of voltage."""

    msl_name = "Modelica.Blocks.Examples.TotalHarmonicDistortion"
    stop_time = 0.1
    tolerance = 1e-7
    msl_signals = MSLNames()

    f1 = ac.Parameter(50.0, unit="Hz", description="fundamental wave frequency")
    V1 = ac.Parameter(100.0, unit="V", description="fundamental wave RMS voltage")
    V3 = ac.Parameter(20.0, unit="V", description="third harmonic wave RMS voltage")
    THD1 = ac.Parameter(lambda c: c.V3 / c.V1,
                        description="theoretically obtained THD with respect to fundamental "
                                    "wave")
    THDrms = ac.Parameter(lambda c: c.V3 / ac.sqrt(c.V1**2 + c.V3**2),
                          description="theoretically obtained THD with respect to RMS")
    V1_peak = ac.Parameter(lambda c: math.sqrt(2) * c.V1, unit="V", description="sqrt(2) V1")
    V3_peak = ac.Parameter(lambda c: math.sqrt(2) * c.V3, unit="V", description="sqrt(2) V3")
    f3 = ac.Parameter(lambda c: 3 * c.f1, unit="Hz", description="3 f1")
    ground = Ground()
    sineVoltage3 = SineVoltage(V=ac.ref("V3_peak"), f=ac.ref("f3"), startTime=0.02)
    sineVoltage1 = SineVoltage(V=ac.ref("V1_peak"), f=ac.ref("f1"), startTime=0.02)
    voltageSensor = VoltageSensor()
    thd1 = TotalHarmonicDistortion(f=ac.ref("f1"))
    thdRMS = TotalHarmonicDistortion(f=ac.ref("f1"), useFirstHarmonic=False)

    def equations(self):
        return [ac.connect(self.voltageSensor.p, self.sineVoltage3.p),
                ac.connect(self.sineVoltage3.n, self.sineVoltage1.p),
                ac.connect(self.sineVoltage1.n, self.ground.p),
                ac.connect(self.ground.p, self.voltageSensor.n),
                ac.connect(self.thd1.u, self.voltageSensor.v),
                ac.connect(self.voltageSensor.v, self.thdRMS.u)]


if __name__ == "__main__":
    res = ac.simulate(TotalHarmonicDistortionExample(), t_end=0.1, rtol=1e-7)
    print(f"thd1.y at {res.t[-1]:g} s: {res['thd1.y'][-1]:.6g} (0.2 expected)")
