"""Modelica.Blocks.Examples.Modulation (MSL v4.0.0): a 100 Hz sine, its amplitude
modulated (1 + 0.5 sin(2 pi 2 t)) as a sine and a cosine, and its frequency modulated
(100 + 50 sin(2 pi 2 t) Hz) as a sine and a cosine; each integrates its phase from 0."""
import acausal as ac
from acausal.library.blocks import (CosineVariableFrequencyAndAmplitude, Sine,
                                    SineVariableFrequencyAndAmplitude)

from . import MSLNames

__all__ = ["Modulation"]

_PHASE = {"phi": {"fixed": True}}


class Modulation(ac.Component):
    """Demonstrate amplitude modulation and frequency modulation."""

    msl_name = "Modelica.Blocks.Examples.Modulation"
    stop_time = 1.0
    tolerance = 1e-6
    msl_signals = MSLNames()

    sine = SineVariableFrequencyAndAmplitude(useConstantAmplitude=True,
                                             useConstantFrequency=True,
                                             constantFrequency=100.0, **_PHASE)
    amplitude = Sine(amplitude=0.5, f=2.0, offset=1.0)
    sinAM = SineVariableFrequencyAndAmplitude(useConstantAmplitude=False,
                                              useConstantFrequency=True,
                                              constantFrequency=100.0, **_PHASE)
    cosAM = CosineVariableFrequencyAndAmplitude(useConstantAmplitude=False,
                                                useConstantFrequency=True,
                                                constantFrequency=100.0, **_PHASE)
    frequency = Sine(amplitude=50.0, f=2.0, offset=100.0)
    sinFM = SineVariableFrequencyAndAmplitude(useConstantAmplitude=True,
                                              useConstantFrequency=False,
                                              constantFrequency=100.0, **_PHASE)
    cosFM = CosineVariableFrequencyAndAmplitude(useConstantAmplitude=True,
                                                useConstantFrequency=False,
                                                constantFrequency=100.0, **_PHASE)

    def equations(self):
        return [ac.connect(self.amplitude.y, self.sinAM.amplitude),
                ac.connect(self.frequency.y, self.sinFM.f),
                ac.connect(self.amplitude.y, self.cosAM.amplitude),
                ac.connect(self.frequency.y, self.cosFM.f)]
