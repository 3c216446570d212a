"""Partial friction elements: the relative motion of two flanges and the friction
force (torque) between them, like a damper (``PartialCompliant``).

The friction f acts on flange_b against the relative velocity v = der(flange_b -
flange_a) and with -f on flange_a; a dissipative law has f v >= 0.  Connect flange_a
to a ``Fixed`` housing for friction against the ground.

The equations are written here once: the kinematics and ``law(v, f)``, the friction law
each element provides (written once for both domains in ``_models``).
"""
import acausal as ac
from acausal.library import rotational as rot
from acausal.library import translational as tr

__all__ = ["PartialTranslationalFriction", "PartialRotationalFriction"]


class PartialTranslationalFriction(tr.PartialCompliant):
    """s_rel = flange_b.s - flange_a.s,  v = der(s_rel),  flange_b.f = f,  flange_a.f = -f."""

    v = ac.Variable(start=0.0, unit="m/s", description="relative velocity")

    def law(self, v, f) -> list:
        """The friction law relating the force f to the relative velocity v."""
        raise NotImplementedError(f"{type(self).__name__} defines no friction law")

    def equations(self):
        return [ac.Eq(self.v, ac.der(self.s_rel)), *self.law(self.v, self.f)]


class PartialRotationalFriction(rot.PartialCompliant):
    """phi_rel = flange_b.phi - flange_a.phi,  w = der(phi_rel),  flange_b.tau = tau,
    flange_a.tau = -tau."""

    w = ac.Variable(start=0.0, unit="rad/s", description="relative angular velocity")

    def law(self, w, tau) -> list:
        """The friction law relating the torque tau to the relative velocity w."""
        raise NotImplementedError(f"{type(self).__name__} defines no friction law")

    def equations(self):
        return [ac.Eq(self.w, ac.der(self.phi_rel)), *self.law(self.w, self.tau)]
