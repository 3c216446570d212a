"""Rotational components (Modelica.Mechanics.Rotational.Components; Egeland & Gravdahl 3.2)."""
import acausal as ac
from acausal.ports import RotationalFlange

from .interfaces import (PartialCompliant, PartialCompliantWithRelativeStates,
                         PartialElementaryOneFlange,
                         PartialElementaryRotationalToTranslational,
                         PartialElementaryTwoFlangesAndSupport, PartialTwoFlanges)

__all__ = ["Fixed", "Inertia", "Disc", "Spring", "Damper", "SpringDamper", "IdealGear",
           "IdealPlanetary", "IdealGearR2T", "IdealRollingWheel", "RackAndPinion"]


class Fixed(PartialElementaryOneFlange):
    """Flange fixed in the housing:  flange.phi = phi0."""

    phi0 = ac.Parameter(0.0, unit="rad", description="fixed angle of the housing")

    energy_role = "lossless"  # the housing does not move

    def equations(self):
        return [ac.Eq(self.flange.phi, self.phi0)]


class Inertia(PartialTwoFlanges):
    """Rotating mass (Egeland & Gravdahl (3.30)):

        phi = flange_a.phi = flange_b.phi,   w = der(phi),
        J der(w) = flange_a.tau + flange_b.tau
    """

    J = ac.Parameter(1.0, unit="kg.m2", min=0, description="moment of inertia")
    phi = ac.Variable(start=0.0, unit="rad", description="absolute rotation angle")
    w = ac.Variable(start=0.0, unit="rad/s", description="absolute angular velocity")
    a = ac.Variable(unit="rad/s2", description="absolute angular acceleration")

    def stored_energy(self):
        """Kinetic energy J w^2 / 2  (Egeland & Gravdahl (3.32))."""
        return self.J * self.w**2 / 2

    def equations(self):
        return [ac.Eq(self.phi, self.flange_a.phi),
                ac.Eq(self.phi, self.flange_b.phi),
                ac.Eq(self.w, ac.der(self.phi)),
                ac.Eq(self.a, ac.der(self.w)),
                ac.Eq(self.J * self.a, self.flange_a.tau + self.flange_b.tau)]


class Disc(PartialTwoFlanges):
    """A massless disc that turns flange_b by a fixed angle against flange_a (MSL
    Components.Disc):

        flange_b.phi = flange_a.phi + deltaPhi,   0 = flange_a.tau + flange_b.tau
    """

    deltaPhi = ac.Parameter(0.0, unit="rad", description="angle of flange_b to flange_a")

    energy_role = "lossless"  # rigid and massless

    def equations(self):
        return [ac.Eq(self.flange_b.phi, self.flange_a.phi + self.deltaPhi),
                ac.Eq(0, self.flange_a.tau + self.flange_b.tau)]


class Spring(PartialCompliant):
    """Linear torsional spring:  tau = c (phi_rel - phi_rel0)."""

    c = ac.Parameter(1.0e5, unit="N.m/rad", min=0, description="spring constant")
    phi_rel0 = ac.Parameter(0.0, unit="rad", description="unstretched spring angle")

    def stored_energy(self):
        """c (phi_rel - phi_rel0)^2 / 2."""
        return self.c * (self.phi_rel - self.phi_rel0)**2 / 2

    def equations(self):
        return [ac.Eq(self.tau, self.c * (self.phi_rel - self.phi_rel0))]


class Damper(PartialCompliantWithRelativeStates):
    """Linear torsional damper (MSL Rotational.Components.Damper):

        tau = d w_rel,   lossPower = d w_rel^2

    ``Damper(stateSelect="prefer")`` makes phi_rel and w_rel preferred states.
    """

    d = ac.Parameter(0.0, unit="N.m.s/rad", min=0, description="damping constant")
    lossPower = ac.Variable(unit="W", description="power dissipated, d w_rel^2 >= 0")

    def loss_power(self):
        """lossPower (the audit checks it against the port power tau w_rel)."""
        return self.lossPower

    def equations(self):
        return [ac.Eq(self.tau, self.d * self.w_rel),
                ac.Eq(self.lossPower, self.d * self.w_rel**2)]


class SpringDamper(PartialCompliantWithRelativeStates):
    """Spring and damper in parallel (MSL Rotational.Components.SpringDamper):

        tau = c (phi_rel - phi_rel0) + d w_rel,   lossPower = d w_rel^2

    With ``stateSelect="prefer"`` phi_rel and w_rel are preferred states: a stiff
    shaft keeps its twist accurate however far its ends have turned.
    """

    c = ac.Parameter(1.0e5, unit="N.m/rad", min=0, description="spring constant")
    d = ac.Parameter(0.0, unit="N.m.s/rad", min=0, description="damping constant")
    phi_rel0 = ac.Parameter(0.0, unit="rad", description="unstretched spring angle")
    lossPower = ac.Variable(unit="W", description="power dissipated, d w_rel^2 >= 0")

    def stored_energy(self):
        """c (phi_rel - phi_rel0)^2 / 2."""
        return self.c * (self.phi_rel - self.phi_rel0)**2 / 2

    def loss_power(self):
        """lossPower (the audit checks it against the port power tau w_rel)."""
        return self.lossPower

    def equations(self):
        return [ac.Eq(self.tau, self.c * (self.phi_rel - self.phi_rel0) + self.d * self.w_rel),
                ac.Eq(self.lossPower, self.d * self.w_rel**2)]


