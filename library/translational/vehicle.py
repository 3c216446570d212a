"""Driving resistances and a one-dimensional vehicle
(Modelica.Mechanics.Translational.Components.RollingResistance and Vehicle).

Their inclination, rolling resistance coefficient and wind speed are parameters or,
where the component is created with ``useInclinationInput=True`` (``useCrInput``,
``useWindInput``), signal inputs: the MSL's conditional inputs, ``ac.Conditional`` ports
of structural flags (like ``useSupport``, given where the component is created).
"""
from __future__ import annotations

import acausal as ac
from acausal.ports import RealInput, RotationalFlange, TranslationalFlange

from .. import rotational as rot
from ..friction.regularization import check_regularization, regularized_sign
from .components import Mass
from .sources import Force, QuadraticSpeedDependentForce, Speed, _PartialForce

__all__ = ["RollingResistance", "Vehicle"]

G_N = 9.80665
"""Standard gravity [m/s2] (Modelica.Constants.g_n)."""


class _OptionalInputs:
    """Signal inputs that exist only when their flag is True (``ac.Conditional``), else
    a constant parameter stands in (``_inputs``: {port: (flag, the parameter)})."""

    _inputs: dict = {}

    def input_or_constant(self, port: str):
        """The input ``port`` where it exists, else its constant parameter."""
        flag, constant = self._inputs[port]
        return getattr(self, port) if getattr(self, flag) else getattr(self, constant)


class RollingResistance(_OptionalInputs, _PartialForce):
    """Resistance of a rolling wheel (MSL Translational.Components.RollingResistance),
    with f = flange.f and the regularized sign of ``friction.regularization`` (``reg``,
    the MSL's default "Exp"):

        f_nominal = -Cr fWeight cos(atan(inclination))
        f = -f_nominal sgn_reg(v / v0)

    Cr and the inclination (tan of the road's angle) are ``CrConstant`` and
    ``inclinationConstant``, or the inputs ``cr`` and ``inclination`` with
    ``useCrInput=True`` / ``useInclinationInput=True``.
    """

    fWeight = ac.Parameter(0.0, unit="N", description="wheel load due to gravity")
    CrConstant = ac.Parameter(0.01, description="constant rolling resistance coefficient")
    inclinationConstant = ac.Parameter(0.0, description="constant inclination = tan(angle)")
    v0 = ac.Parameter(0.1, unit="m/s", min=0, description="regularization below v0 (> 0)")
    f_nominal = ac.Variable(unit="N", description="nominal rolling resistance, without "
                                                  "regularization")

    energy_role = "source"  # a resistance imposed from outside (a source of negative power)
    useCrInput = ac.Parameter(False, structural=True, description="enable the input cr")
    useInclinationInput = ac.Parameter(False, structural=True,
                                       description="enable the input inclination")
    cr = ac.Conditional(RealInput(), "useCrInput")
    inclination = ac.Conditional(RealInput(), "useInclinationInput")
    _inputs = {"cr": ("useCrInput", "CrConstant"),
               "inclination": ("useInclinationInput", "inclinationConstant")}

    def __init__(self, *, reg="Exp", **modifications):
        super().__init__(**modifications)
        object.__setattr__(self, "reg", check_regularization(reg, type(self).__name__))

    def equations(self):
        cr, inclination = self.input_or_constant("cr"), self.input_or_constant("inclination")
        return [ac.Eq(self.f_nominal, -cr * self.fWeight * ac.cos(ac.atan(inclination))),
                ac.Eq(self.f, -self.f_nominal * regularized_sign(self.v, self.v0, self.reg))]


