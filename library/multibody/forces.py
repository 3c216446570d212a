"""Elements acting along the line through the origins of two frames: springs and
dampers (Modelica PlanarMechanics.Parts.Spring / Damper without their rotational part)
and the rigid rod of a point-mass chain."""
import acausal as ac

from .interfaces import PartialLineForce

__all__ = ["Rod", "Spring", "Damper", "SpringDamper"]


class Rod(PartialLineForce):
    """Massless rigid rod with a pin at each end (the links of the DAE notes, 000
    section 3.2, (3.2.4)):  s = L.  The tension f is the constraint force (the
    Lagrange multiplier, times L); the rod takes no torque, so the frames' angles stay
    free."""

    L = ac.Parameter(1.0, unit="m", min=0, description="rod length")

    energy_role = "lossless"  # rigid: f der(s) = 0

    def equations(self):
        return [ac.Eq(self.s, self.L)]


class _SpringLaw:
    """f = c (s - s_unstretched) for a line-force element of either multibody library."""

    c = ac.Parameter(1.0e3, unit="N/m", min=0, description="spring constant")
    s_unstretched = ac.Parameter(0.0, unit="m", min=0, description="unstretched length")

    def stored_energy(self):
        """c (s - s_unstretched)^2 / 2."""
        return self.c * (self.s - self.s_unstretched)**2 / 2

    def equations(self):
        return [ac.Eq(self.f, self.c * (self.s - self.s_unstretched))]


class _DamperLaw:
    """f = d der(s) for a line-force element of either multibody library."""

    d = ac.Parameter(1.0, unit="N.s/m", min=0, description="damping constant")

    def loss_power(self):
        """d der(s)^2 (the audit checks it against f der(s))."""
        return self.d * ac.der(self.s)**2

    def equations(self):
        return [ac.Eq(self.f, self.d * ac.der(self.s))]


class _SpringDamperLaw:
    """f = c (s - s_unstretched) + d der(s) for a line-force element of either library."""

    c = ac.Parameter(1.0e3, unit="N/m", min=0, description="spring constant")
    d = ac.Parameter(1.0, unit="N.s/m", min=0, description="damping constant")
    s_unstretched = ac.Parameter(0.0, unit="m", min=0, description="unstretched length")

    def stored_energy(self):
        """c (s - s_unstretched)^2 / 2."""
        return self.c * (self.s - self.s_unstretched)**2 / 2

    def loss_power(self):
        """d der(s)^2."""
        return self.d * ac.der(self.s)**2

    def equations(self):
        return [ac.Eq(self.f, self.c * (self.s - self.s_unstretched) + self.d * ac.der(self.s))]


class Spring(_SpringLaw, PartialLineForce):
    """Linear spring:  f = c (s - s_unstretched)."""


class Damper(_DamperLaw, PartialLineForce):
    """Linear damper:  f = d der(s)."""


class SpringDamper(_SpringDamperLaw, PartialLineForce):
    """Spring and damper in parallel:  f = c (s - s_unstretched) + d der(s)."""
