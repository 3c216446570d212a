"""A signal source the DC machine examples use that the blocks library does not have
yet: Modelica.Blocks.Sources.Exponentials (MSL v4.0.0)."""
import acausal as ac
from acausal.library.blocks.interfaces import SignalSource

__all__ = ["Exponentials"]


class Exponentials(SignalSource):
    """A rising exponential followed by a falling one (Modelica.Blocks.Sources.
    Exponentials):

        y_riseTime = outMax (1 - exp(-riseTime/riseTimeConst))
        y = offset                                                     (time < startTime)
        y = offset + outMax (1 - exp(-(time - startTime)/riseTimeConst))
                                                        (time < startTime + riseTime)
        y = offset + y_riseTime exp(-(time - startTime - riseTime)/fallTimeConst)
    """

    outMax = ac.Parameter(1.0, description="height of output for infinite riseTime")
    riseTime = ac.Parameter(0.5, unit="s", min=0, description="rise time")
    riseTimeConst = ac.Parameter(0.1, unit="s", min=1e-60, description="rise time "
                                 "constant; rising is outMax (1 - exp(-riseTime/"
                                 "riseTimeConst))")
    fallTimeConst = ac.Parameter(lambda c: c.riseTimeConst, unit="s", min=1e-60,
                                 description="fall time constant")
    y_riseTime = ac.Variable(description="output at the end of the rise")

    def equations(self):
        t = ac.time - self.startTime
        rising = self.outMax * (1 - ac.exp(-t / self.riseTimeConst))
        falling = self.y_riseTime * ac.exp(-(t - self.riseTime) / self.fallTimeConst)
        return [ac.Eq(self.y_riseTime,
                      self.outMax * (1 - ac.exp(-self.riseTime / self.riseTimeConst))),
                ac.Eq(self.y, self.offset + ac.if_else(
                    t < 0, 0, ac.if_else(t < self.riseTime, rising, falling)))]
