"""Modelica.Blocks.Examples.SlewRateLimiter (MSL v4.0.0): a unit step at 0.1 s smoothed
by two slew-rate limiters in series: the first limits the speed (2 per second) of the
position, its derivative (Der) is limited in acceleration (20 per second squared) by the
second, whose output is integrated back to a smoothed position."""
import acausal as ac
from acausal.library.blocks import Der, Integrator, SlewRateLimiter, Step

from . import MSLNames

__all__ = ["SlewRateLimiterExample"]


class SlewRateLimiterExample(ac.Component):
    """Demonstrate usage of Nonlinear.SlewRateLimiter (the limiters and the integrator
    start from their y_start, the MSL's initType = InitialOutput: here their states'
    start values)."""

    msl_name = "Modelica.Blocks.Examples.SlewRateLimiter"
    stop_time = 1.0
    tolerance = 1e-6
    msl_signals = MSLNames()

    vMax = ac.Parameter(2.0, unit="m/s", description="maximum velocity")
    aMax = ac.Parameter(20.0, unit="m/s2", description="maximum acceleration")
    s = ac.Variable(unit="m", description="reference position")
    sSmoothed = ac.Variable(unit="m", description="smoothed position")
    vLimited = ac.Variable(unit="m/s", description="limited velocity")
    aLimited = ac.Variable(unit="m/s2", description="limited acceleration")
    positionStep = Step(startTime=0.1)
    limit_v = SlewRateLimiter(Rising=ac.ref("vMax"), Td=0.0001, x=0.0)
    v = Der()
    limit_a = SlewRateLimiter(Rising=20.0, Td=0.0001, x=0.0)
    positionSmoothed = Integrator(k=1.0, x=0.0)
    a = Der()

    def equations(self):
        return [ac.Eq(self.s, self.positionStep.y), ac.Eq(self.sSmoothed, self.positionSmoothed.y),
                ac.Eq(self.vLimited, self.limit_a.y), ac.Eq(self.aLimited, self.a.y),
                ac.connect(self.positionStep.y, self.limit_v.u),
                ac.connect(self.limit_v.y, self.v.u),
                ac.connect(self.v.y, self.limit_a.u),
                ac.connect(self.limit_a.y, self.positionSmoothed.u),
                ac.connect(self.limit_a.y, self.a.u)]
