"""Static nonlinearities (Modelica.Blocks.Nonlinear).  Their corners are events."""
import acausal as ac

from .interfaces import SISO, start_from

__all__ = ["Limiter", "Saturation", "DeadZone", "SlewRateLimiter", "clip"]


def clip(u, upper, lower):
    """``u`` clipped to [lower, upper], as an event-generating expression."""
    return ac.if_else(u > upper, upper, ac.if_else(u < lower, lower, u))


class Limiter(SISO):
    """y = uMax if u > uMax, uMin if u < uMin, u otherwise."""

    uMax = ac.Parameter(1.0, description="upper limit")
    uMin = ac.Parameter(-1.0, description="lower limit")

    def equations(self):
        return [ac.Eq(self.y, clip(self.u.signal, self.uMax, self.uMin))]


class Saturation(SISO):
    """Symmetric saturation:  y = clip(u, -limit, +limit)."""

    limit = ac.Parameter(1.0, min=0, description="saturation level")

    def equations(self):
        return [ac.Eq(self.y, clip(self.u.signal, self.limit, -self.limit))]


class DeadZone(SISO):
    """y = u - uMax if u > uMax, u - uMin if u < uMin, 0 in between."""

    uMax = ac.Parameter(1.0, description="upper end of the dead zone")
    uMin = ac.Parameter(-1.0, description="lower end of the dead zone")

    def equations(self):
        u = self.u.signal
        y = ac.if_else(u > self.uMax, u - self.uMax, ac.if_else(u < self.uMin, u - self.uMin, 0))
        return [ac.Eq(self.y, y)]


class SlewRateLimiter(SISO):
    """Limits the slew rate of a signal (MSL Blocks.Nonlinear.SlewRateLimiter): the
    output follows the input with the time constant Td, at a rate between Falling and
    Rising,

        val = (u - y)/Td,   der(y) = Falling if val < Falling, Rising if val > Rising,
                            val otherwise

    ``initType``: SteadyState (the MSL's default) starts at y = u, InitialState and
    InitialOutput at y = y_start, NoInit from y's start value.  ``strict`` (the MSL's
    noEvent variant) is not offered: the corners are events.
    """

    Rising = ac.Parameter(1.0, min=0, description="maximum rising slew rate [+small..+inf) "
                                                  "[1/s]")
    Falling = ac.Parameter(lambda c: -c.Rising, max=0,
                           description="maximum falling slew rate (-inf..-small] [1/s]")
    Td = ac.Parameter(0.001, unit="s", min=0, description="derivative time constant")
    initType = ac.Init.parameter("SteadyState",
                                 description="type of initialization (SteadyState implies "
                                             "y = u)")
    y_start = ac.Parameter(0.0, description="initial or guess value of output (= state)")

    def __init__(self, **modifications):
        super().__init__(**start_from(modifications, "y_start"))

    def initial_equations(self):
        if self.initType == "SteadyState":
            return [ac.Eq(self.y, self.u)]
        if self.initType in ("InitialState", "InitialOutput"):
            return [ac.Eq(self.y, self.y_start)]
        return []

    def equations(self):
        val = (self.u.signal - self.y.signal) / self.Td
        return [ac.Eq(ac.der(self.y.signal), clip(val, self.Rising, self.Falling))]
