"""Static nonlinearities (Modelica.Blocks.Nonlinear).  Their corners are events."""
import acausal as ac

from .interfaces import SISO

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
    """Limits the slew rate of a signal (MSL Blocks.Nonlinear.SlewRateLimiter, strict =
    false): the output follows the input with the time constant Td, at a rate between
    Falling and Rising,

        der(x) = clip((u - x)/Td, Falling, Rising),   y = x

    Its state is x, as in the library's other blocks (the MSL's y): it starts from its
    start value, ``SlewRateLimiter(x=y_start)`` (the MSL's initType = InitialOutput; its
    default, SteadyState, y = u, is not offered).
    """

    Rising = ac.Parameter(1.0, min=0, description="maximum rising slew rate (> 0), the "
                                                  "input's unit per second")
    Falling = ac.Parameter(lambda c: -c.Rising, max=0,
                           description="maximum falling slew rate (< 0), default -Rising")
    Td = ac.Parameter(0.001, unit="s", min=0, description="derivative time constant (> 0)")
    x = ac.Variable(start=0.0, description="state (the output)")

    def equations(self):
        val = (self.u.signal - self.x) / self.Td
        return [ac.Eq(ac.der(self.x), clip(val, self.Rising, self.Falling)),
                ac.Eq(self.y, self.x)]
