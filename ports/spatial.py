"""The spatial mechanical frame (Modelica.Mechanics.MultiBody.Interfaces.Frame).

A frame is a coordinate system fixed to a point of a body.  It carries, as in the MSL,

* the position r_0 = (x, y, z) of its origin in the world frame [m],
* its orientation R = [R11 .. R33], the MSL's ``R.T``: the matrix that maps a vector
  given in world coordinates to the same vector in frame coordinates (v_frame = R v_0),
* the cut force f = (fx, fy, fz) [N] and cut torque t = (tx, ty, tz) [N.m] acting on the
  component, both resolved in the frame itself (through variables).

The nine entries of R have three degrees of freedom: R is *overdetermined* (MSL:
Connections.branch/root).  This framework writes it only in the direction of the
spanning tree that starts at a root (the World, a Fixed frame, a free point mass): the
root sets it, every joint and rigid part sets that of its frame_b from its frame_a, and
bodies, force elements and sensors only read it.  Each connection set then holds exactly
one frame that sets R (``acausal.library.multibody3d`` gives the reasoning and what it
excludes).

Power into the component: f . (R der(r_0)) + t . w, w the frame's angular velocity
resolved in the frame.
"""
import numpy as np

from ..components.declarations import Across, Through
from .base import Port

__all__ = ["Frame"]

_R = "orientation R[{i},{j}] (MSL R.T): world vector -> frame coordinates"
# R's start values are the identity: the guess of a Newton iteration that solves for an
# orientation (in a closed loop) must not be the singular R = 0


class Frame(Port):
    """Spatial frame: position r_0 [m] in the world, orientation R (world -> frame); cut
    force f [N] and torque t [N.m] acting on the component, resolved in this frame."""

    x = Across(unit="m", description="x of the frame origin in the world frame (r_0[1])")
    y = Across(unit="m", description="y of the frame origin in the world frame (r_0[2])")
    z = Across(unit="m", description="z of the frame origin in the world frame (r_0[3])")
    R11 = Across(start=1.0, description=_R.format(i=1, j=1))
    R12 = Across(description=_R.format(i=1, j=2))
    R13 = Across(description=_R.format(i=1, j=3))
    R21 = Across(description=_R.format(i=2, j=1))
    R22 = Across(start=1.0, description=_R.format(i=2, j=2))
    R23 = Across(description=_R.format(i=2, j=3))
    R31 = Across(description=_R.format(i=3, j=1))
    R32 = Across(description=_R.format(i=3, j=2))
    R33 = Across(start=1.0, description=_R.format(i=3, j=3))
    fx = Through(unit="N", description="cut force acting on the component, frame x")
    fy = Through(unit="N", description="cut force acting on the component, frame y")
    fz = Through(unit="N", description="cut force acting on the component, frame z")
    tx = Through(unit="N.m", description="cut torque acting on the component, frame x")
    ty = Through(unit="N.m", description="cut torque acting on the component, frame y")
    tz = Through(unit="N.m", description="cut torque acting on the component, frame z")
    effort, flow = "fx", "der(x)"
    hint = ("the World is missing or a frame is not connected; or a joint or rigid part is "
            "connected backwards (its frame_a must face the World); or a body is held only "
            "by force elements (attach a free body with FreeMotion); or the frames close a "
            "kinematic loop, which fixes an orientation twice (close a planar loop with a "
            "RevolutePlanarLoopConstraint)")

    def power(self, value, rate):
        """Power into the component over a trajectory (the energy audit):
        f . (R der(r_0)) + t . w, with skew(w) = -der(R) R^T."""
        R = np.array([[value(f"R{i}{j}") for j in (1, 2, 3)] for i in (1, 2, 3)])
        Rdot = np.array([[rate(f"R{i}{j}") for j in (1, 2, 3)] for i in (1, 2, 3)])
        v = np.einsum("ijn,jn->in", R, np.array([rate(c) for c in "xyz"]))
        W = -np.einsum("ikn,jkn->ijn", Rdot, R)
        w = np.array([W[2, 1], W[0, 2], W[1, 0]])
        f = np.array([value(f"f{c}") for c in "xyz"])
        t = np.array([value(f"t{c}") for c in "xyz"])
        return np.sum(f * v + t * w, axis=0)
