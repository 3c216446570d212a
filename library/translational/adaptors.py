"""Signal adaptors of a translational flange (Modelica.Mechanics.Translational.Components
.GeneralForceToPositionAdaptor and GeneralPositionToForceAdaptor, after
Modelica.Blocks.Interfaces.Adaptors), which turn a flange into signals (a model with
signal inputs and outputs, as an FMU has).

Their optional signals are conditional ports (``ac.Conditional``) of the structural
flags ``use_pder`` and ``use_pder2``.  A GeneralPositionToForceAdaptor imposes the
position with its speed and acceleration inputs as the position's derivatives, through
the functions with a derivative annotation of the MSL's Adaptors.Functions.state1 and
state2 (the same functions as the rotational Move's,
:mod:`acausal.library.rotational.move`), so index reduction reads the inputs instead of
differentiating the position signal.  The flow's derivatives (use_fder, use_fder2) are
false in both, as in the MSL (final).
"""
from __future__ import annotations

import acausal as ac
from acausal.ports import RealInput, RealOutput, TranslationalFlange

from ..rotational.move import position as state2
from ..rotational.move import position_w as state1

__all__ = ["GeneralForceToPositionAdaptor", "GeneralPositionToForceAdaptor"]


def _pder2_needs_pder(modifications: dict) -> dict:
    """pder2 exists only with pder (the MSL's ``if use_pder and use_pder2``)."""
    if not modifications.get("use_pder", True):
        modifications["use_pder2"] = False
    return modifications


class GeneralForceToPositionAdaptor(ac.Component):
    """Signal adaptor of a flange driven by a force signal ``f``, with the position,
    speed and acceleration as outputs ``p``, ``pder``, ``pder2`` (MSL Translational
    .Components.GeneralForceToPositionAdaptor):

        flange.f = f,   p = flange.s,   pder = der(p),   pder2 = der(pder)

    ``use_pder`` / ``use_pder2`` (default True; pder2 only with pder) create the
    outputs pder and pder2.
    """

    use_pder = ac.Parameter(True, structural=True,
                            description="use output for 1st derivative of potential")
    use_pder2 = ac.Parameter(True, structural=True,
                             description="use output for 2nd derivative of potential "
                                         "(only if 1st derivative is used, too)")
    flange = TranslationalFlange()
    p = RealOutput()
    pder = ac.Conditional(RealOutput(), "use_pder")
    pder2 = ac.Conditional(RealOutput(), "use_pder2")
    f = RealInput()

    energy_role = "source"  # the force signal comes from outside the mechanics

    def __init__(self, **modifications):
        super().__init__(**_pder2_needs_pder(modifications))

    def equations(self):
        eqs = [ac.Eq(self.p, self.flange.s), ac.Eq(self.flange.f, self.f)]
        if self.use_pder:
            eqs.append(ac.Eq(self.pder, ac.der(self.p)))
            if self.use_pder2:
                eqs.append(ac.Eq(self.pder2, ac.der(self.pder)))
        return eqs


class GeneralPositionToForceAdaptor(ac.Component):
    """Signal adaptor of a flange driven by a position signal ``p``, and its speed
    ``pder`` and acceleration ``pder2``, with the force that needs as the output ``f``
    (MSL Translational.Components.GeneralPositionToForceAdaptor):

        flange.s = state2({p, pder, pder2}, time)   use_pder and use_pder2
        flange.s = state1({p, pder}, time)          use_pder alone
        flange.s = p                                neither
        f = -flange.f

    where d/dt state = pder and d2/dt2 state = pder2 (the inputs must be consistent).
    f is the force acting on what the flange drives.
    """

    use_pder = ac.Parameter(True, structural=True,
                            description="use input for 1st derivative of potential")
    use_pder2 = ac.Parameter(True, structural=True,
                             description="use input for 2nd derivative of potential "
                                         "(only if 1st derivative is used, too)")
    flange = TranslationalFlange()
    p = RealInput()
    pder = ac.Conditional(RealInput(), "use_pder")
    pder2 = ac.Conditional(RealInput(), "use_pder2")
    f = RealOutput()

    energy_role = "source"  # the motion is imposed from outside the mechanics

    def __init__(self, **modifications):
        super().__init__(**_pder2_needs_pder(modifications))

    def equations(self):
        if self.use_pder and self.use_pder2:
            s = state2([self.p, self.pder, self.pder2], ac.time)
        elif self.use_pder:
            s = state1([self.p, self.pder], ac.time)
        else:
            s = self.p
        return [ac.Eq(self.flange.s, s), ac.Eq(self.f, -self.flange.f)]
