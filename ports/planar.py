"""The planar mechanical frame (Modelica PlanarMechanics.Interfaces.Frame).

A frame is a point with an orientation in the x-y plane of the world.  It carries
positions, as the 1-D flanges do, so joints and rigid bars are position constraints
that index reduction differentiates.
"""
from ..components.declarations import Across, Through
from .base import Port

__all__ = ["Frame"]


class Frame(Port):
    """Planar frame: position (x, y) [m] and angle phi [rad] in the world frame; cut
    force (fx, fy) [N] in world coordinates and cut torque tau [N m], positive into the
    component (they act on the component).

    Power into the component: fx der(x) + fy der(y) + tau der(phi).
    """

    x = Across(unit="m", description="x position of the frame origin in the world frame")
    y = Across(unit="m", description="y position of the frame origin in the world frame")
    phi = Across(unit="rad", description="angle of the frame w.r.t. the world frame")
    fx = Through(unit="N", description="cut force in world x acting on the component")
    fy = Through(unit="N", description="cut force in world y acting on the component")
    tau = Through(unit="N.m", description="cut torque about z acting on the component")
    # the power is a sum of three products; the first pair names the port's kind
    effort, flow = "fx", "der(x)"
    hint = "a FixedFrame is missing, or a frame is not connected"
