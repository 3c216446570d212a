"""Mechanical flanges.  They carry positions, as in Modelica: a rigid coupling (an
ideal gear, a joint) is then a position constraint, which index reduction handles."""
from ..components.declarations import Across, Through
from .base import Port

__all__ = ["RotationalFlange", "TranslationalFlange"]


class RotationalFlange(Port):
    """Rotational flange: absolute angle phi [rad], cut torque tau [N m] into the flange.

    Power into the component: tau * der(phi).
    """

    phi = Across(unit="rad", description="absolute rotation angle of the flange")
    tau = Through(unit="N.m", description="cut torque in the flange")
    effort, flow = "tau", "der(phi)"
    hint = "a Fixed component is missing, or a flange is not connected"


class TranslationalFlange(Port):
    """Translational flange: absolute position s [m], cut force f [N] into the flange.

    Power into the component: f * der(s).
    """

    s = Across(unit="m", description="absolute position of the flange")
    f = Through(unit="N", description="cut force in the flange")
    effort, flow = "f", "der(s)"
    hint = "a Fixed component is missing, or a flange is not connected"
