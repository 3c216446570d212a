"""Signal adaptors of a translational flange (Modelica.Mechanics.Translational.Components
.GeneralForceToPositionAdaptor and GeneralPositionToForceAdaptor, after
Modelica.Blocks.Interfaces.Adaptors), which turn a flange into signals (a model with
signal inputs and outputs, as an FMU has).

Their optional signals (``use_pder``, ``use_pder2``) are constructor arguments, because
they add a port.  A GeneralPositionToForceAdaptor that takes the speed (and
acceleration) as inputs (use_pder true, the MSL's default) imposes the position with
those inputs as its derivatives, which the MSL writes as a function with a
``derivative`` annotation (Adaptors.Functions.state1, state2); the language has no such
functions yet, so only the position alone (``use_pder=False``) can be imposed, and the
others are refused.  The flow's derivatives (use_fder, use_fder2) are false in both, as
in the MSL (final).
"""
from __future__ import annotations

import acausal as ac
from acausal.ports import RealInput, RealOutput, TranslationalFlange

from ..rotational.adaptors import optional_ports

__all__ = ["GeneralForceToPositionAdaptor", "GeneralPositionToForceAdaptor"]


class GeneralForceToPositionAdaptor(ac.Component):
    """Signal adaptor of a flange driven by a force signal ``f``, with the position,
    speed and acceleration as outputs ``p``, ``pder``, ``pder2`` (MSL Translational
    .Components.GeneralForceToPositionAdaptor):

        flange.f = f,   p = flange.s,   pder = der(p),   pder2 = der(pder)

    ``use_pder`` / ``use_pder2`` (default True; pder2 only with pder) create the
    outputs pder and pder2.
    """

    flange = TranslationalFlange()
    p = RealOutput()
    f = RealInput()

    energy_role = "source"  # the force signal comes from outside the mechanics

    def __init__(self, *, use_pder=True, use_pder2=True, **modifications):
        super().__init__(**modifications)
        optional_ports(self, {"pder": (RealOutput, ("use_pder",)),
                              "pder2": (RealOutput, ("use_pder", "use_pder2"))},
                       {"use_pder": use_pder, "use_pder2": use_pder2})

    def equations(self):
        eqs = [ac.Eq(self.p, self.flange.s), ac.Eq(self.flange.f, self.f)]
        if self.use_pder:
            eqs.append(ac.Eq(self.pder, ac.der(self.p)))
            if self.use_pder2:
                eqs.append(ac.Eq(self.pder2, ac.der(self.pder)))
        return eqs


class GeneralPositionToForceAdaptor(ac.Component):
    """Signal adaptor of a flange driven by a position signal ``p``, with the force that
    needs as the output ``f`` (MSL Translational.Components
    .GeneralPositionToForceAdaptor), with ``use_pder=False``:

        flange.s = p,   f = -flange.f

    (f is the force acting on what the flange drives).  The MSL's default takes the
    speed and acceleration as inputs as well, as the derivatives of p; that needs a
    function with a derivative annotation, which the language does not have yet
    (module docstring): those are refused.
    """

    flange = TranslationalFlange()
    p = RealInput()
    f = RealOutput()

    energy_role = "source"  # the motion is imposed from outside the mechanics

    def __init__(self, *, use_pder=True, use_pder2=True, **modifications):
        super().__init__(**modifications)
        if use_pder:
            raise ac.ModelError(
                f"{type(self).__name__}(use_pder=True): imposing the position with the "
                "speed (and acceleration) inputs as its derivatives needs a function with a "
                "derivative annotation (the MSL's Adaptors.Functions.state1/state2), which "
                "the language does not have yet; GeneralPositionToForceAdaptor("
                "use_pder=False) imposes the position alone")
        optional_ports(self, {}, {"use_pder": use_pder, "use_pder2": use_pder2})

    def equations(self):
        return [ac.Eq(self.flange.s, self.p), ac.Eq(self.f, -self.flange.f)]
