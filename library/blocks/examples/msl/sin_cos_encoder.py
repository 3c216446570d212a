"""Modelica.Blocks.Examples.SinCosEncoder (MSL v4.0.0): the four tracks of a sin-cos
encoder (cosine, minus cosine, sine, minus sine, each 1 about an offset of 1.5) at a
frequency rising as 100 t Hz; the differences are a cosine and a sine of amplitude 2,
whose phasor a controller (an integrator of gain 1e6 on the rotated phasor's imaginary
part) follows: its angle is the continuous encoder angle, its derivative 2 pi f; the
angle wrapped to ]-pi, pi], and the phasor's magnitude and angle for comparison.

No reference is available: MAP-LIB's result file of this example is absent from the
offline copy (and it has no earlier version).  ``tests/library/test_blocks_msl.py``
checks the run against the exact phase 2 pi 50 t^2 of the tracks and an independent
solution of the controller's equation.
"""
import math

import acausal as ac
from acausal.library.blocks import (CosineVariableFrequencyAndAmplitude, Der, Feedback,
                                    Integrator, Ramp, Rotator,
                                    SineVariableFrequencyAndAmplitude, ToPolar, WrapAngle)

__all__ = ["SinCosEncoder"]


class SinCosEncoder(ac.Component):
    """Evaluation of a sinusoidal encoder (StopTime 1 s, Tolerance 1e-6)."""

    stop_time = 1.0
    tolerance = 1e-6

    w = ac.Variable(unit="rad/s", description="2*pi*f")
    ramp = Ramp(height=100.0, duration=1.0, offset=0.0, startTime=0.0)
    cosB = CosineVariableFrequencyAndAmplitude(useConstantAmplitude=True, offset=1.5,
                                               phi={"fixed": True})
    cosBminus = CosineVariableFrequencyAndAmplitude(useConstantAmplitude=True,
                                                    constantAmplitude=-1.0, offset=1.5,
                                                    phi={"fixed": True})
    sinA = SineVariableFrequencyAndAmplitude(useConstantAmplitude=True, offset=1.5,
                                             phi={"fixed": True})
    sinAminus = SineVariableFrequencyAndAmplitude(useConstantAmplitude=True,
                                                  constantAmplitude=-1.0, offset=1.5,
                                                  phi={"fixed": True})
    feedbackCos = Feedback()
    feedbackSin = Feedback()
    rotator = Rotator()
    integrator = Integrator(k=1e6)
    der1 = Der()
    wrapAngle = WrapAngle(positiveRange=False)
    toPolar = ToPolar()

    def equations(self):
        c = ac.connect
        return [ac.Eq(self.w, 2 * math.pi * self.ramp.y),
                c(self.ramp.y, self.sinA.f), c(self.ramp.y, self.sinAminus.f),
                c(self.ramp.y, self.cosBminus.f), c(self.ramp.y, self.cosB.f),
                c(self.cosBminus.y, self.feedbackCos.u2), c(self.cosB.y, self.feedbackCos.u1),
                c(self.sinA.y, self.feedbackSin.u1), c(self.sinAminus.y, self.feedbackSin.u2),
                c(self.feedbackCos.y, self.rotator.u[0]),
                c(self.feedbackSin.y, self.rotator.u[1]),
                c(self.rotator.y[1], self.integrator.u),
                c(self.integrator.y, self.rotator.angle), c(self.integrator.y, self.der1.u),
                c(self.integrator.y, self.wrapAngle.u),
                c(self.feedbackCos.y, self.toPolar.u[0]),
                c(self.feedbackSin.y, self.toPolar.u[1])]


if __name__ == "__main__":
    res = ac.simulate(SinCosEncoder(), t_end=1.0, rtol=1e-6)
    print(f"integrator.y at {res.t[-1]:g} s: {res['integrator.y'][-1]:.6g} "
          f"(the tracks' phase {100 * math.pi:.6g})")
