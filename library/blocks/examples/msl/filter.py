"""Modelica.Blocks.Examples.Filter (MSL v4.0.0): a step from 0.1 to 1.1 at 0.1 s through
third-order low pass filters of the four kinds (CriticalDamping, Bessel, Butterworth,
ChebyshevI), cut-off 2 Hz, normalized, started in steady state."""
import acausal as ac
from acausal.library.blocks import Filter, Step

from . import MSLNames

__all__ = ["FilterExample"]


def _filter(kind):
    return Filter(analogFilter=kind, filterType="LowPass", order=3, normalized=True,
                  f_cut=ac.ref("f_cut"), f_min=ac.ref("f_min"))


class FilterExample(ac.Component):
    """Demonstrates the Continuous.Filter block with various options."""

    msl_name = "Modelica.Blocks.Examples.Filter"
    stop_time = 0.9
    tolerance = 1e-6
    msl_signals = MSLNames()

    f_cut = ac.Parameter(2.0, unit="Hz", description="cut-off frequency")
    f_min = ac.Parameter(lambda c: 0.8 * c.f_cut, unit="Hz",
                         description="lower end of the band of band filters")
    step = Step(startTime=0.1, offset=0.1)
    CriticalDamping = _filter("CriticalDamping")
    Bessel = _filter("Bessel")
    Butterworth = _filter("Butterworth")
    ChebyshevI = _filter("ChebyshevI")

    def equations(self):
        return [ac.connect(self.step.y, self.CriticalDamping.u),
                ac.connect(self.step.y, self.Bessel.u),
                ac.connect(self.Butterworth.u, self.step.y),
                ac.connect(self.ChebyshevI.u, self.step.y)]
