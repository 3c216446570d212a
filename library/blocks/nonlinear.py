"""Static nonlinearities (Modelica.Blocks.Nonlinear).  Their corners are events."""
import acausal as ac

from .interfaces import SISO

__all__ = ["Limiter", "Saturation", "DeadZone", "clip"]


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