class IdealGear(PartialElementaryTwoFlangesAndSupport):
    """Ideal gear without inertia (Egeland & Gravdahl 3.2.3, (3.1)-(3.4); MSL
    Rotational.Components.IdealGear), with the angles taken from its housing:

        flange_a.phi - phi_support = ratio (flange_b.phi - phi_support)
        0 = ratio flange_a.tau + flange_b.tau,   support.tau = -flange_a.tau - flange_b.tau

    ``IdealGear(useSupport=True)`` mounts it on a ``support`` flange (a gearbox on a
    moving or elastic housing, which then takes the reaction torque); by default the
    housing is fixed.  With both flanges on inertias this is a position constraint
    between two states: index 3, which index reduction handles.
    """

    ratio = ac.Parameter(1.0, description="transmission ratio flange_a.phi / flange_b.phi")

    energy_role = "lossless"  # an ideal transformer of motion: power in = power out

    def equations(self):
        phi_s = self.phi_support()
        return [ac.Eq(self.flange_a.phi - phi_s, self.ratio * (self.flange_b.phi - phi_s)),
                ac.Eq(0, self.ratio * self.flange_a.tau + self.flange_b.tau)]


class IdealPlanetary(ac.Component):
    """Ideal planetary gear without inertia (MSL Rotational.Components.IdealPlanetary):
    sun, planet carrier and ring, with ratio = z_ring / z_sun:

        (1 + ratio) carrier.phi = sun.phi + ratio ring.phi          (Willis' equation)
        ring.tau = ratio sun.tau,   carrier.tau = -(1 + ratio) sun.tau

    The three torques sum to zero (no housing) and so do the powers.
    """

    ratio = ac.Parameter(2.0, description="number of ring teeth / sun teeth")
    sun = RotationalFlange()
    carrier = RotationalFlange()
    ring = RotationalFlange()

    energy_role = "lossless"  # sun.tau (w_sun + ratio w_ring - (1 + ratio) w_carrier) = 0

    def equations(self):
        r = self.ratio
        return [ac.Eq((1 + r) * self.carrier.phi, self.sun.phi + r * self.ring.phi),
                ac.Eq(self.ring.tau, r * self.sun.tau),
                ac.Eq(self.carrier.tau, -(1 + r) * self.sun.tau)]


class IdealGearR2T(PartialElementaryRotationalToTranslational):
    """Ideal gear from rotation to translation (MSL IdealGearR2T), each side measured
    from its support:

        flangeR.phi - phi_supportR = ratio (flangeT.s - s_supportT)
        0 = ratio flangeR.tau + flangeT.f
    """

    ratio = ac.Parameter(1.0, unit="rad/m", description="flangeR.phi / flangeT.s")

    energy_role = "lossless"  # an ideal transformer of motion: power in = power out

    def equations(self):
        return [ac.Eq(self.flangeR.phi - self.phi_supportR(),
                      self.ratio * (self.flangeT.s - self.s_supportT())),
                ac.Eq(0, self.ratio * self.flangeR.tau + self.flangeT.f)]


class IdealRollingWheel(PartialElementaryRotationalToTranslational):
    """Wheel rolling without slip (MSL IdealRollingWheel), on supports:

        flangeT.s - s_supportT = radius (flangeR.phi - phi_supportR)
        0 = radius flangeT.f + flangeR.tau
    """

    radius = ac.Parameter(0.3, unit="m", min=0, description="wheel radius")

    energy_role = "lossless"  # an ideal transformer of motion: power in = power out

    def equations(self):
        return [ac.Eq(self.flangeT.s - self.s_supportT(),
                      self.radius * (self.flangeR.phi - self.phi_supportR())),
                ac.Eq(0, self.radius * self.flangeT.f + self.flangeR.tau)]


class RackAndPinion(PartialElementaryRotationalToTranslational):
    """Rack and pinion, the rotation-to-translation transformer of Egeland & Gravdahl
    3.2.5, (3.14)-(3.15):  v = r w_m,  F = T_L / r.  At position level, each side
    measured from its support:

        flangeT.s - s_supportT = r (flangeR.phi - phi_supportR)
        0 = r flangeT.f + flangeR.tau

    (flangeR.tau = T_L is the load torque on the motor, -flangeT.f = F the force on
    the rack.)
    """

    r = ac.Parameter(0.05, unit="m", min=0, description="pinion radius")

    energy_role = "lossless"  # an ideal transformer of motion: power in = power out

    def equations(self):
        return [ac.Eq(self.flangeT.s - self.s_supportT(),
                      self.r * (self.flangeR.phi - self.phi_supportR())),
                ac.Eq(0, self.r * self.flangeT.f + self.flangeR.tau)]