class Vehicle(_OptionalInputs, ac.Component):
    """Simple vehicle (MSL Translational.Components.Vehicle): a mass m on wheels of
    radius R driven at ``flangeR`` through the drive train's inertia J, pushing
    ``flangeT``, against the driving resistances:

        drag         f = -Cd A rho (v - vWind) |v - vWind| / 2   (a QuadraticSpeedDependentForce
                     on a support moving at the wind speed)
        rolling      RollingResistance(fWeight = m g, reg = "Linear", v0 = vReg)
        gravity      f = -m g sin(atan(inclination))

    s, v, a are the mass's.  The inclination, Cr and the wind speed are parameters
    (``inclinationConstant``, ``CrConstant``, ``vWindConstant``) or, with
    ``useInclinationInput=True`` (``useCrInput``, ``useWindInput``), the inputs
    ``inclination``, ``cr``, ``vWind``.
    """

    m = ac.Parameter(1.0, unit="kg", description="total mass of the vehicle")
    g = ac.Parameter(G_N, unit="m/s2", description="constant gravity acceleration")
    J = ac.Parameter(1.0, unit="kg.m2", description="total rotational inertia of the "
                                                    "drive train")
    R = ac.Parameter(1.0, unit="m", description="wheel radius")
    A = ac.Parameter(1.0, unit="m2", description="cross section of the vehicle")
    Cd = ac.Parameter(0.5, description="drag resistance coefficient")
    rho = ac.Parameter(1.2, unit="kg/m3", description="density of air")
    vWindConstant = ac.Parameter(0.0, unit="m/s", description="constant wind velocity")
    CrConstant = ac.Parameter(0.015, description="constant rolling resistance coefficient")
    vReg = ac.Parameter(1e-3, unit="m/s", description="velocity for regularization around 0")
    inclinationConstant = ac.Parameter(0.0, description="constant inclination = tan(angle)")
    vRef = ac.Parameter(1.0, unit="m/s", description="reference velocity of the air drag")
    # the MSL's final modifiers of fDrag and fRoll
    fDrag_nominal = ac.Parameter(lambda c: -c.Cd * c.A * c.rho * c.vRef**2 / 2, unit="N",
                                 description="drag force at vRef against the wind (derived)")
    fWeight = ac.Parameter(lambda c: c.m * c.g, unit="N", description="weight m g (derived)")
    s = ac.Variable(start=0.0, unit="m", description="position of the vehicle")
    v = ac.Variable(start=0.0, unit="m/s", description="velocity of the vehicle")
    a = ac.Variable(unit="m/s2", description="acceleration of the vehicle")
    flangeT = TranslationalFlange()
    flangeR = RotationalFlange()

    useWindInput = ac.Parameter(False, structural=True, description="enable the input vWind")
    useCrInput = ac.Parameter(False, structural=True, description="enable the input cr")
    useInclinationInput = ac.Parameter(False, structural=True,
                                       description="enable the input inclination")
    inclination = ac.Conditional(RealInput(), "useInclinationInput")
    cr = ac.Conditional(RealInput(), "useCrInput")
    vWind = ac.Conditional(RealInput(), "useWindInput")
    _inputs = {"inclination": ("useInclinationInput", "inclinationConstant"),
               "cr": ("useCrInput", "CrConstant"),
               "vWind": ("useWindInput", "vWindConstant")}

    def build(self):
        useCrInput, useInclinationInput = self.useCrInput, self.useInclinationInput
        self.fDrag = QuadraticSpeedDependentForce(
            useSupport=True, ForceDirection=False, v_nominal=ac.ref("vRef"),
            f_nominal=ac.ref("fDrag_nominal"))
        self.fRoll = RollingResistance(useCrInput=useCrInput,
                                       useInclinationInput=useInclinationInput,
                                       reg="Linear", fWeight=ac.ref("fWeight"),
                                       CrConstant=ac.ref("CrConstant"), v0=ac.ref("vReg"),
                                       inclinationConstant=ac.ref("inclinationConstant"))
        self.fGrav = Force()
        self.inertia = rot.Inertia(J=ac.ref("J"))
        self.idealRollingWheel = rot.IdealRollingWheel(radius=ac.ref("R"))
        self.mass = Mass(m=ac.ref("m"))
        self.windSpeed = Speed(s={"fixed": True})

    def equations(self):
        inputs = [ac.connect(getattr(self, port), getattr(self.fRoll, port))
                  for port in ("cr", "inclination") if getattr(self, self._inputs[port][0])]
        inclination = self.input_or_constant("inclination")
        return [*inputs,
                ac.Eq(self.s, self.mass.s), ac.Eq(self.v, self.mass.v),
                ac.Eq(self.a, self.mass.a),
                ac.Eq(self.windSpeed.v_ref, self.input_or_constant("vWind")),
                ac.Eq(self.fGrav.f, -self.m * self.g * ac.sin(ac.atan(inclination))),
                ac.connect(self.idealRollingWheel.flangeT, self.mass.flange_a),
                ac.connect(self.fDrag.support, self.windSpeed.flange),
                ac.connect(self.mass.flange_b, self.flangeT, self.fDrag.flange,
                           self.fRoll.flange, self.fGrav.flange),
                ac.connect(self.inertia.flange_b, self.idealRollingWheel.flangeR),
                ac.connect(self.flangeR, self.inertia.flange_a)]
