"""Utilities of the translational examples (Modelica.Mechanics.Translational.Examples
.Utilities, MSL v4.0.0): the Stribeck friction table of the Friction example, and a
mass, a spring and a spring-damper as blocks with signal inputs and outputs, the way a
model is exported as an FMU.
"""
import numpy as np

import acausal as ac
from acausal.library.thermal.conditional import PartialElementaryConditionalHeatPortWithoutT
from acausal.library.translational import Force, Mass, Spring as SpringElement
from acausal.library.translational.adaptors import (GeneralForceToPositionAdaptor,
                                                     GeneralPositionToForceAdaptor)
from acausal.library.translational.interfaces import PartialCompliant
from acausal.ports import RealInput, RealOutput

__all__ = ["GenerateStribeckFrictionTable", "DirectMass", "InverseMass", "Spring",
           "SpringDamper", "SpringDamperNoRelativeStates"]


def GenerateStribeckFrictionTable(F_prop, F_Coulomb, F_Stribeck, fexp, v_max, nTable=100):
    """The Stribeck friction curve as a table for ``SupportFriction`` (MSL
    Examples.Utilities.GenerateStribeckFrictionTable): nTable rows [v, f], v from 0 to
    v_max evenly, f = F_Coulomb + F_prop v + F_Stribeck exp(-fexp v)."""
    if int(nTable) != nTable or nTable < 2:
        raise ValueError(f"GenerateStribeckFrictionTable: nTable must be an integer >= 2, "
                         f"not {nTable!r}")
    v = v_max * np.arange(int(nTable)) / (int(nTable) - 1)
    return np.column_stack([v, F_Coulomb + F_prop * v + F_Stribeck * np.exp(-fexp * v)])


class DirectMass(ac.Component):
    """Input/output block of a direct mass model (MSL Examples.Utilities.DirectMass):
    the force fDrive accelerates the mass, against the force f its other side receives;
    s, v, a are its motion."""

    m = ac.Parameter(1.0, unit="kg", min=0, description="mass")
    fDrive = RealInput()
    f = RealInput()
    s = RealOutput()
    v = RealOutput()
    a = RealOutput()
    mass = Mass(m=ac.ref("m"), s={"start": 0.0, "fixed": True}, v={"start": 0.0, "fixed": True})
    forceSource = Force()
    forceToPosition = GeneralForceToPositionAdaptor()

    def equations(self):
        return [ac.connect(self.forceToPosition.f, self.f),
                ac.connect(self.forceToPosition.p, self.s),
                ac.connect(self.forceToPosition.pder, self.v),
                ac.connect(self.forceToPosition.pder2, self.a),
                ac.connect(self.fDrive, self.forceSource.f),
                ac.connect(self.forceSource.flange, self.mass.flange_a),
                ac.connect(self.mass.flange_b, self.forceToPosition.flange)]


class Spring(ac.Component):
    """Input/output block of a spring model (MSL Examples.Utilities.Spring): the
    positions s1, s2 of its flanges in, the forces f1, f2 needed to move them out."""

    c = ac.Parameter(1e4, unit="N/m", description="spring constant")
    s_rel0 = ac.Parameter(0.0, unit="m", description="unstretched spring length")
    s1 = RealInput()
    s2 = RealInput()
    f1 = RealOutput()
    f2 = RealOutput()
    positionToForce1 = GeneralPositionToForceAdaptor(use_pder=False, use_pder2=False)
    spring = SpringElement(c=ac.ref("c"), s_rel0=ac.ref("s_rel0"))
    positionToForce2 = GeneralPositionToForceAdaptor(use_pder=False, use_pder2=False)

    def equations(self):
        return [ac.connect(self.f1, self.positionToForce1.f),
                ac.connect(self.positionToForce2.f, self.f2),
                ac.connect(self.positionToForce1.flange, self.spring.flange_a),
                ac.connect(self.spring.flange_b, self.positionToForce2.flange),
                ac.connect(self.positionToForce1.p, self.s1),
                ac.connect(self.positionToForce2.p, self.s2)]


