"""Modelica.Blocks.Examples.TotalHarmonicDistortion (MSL v4.0.0): a voltage of 100 V RMS
at 50 Hz and 20 V RMS at 150 Hz, both from 0.02 s, measured and fed to two THD blocks:
relative to the first harmonic (THD = 0.2) and to the RMS (THD = 20/sqrt(100^2 + 20^2)).

The two series sine sources of the MSL (SineVoltage with startTime) are SignalVoltages
driven by Sine blocks with that start time: the electrical SineVoltage here has no
startTime.

Known to fail: before the sources start (0 .. 0.02 s) the THD blocks divide by their
limiter's lower bound (the MSL's eps = 1e-15) and acausal judges the relation u < 1e-15
at u = 0 as at its switching point: the division by 0 of the other side makes every
output of that stretch NaN, though the run succeeds (reported as a defect of the
runtime's relations; the values after 0.02 s are right).
"""
import math

import acausal as ac
from acausal.library.blocks import Sine, TotalHarmonicDistortion
from acausal.library.electrical import Ground, SignalVoltage, VoltageSensor

from . import MSLNames

__all__ = ["TotalHarmonicDistortionExample"]


class TotalHarmonicDistortionExample(ac.Component):
    """Calculation of total harmonic distortion of a voltage."""

    msl_name = "Modelica.Blocks.Examples.TotalHarmonicDistortion"
    stop_time = 0.1
    tolerance = 1e-7
    msl_signals = MSLNames()
    msl_known_failure = (
        "defect: the relation u < 1e-15 at u = 0 is judged at its switching point and "
        "the division it guards makes every output NaN before the sources start")

    f1 = ac.Parameter(50.0, unit="Hz", description="fundamental wave frequency")
    V1 = ac.Parameter(100.0, unit="V", description="fundamental wave RMS voltage")
    V3 = ac.Parameter(20.0, unit="V", description="third harmonic wave RMS voltage")
    THD1 = ac.Parameter(lambda c: c.V3 / c.V1,
                        description="THD with respect to the fundamental wave")
    THDrms = ac.Parameter(lambda c: c.V3 / ac.sqrt(c.V1**2 + c.V3**2),
                          description="THD with respect to the RMS")
    V1_peak = ac.Parameter(lambda c: math.sqrt(2) * c.V1, unit="V", description="sqrt(2) V1")
    V3_peak = ac.Parameter(lambda c: math.sqrt(2) * c.V3, unit="V", description="sqrt(2) V3")
    f3 = ac.Parameter(lambda c: 3 * c.f1, unit="Hz", description="3 f1")
    ground = Ground()
    sineVoltage3 = SignalVoltage()
    sine3 = Sine(amplitude=ac.ref("V3_peak"), f=ac.ref("f3"), startTime=0.02)
    sineVoltage1 = SignalVoltage()
    sine1 = Sine(amplitude=ac.ref("V1_peak"), f=ac.ref("f1"), startTime=0.02)
    voltageSensor = VoltageSensor()
    thd1 = TotalHarmonicDistortion(f=ac.ref("f1"))
    thdRMS = TotalHarmonicDistortion(f=ac.ref("f1"), useFirstHarmonic=False)

    def equations(self):
        return [ac.connect(self.sine3.y, self.sineVoltage3.v),
                ac.connect(self.sine1.y, self.sineVoltage1.v),
                ac.connect(self.voltageSensor.p, self.sineVoltage3.p),
                ac.connect(self.sineVoltage3.n, self.sineVoltage1.p),
                ac.connect(self.sineVoltage1.n, self.ground.p),
                ac.connect(self.ground.p, self.voltageSensor.n),
                ac.connect(self.thd1.u, self.voltageSensor.v),
                ac.connect(self.voltageSensor.v, self.thdRMS.u)]
