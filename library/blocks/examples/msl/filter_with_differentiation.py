"""Modelica.Blocks.Examples.FilterWithDifferentiation (MSL v4.0.0): a step through a
third-order Bessel low pass (2 Hz), whose output is differentiated three times by Der
blocks: the filter's states must be differentiable that often, and index reduction
differentiates the filter's equations to get them."""
import acausal as ac
from acausal.library.blocks import Der, Filter, Step

from . import MSLNames

__all__ = ["FilterWithDifferentiation"]


class FilterWithDifferentiation(ac.Component):
    """Demonstrates the use of low pass filters to determine derivatives of filters."""

    msl_name = "Modelica.Blocks.Examples.FilterWithDifferentiation"
    stop_time = 0.9
    tolerance = 1e-6
    msl_signals = MSLNames()

    f_cut = ac.Parameter(2.0, unit="Hz", description="cut-off frequency")
    step = Step(startTime=0.1, offset=0.1)
    Bessel = Filter(analogFilter="Bessel", filterType="LowPass", order=3,
                    f_cut=ac.ref("f_cut"))
    der1 = Der()
    der2 = Der()
    der3 = Der()

    def equations(self):
        return [ac.connect(self.step.y, self.Bessel.u),
                ac.connect(self.Bessel.y, self.der1.u),
                ac.connect(self.der1.y, self.der2.u),
                ac.connect(self.der2.y, self.der3.u)]