class InverseMass(ac.Component):
    """Input/output block of an inverse mass model (MSL Examples.Utilities.InverseMass):
    the position, speed and acceleration in, the force that moves the mass so out."""

    m = ac.Parameter(1.0, unit="kg", description="mass")
    s = RealInput()
    v = RealInput()
    a = RealInput()
    f = RealOutput()
    mass = Mass(m=ac.ref("m"))
    positionToForce = GeneralPositionToForceAdaptor()

    def equations(self):
        return [ac.connect(self.positionToForce.f, self.f),
                ac.connect(self.positionToForce.flange, self.mass.flange_a),
                ac.connect(self.positionToForce.p, self.s),
                ac.connect(self.positionToForce.pder, self.v),
                ac.connect(self.positionToForce.pder2, self.a)]


class SpringDamperNoRelativeStates(PartialCompliant,
                                   PartialElementaryConditionalHeatPortWithoutT):
    """Linear spring and damper in parallel whose relative position and speed are not
    states (MSL Examples.Utilities.SpringDamperNoRelativeStates; no a_rel = der(v_rel),
    so an FMU of it needs no accelerations as inputs):

        v_rel = der(s_rel),   f_c = c (s_rel - s_rel0),   f_d = d v_rel
        f = f_c + f_d,        lossPower = f_d v_rel
    """

    c = ac.Parameter(1.0, unit="N/m", min=0, description="spring constant")
    d = ac.Parameter(0.0, unit="N.s/m", min=0, description="damping constant")
    s_rel0 = ac.Parameter(0.0, unit="m", description="unstretched spring length")
    v_rel = ac.Variable(start=0.0, unit="m/s",
                        description="relative velocity (= der(s_rel))")
    f_c = ac.Variable(unit="N", description="spring force")
    f_d = ac.Variable(unit="N", description="linear damping force")

    def equations(self):
        return [ac.Eq(self.v_rel, ac.der(self.s_rel)),
                ac.Eq(self.f_c, self.c * (self.s_rel - self.s_rel0)),
                ac.Eq(self.f_d, self.d * self.v_rel),
                ac.Eq(self.f, self.f_c + self.f_d),
                ac.Eq(self.lossPower, self.f_d * self.v_rel)]


class SpringDamper(ac.Component):
    """Input/output block of a spring/damper model (MSL Examples.Utilities
    .SpringDamper): the positions and speeds of its flanges in, the forces needed to
    move them out."""

    c = ac.Parameter(1e4, unit="N/m", description="spring constant")
    d = ac.Parameter(1.0, unit="N.s/m", description="damping constant")
    s_rel0 = ac.Parameter(0.0, unit="m", description="unstretched spring length")
    s1 = RealInput()
    v1 = RealInput()
    f1 = RealOutput()
    s2 = RealInput()
    v2 = RealInput()
    f2 = RealOutput()
    positionToForce1 = GeneralPositionToForceAdaptor(use_pder2=False)
    springDamper = SpringDamperNoRelativeStates(c=ac.ref("c"), d=ac.ref("d"),
                                                s_rel0=ac.ref("s_rel0"))
    positionToForce2 = GeneralPositionToForceAdaptor(use_pder2=False)

    def equations(self):
        return [ac.connect(self.f1, self.positionToForce1.f),
                ac.connect(self.positionToForce2.f, self.f2),
                ac.connect(self.positionToForce1.flange, self.springDamper.flange_a),
                ac.connect(self.springDamper.flange_b, self.positionToForce2.flange),
                ac.connect(self.positionToForce1.p, self.s1),
                ac.connect(self.positionToForce1.pder, self.v1),
                ac.connect(self.positionToForce2.p, self.s2),
                ac.connect(self.positionToForce2.pder, self.v2)]
