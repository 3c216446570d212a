"""Modelica.Blocks.Examples.FilterWithRiseTime (MSL v4.0.0): a unit step at 1 s through
second-order critically damped low passes whose cut-off frequencies are 3, 4 and 5
over 2 pi riseTime (riseTime = 2 s): the factor sets how well each reaches the step
after riseTime."""
import math

import acausal as ac
from acausal.library.blocks import Filter, Step

from . import MSLNames

__all__ = ["FilterWithRiseTime"]


def _cut(factor):
    return ac.Parameter(lambda c: factor / (2 * math.pi * c.riseTime), unit="Hz",
                        description=f"cut-off frequency {factor}/(2 pi riseTime)")


class FilterWithRiseTime(ac.Component):
    """Demonstrates to use the rise time instead of the cut-off frequency to define a
    filter."""

    msl_name = "Modelica.Blocks.Examples.FilterWithRiseTime"
    stop_time = 4.0
    tolerance = 1e-6
    msl_signals = MSLNames()

    riseTime = ac.Parameter(2.0, unit="s", description="time to reach the step input")
    f_cut5, f_cut4, f_cut3 = _cut(5), _cut(4), _cut(3)
    filter_fac5 = Filter(order=2, f_cut=ac.ref("f_cut5"))
    step = Step(startTime=1.0)
    filter_fac4 = Filter(order=2, f_cut=ac.ref("f_cut4"))
    filter_fac3 = Filter(order=2, f_cut=ac.ref("f_cut3"))

    def equations(self):
        return [ac.connect(self.step.y, self.filter_fac5.u),
                ac.connect(self.step.y, self.filter_fac4.u),
                ac.connect(self.step.y, self.filter_fac3.u)]
