"""Utilities of the translational examples (Modelica.Mechanics.Translational.Examples
.Utilities, MSL v4.0.0): the Stribeck friction table of the Friction example, and a mass
and a spring as blocks with signal inputs and outputs, the way a model is exported as
an FMU.

``InverseMass`` and ``SpringDamper``, which take speeds and accelerations as inputs,
need a GeneralPositionToForceAdaptor with use_pder, which the language cannot express
yet (see ``acausal.library.translational.adaptors``).
"""
import numpy as np

import acausal as ac
from acausal.ports import RealInput, RealOutput
from acausal.library.translational import Force, Mass, Spring as SpringElement
from acausal.library.translational.adaptors import (GeneralForceToPositionAdaptor,
                                                     GeneralPositionToForceAdaptor)

__all__ = ["GenerateStribeckFrictionTable", "DirectMass", "Spring"]


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
