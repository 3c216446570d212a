"""Rotational components (Modelica.Mechanics.Rotational.Components; Egeland & Gravdahl 3.2)."""
import acausal as ac

from .interfaces import (PartialCompliant, PartialElementaryOneFlange,
                         PartialElementaryRotationalToTranslational, PartialTwoFlanges)

__all__ = ["Fixed", "Inertia", "Spring", "Damper", "SpringDamper", "IdealGear",
           "IdealGearR2T", "IdealRollingWheel", "RackAndPinion", "ElasticGearWithDeadzone"]


class Fixed(PartialElementaryOneFlange):
    """Flange fixed in the housing:  flange.phi = phi0."""

    phi0 = ac.Parameter(0.0, unit="rad", description="fixed angle of the housing")

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

    def equations(self):
        return [ac.Eq(self.phi, self.flange_a.phi),
                ac.Eq(self.phi, self.flange_b.phi),
                ac.Eq(self.w, ac.der(self.phi)),
                ac.Eq(self.a, ac.der(self.w)),
                ac.Eq(self.J * self.a, self.flange_a.tau + self.flange_b.tau)]


class Spring(PartialCompliant):
    """Linear torsional spring:  tau = c (phi_rel - phi_rel0)."""

    c = ac.Parameter(1.0e5, unit="N.m/rad", min=0, description="spring constant")
    phi_rel0 = ac.Parameter(0.0, unit="rad", description="unstretched spring angle")

    def equations(self):
        return [*super().equations(), ac.Eq(self.tau, self.c * (self.phi_rel - self.phi_rel0))]


class Damper(PartialCompliant):
    """Linear torsional damper:  tau = d der(phi_rel)."""

    d = ac.Parameter(0.0, unit="N.m.s/rad", min=0, description="damping constant")

    def equations(self):
        return [*super().equations(), ac.Eq(self.tau, self.d * ac.der(self.phi_rel))]


class SpringDamper(PartialCompliant):
    """Spring and damper in parallel:  tau = c (phi_rel - phi_rel0) + d der(phi_rel)."""

    c = ac.Parameter(1.0e5, unit="N.m/rad", min=0, description="spring constant")
    d = ac.Parameter(0.0, unit="N.m.s/rad", min=0, description="damping constant")
    phi_rel0 = ac.Parameter(0.0, unit="rad", description="unstretched spring angle")

    def equations(self):
        return [*super().equations(),
                ac.Eq(self.tau, self.c * (self.phi_rel - self.phi_rel0)
                      + self.d * ac.der(self.phi_rel))]


class IdealGear(PartialTwoFlanges):
    """Ideal gear without inertia (Egeland & Gravdahl 3.2.3, (3.1)-(3.4)):

        flange_a.phi = n flange_b.phi,   0 = n flange_a.tau + flange_b.tau

    With both flanges on inertias this is a position constraint between two states:
    index 3, which index reduction handles.
    """

    n = ac.Parameter(1.0, description="gear ratio flange_a.phi / flange_b.phi")

    def equations(self):
        return [ac.Eq(self.flange_a.phi, self.n * self.flange_b.phi),
                ac.Eq(0, self.n * self.flange_a.tau + self.flange_b.tau)]


class IdealGearR2T(PartialElementaryRotationalToTranslational):
    """Ideal gear from rotation to translation (Modelica IdealGearR2T):

        flangeR.phi = ratio flangeT.s,   0 = ratio flangeR.tau + flangeT.f
    """

    ratio = ac.Parameter(1.0, unit="rad/m", description="flangeR.phi / flangeT.s")

    def equations(self):
        return [ac.Eq(self.flangeR.phi, self.ratio * self.flangeT.s),
                ac.Eq(0, self.ratio * self.flangeR.tau + self.flangeT.f)]


class IdealRollingWheel(PartialElementaryRotationalToTranslational):
    """Wheel rolling without slip on the ground (Modelica IdealRollingWheel):

        flangeT.s = radius flangeR.phi,   0 = radius flangeT.f + flangeR.tau
    """

    radius = ac.Parameter(0.3, unit="m", min=0, description="wheel radius")

    def equations(self):
        return [ac.Eq(self.flangeT.s, self.radius * self.flangeR.phi),
                ac.Eq(0, self.radius * self.flangeT.f + self.flangeR.tau)]


class RackAndPinion(PartialElementaryRotationalToTranslational):
    """Rack and pinion, the rotation-to-translation transformer of Egeland & Gravdahl
    3.2.5, (3.14)-(3.15):  v = r w_m,  F = T_L / r.  At position level:

        flangeT.s = r flangeR.phi,   0 = r flangeT.f + flangeR.tau

    (flangeR.tau = T_L is the load torque on the motor, -flangeT.f = F the force on
    the rack.)
    """

    r = ac.Parameter(0.05, unit="m", min=0, description="pinion radius")

    def equations(self):
        return [ac.Eq(self.flangeT.s, self.r * self.flangeR.phi),
                ac.Eq(0, self.r * self.flangeT.f + self.flangeR.tau)]


class ElasticGearWithDeadzone(PartialTwoFlanges):
    """Elastic gear with backlash (dead zone) delta (Egeland & Gravdahl 3.6.2,
    (3.118)-(3.119)), motor on flange_a, load on flange_b:

        phi = flange_a.phi - n flange_b.phi
        tau = K (phi + delta)  if phi < -delta,   K (phi - delta)  if phi > delta,   else 0
        flange_a.tau = tau,   flange_b.tau = -n tau

    Here n = flange_a.phi / flange_b.phi as in IdealGear; the book's ratio is 1/n
    (its phi = theta_m - theta_L/n_book, T_gL = T_gm/n_book).  The corners of the
    dead zone are events.
    """

    n = ac.Parameter(1.0, description="gear ratio flange_a.phi / flange_b.phi in contact")
    K = ac.Parameter(1.0e4, unit="N.m/rad", min=0, description="gear stiffness (motor side)")
    delta = ac.Parameter(0.01, unit="rad", min=0, description="half width of the dead zone")
    phi = ac.Variable(unit="rad", description="gear deflection, motor side")
    tau = ac.Variable(unit="N.m", description="gear torque on the motor side T_gm")

    def equations(self):
        phi, d = self.phi, self.delta
        law = ac.if_else(phi < -d, self.K * (phi + d),
                         ac.if_else(phi > d, self.K * (phi - d), 0))
        return [ac.Eq(phi, self.flange_a.phi - self.n * self.flange_b.phi),
                ac.Eq(self.tau, law),
                ac.Eq(self.flange_a.tau, self.tau),
                ac.Eq(self.flange_b.tau, -self.n * self.tau)]
