"""Modelica.Blocks.Examples.InverseModel (MSL v4.0.0): the inverse of a first-order lag
(T = 0.3 s) computes the input that makes the lag's output follow a sine (2 Hz, offset
1, from 0.2 s) smoothed by a first-order critically damped filter (100 Hz); fed to a
second, ordinary, lag, that input reproduces the filtered sine.

Both lags start in steady state (the MSL's initType = SteadyState): the model's
initial equations der(firstOrder1.x) = 0 and der(firstOrder2.x) = 0.  firstOrder1's
output is the filter's, through the inverse, so its steady state starts the filter in
steady state too.
"""
import acausal as ac
from acausal.library.blocks import (CriticalDamping, Feedback, FirstOrder,
                                    InverseBlockConstraints, Sine)

from . import MSLNames

__all__ = ["InverseModel"]


class InverseModel(ac.Component):
    """Demonstrates the construction of an inverse model."""

    msl_name = "Modelica.Blocks.Examples.InverseModel"
    stop_time = 1.0
    tolerance = 1e-6
    msl_signals = MSLNames()

    firstOrder1 = FirstOrder(k=1.0, T=0.3)
    sine = Sine(f=2.0, offset=1.0, startTime=0.2)
    inverseBlockConstraints = InverseBlockConstraints()
    firstOrder2 = FirstOrder(k=1.0, T=0.3)
    feedback = Feedback()
    criticalDamping = CriticalDamping(n=1, f=100.0)

    def initial_equations(self):
        return [ac.Eq(ac.der(self.firstOrder1.x), 0), ac.Eq(ac.der(self.firstOrder2.x), 0)]

    def equations(self):
        return [ac.connect(self.firstOrder1.y, self.inverseBlockConstraints.u2),
                ac.connect(self.inverseBlockConstraints.y2, self.firstOrder1.u),
                ac.connect(self.firstOrder2.y, self.feedback.u1),
                ac.connect(self.sine.y, self.criticalDamping.u),
                ac.connect(self.criticalDamping.y, self.inverseBlockConstraints.u1),
                ac.connect(self.sine.y, self.feedback.u2),
                ac.connect(self.inverseBlockConstraints.y1, self.firstOrder2.u)]
