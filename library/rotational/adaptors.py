"""Signal adaptors of a rotational flange (Modelica.Mechanics.Rotational.Components
.TorqueToAngleAdaptor and AngleToTorqueAdaptor), which turn a flange into signals (a
model with signal inputs and outputs, as an FMU has).

Their optional signals (``use_w``, ``use_a``) are constructor arguments, because they
add a port.  An AngleToTorqueAdaptor that takes the speed and acceleration as inputs
(use_w or use_a true, the MSL's default) imposes the angle with those inputs as its
derivatives, which the MSL writes as a function with a ``derivative`` annotation
(Sources.Move); the language has no such functions yet, so only the angle alone
(``use_w=False, use_a=False``) can be imposed, and the others are refused.
"""
from __future__ import annotations

import acausal as ac
from acausal.ports import RealInput, RealOutput, RotationalFlange

__all__ = ["TorqueToAngleAdaptor", "AngleToTorqueAdaptor", "optional_ports"]


def optional_ports(comp, ports: dict, flags: dict) -> None:
    """Create the ports {name: (port class, flags that must all be true)} whose flags
    (``flags``: {flag: value}, each kept on the instance) are given True."""
    for flag, use in flags.items():
        if not isinstance(use, bool):
            raise ac.ModelError(f"{type(comp).__name__}: {flag} must be True or False, "
                                f"not {use!r}")
        object.__setattr__(comp, flag, use)
    for name, (port, needs) in ports.items():
        if all(flags[f] for f in needs):
            setattr(comp, name, port())


class TorqueToAngleAdaptor(ac.Component):
    """Signal adaptor of a flange driven by a torque signal, with the angle, speed and
    acceleration as outputs (MSL Rotational.Components.TorqueToAngleAdaptor):

        flange.tau = tau,   phi = flange.phi,   w = der(phi),   a = der(w)

    ``use_w`` / ``use_a`` (default True) create the outputs w and a.
    """

    flange = RotationalFlange()
    phi = RealOutput()
    tau = RealInput()

    energy_role = "source"  # the torque signal comes from outside the mechanics

    def __init__(self, *, use_w=True, use_a=True, **modifications):
        super().__init__(**modifications)
        optional_ports(self, {"w": (RealOutput, ("use_w",)), "a": (RealOutput, ("use_a",))},
                       {"use_w": use_w, "use_a": use_a})

    def equations(self):
        eqs = [ac.Eq(self.phi, self.flange.phi), ac.Eq(self.flange.tau, self.tau)]
        if self.use_w:
            eqs.append(ac.Eq(self.w, ac.der(self.phi)))
        if self.use_a:
            eqs.append(ac.Eq(self.a, ac.der(self.w) if self.use_w else 0))
        return eqs


class AngleToTorqueAdaptor(ac.Component):
    """Signal adaptor of a flange driven by an angle signal, with the torque that needs
    as the output (MSL Rotational.Components.AngleToTorqueAdaptor), with
    ``use_w=False, use_a=False``:

        flange.phi = phi,   tau = -flange.tau

    (tau is the torque acting on what the flange drives).  The MSL's default takes the
    speed w and acceleration a as inputs as well, as the derivatives of phi (use_w,
    use_a true); that needs a function with a derivative annotation, which the language
    does not have yet (module docstring): those are refused.
    """

    flange = RotationalFlange()
    phi = RealInput()
    tau = RealOutput()

    energy_role = "source"  # the motion is imposed from outside the mechanics

    def __init__(self, *, use_w=True, use_a=True, **modifications):
        super().__init__(**modifications)
        if use_w or use_a:
            raise ac.ModelError(
                f"{type(self).__name__}(use_w={use_w!r}, use_a={use_a!r}): imposing the "
                "angle with the speed and acceleration inputs as its derivatives needs a "
                "function with a derivative annotation (the MSL's Sources.Move), which the "
                "language does not have yet; AngleToTorqueAdaptor(use_w=False, use_a=False) "
                "imposes the angle alone")
        optional_ports(self, {}, {"use_w": use_w, "use_a": use_a})

    def equations(self):
        return [ac.Eq(self.flange.phi, self.phi), ac.Eq(self.tau, -self.flange.tau)]
