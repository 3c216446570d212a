"""Signal adaptors of a rotational flange (Modelica.Mechanics.Rotational.Components
.TorqueToAngleAdaptor and AngleToTorqueAdaptor), which turn a flange into signals (a
model with signal inputs and outputs, as an FMU has).

Their optional signals are conditional ports (``ac.Conditional``) of the structural
flags ``use_w`` and ``use_a``.  An AngleToTorqueAdaptor imposes the angle with its speed
and acceleration inputs as the angle's derivatives, through the functions with a
derivative annotation of :mod:`acausal.library.rotational.move` (the MSL's
Sources.Move and Move_w), so index reduction reads the inputs instead of
differentiating the angle signal.
"""
from __future__ import annotations

import acausal as ac
from acausal.ports import RealInput, RealOutput, RotationalFlange

from .move import position, position_w

__all__ = ["TorqueToAngleAdaptor", "AngleToTorqueAdaptor"]


class TorqueToAngleAdaptor(ac.Component):
    """Signal adaptor of a flange driven by a torque signal, with the angle, speed and
    acceleration as outputs (MSL Rotational.Components.TorqueToAngleAdaptor):

        flange.tau = tau,   phi = flange.phi,
        w = der(phi) (use_w),   a = der(w) (use_a; 0 without use_w)

    ``use_w`` / ``use_a`` (default True) create the outputs w and a.
    """

    use_w = ac.Parameter(True, structural=True,
                         description="= true, enable the output connector w (angular "
                                     "velocity)")
    use_a = ac.Parameter(True, structural=True,
                         description="= true, enable the output connector a (angular "
                                     "acceleration)")
    flange = RotationalFlange()
    phi = RealOutput()
    w = ac.Conditional(RealOutput(), "use_w")
    a = ac.Conditional(RealOutput(), "use_a")
    tau = RealInput()

    energy_role = "source"  # the torque signal comes from outside the mechanics

    def equations(self):
        eqs = [ac.Eq(self.phi, self.flange.phi), ac.Eq(self.flange.tau, self.tau)]
        if self.use_w:
            eqs.append(ac.Eq(self.w, ac.der(self.phi)))
        if self.use_a:
            eqs.append(ac.Eq(self.a, ac.der(self.w) if self.use_w else 0))
        return eqs


class AngleToTorqueAdaptor(ac.Component):
    """Signal adaptor of a flange driven by an angle signal, and its speed and
    acceleration, with the torque that needs as the output (MSL
    Rotational.Components.AngleToTorqueAdaptor):

        flange.phi = position({phi, w, a}, time)   use_a (Sources.Move)
        flange.phi = position_w({phi, w}, time)    use_w, not use_a (Move_w)
        flange.phi = phi                           neither
        tau = -flange.tau

    where d/dt position = w and d2/dt2 position = a (the inputs must be consistent: w
    the derivative of phi, a of w).  tau is the torque acting on what the flange drives.
    The input w exists with use_w or use_a (``use_a=True`` makes ``use_w`` True), a
    with use_a.
    """

    use_w = ac.Parameter(True, structural=True,
                         description="= true, enable the input connector w (angular "
                                     "velocity)")
    use_a = ac.Parameter(True, structural=True,
                         description="= true, enable the input connector a (angular "
                                     "acceleration)")
    flange = RotationalFlange()
    phi = RealInput()
    w = ac.Conditional(RealInput(), "use_w")
    a = ac.Conditional(RealInput(), "use_a")
    tau = RealOutput()

    energy_role = "source"  # the motion is imposed from outside the mechanics

    def __init__(self, **modifications):
        if modifications.get("use_a", True):       # w if use_w or use_a
            modifications["use_w"] = True
        super().__init__(**modifications)

    def equations(self):
        if self.use_a:
            phi = position([self.phi, self.w, self.a], ac.time)
        elif self.use_w:
            phi = position_w([self.phi, self.w], ac.time)
        else:
            phi = self.phi
        return [ac.Eq(self.flange.phi, phi), ac.Eq(self.tau, -self.flange.tau)]
