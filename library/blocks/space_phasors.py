"""Blocks on space phasors, the pair (real part, imaginary part) of a two-axis quantity
(Modelica.Electrical.Machines.SpacePhasors.Blocks, MSL v4.0.0: Rotator, ToPolar), as the
MSL's Blocks.Examples.SinCosEncoder uses them.  The vector ports ``u[2]``, ``y[2]`` of
the MSL's MIMOs(n=2) are ``u[0], u[1]`` and ``y[0], y[1]``."""
from acausal._sympy import sympy as sp

import acausal as ac
from acausal.ports import RealInput, RealOutput

__all__ = ["Rotator", "ToPolar"]


class _MIMO2(ac.Component):
    """Two inputs u[0], u[1] and two outputs y[0], y[1] (the MSL's MIMOs with n = 2)."""

    def build(self):
        self.u = [RealInput(), RealInput()]
        self.y = [RealOutput(), RealOutput()]


class Rotator(_MIMO2):
    """Rotates a space phasor by -angle (MSL Electrical.Machines.SpacePhasors.Blocks.Rotator):

        y = R(-angle) u,   R(a) = [[cos a, -sin a], [sin a, cos a]]

    i.e. y[0] = cos(angle) u[0] + sin(angle) u[1], y[1] = -sin(angle) u[0] +
    cos(angle) u[1]: the phasor seen from axes turned by ``angle``.
    """

    angle = RealInput()

    def equations(self):
        a, u0, u1 = self.angle.signal, self.u[0].signal, self.u[1].signal
        return [ac.Eq(self.y[0], ac.cos(-a) * u0 - ac.sin(-a) * u1),
                ac.Eq(self.y[1], ac.sin(-a) * u0 + ac.cos(-a) * u1)]


class ToPolar(_MIMO2):
    """A space phasor in polar coordinates (MSL
    Electrical.Machines.SpacePhasors.Blocks.ToPolar):

        y[0] = sqrt(u[0]^2 + u[1]^2),   y[1] = atan2(u[1], u[0]), or 0 where y[0] <= small

    (``small`` the MSL's Constants.small, 1e-60; the test is not an event, as the MSL's
    noEvent)."""

    small = ac.Parameter(1e-60, description="magnitude below which the angle is 0")

    def equations(self):
        u0, u1 = self.u[0].signal, self.u[1].signal
        return [ac.Eq(self.y[0], ac.sqrt(u0**2 + u1**2)),
                ac.Eq(self.y[1], ac.no_event(ac.if_else(self.y[0] <= self.small, 0,
                                                        sp.atan2(u1, u0))))]
