"""DC machines (Modelica.Electrical.Machines.BasicMachines.DCMachines, MSL v4.0.0): the
permanent magnet, the electrically (shunt or separately) excited and the series excited
machine, with their losses, built as the MSL builds them.

The armature: pin_ap -> strayLoad -> ra (resistance at the armature's temperature) ->
la -> the air gap's armature -> brush -> pin_an, with the core losses across la and the
air gap.  The rotor (inertiaRotor, Jr) carries the air gap's torque to the flange,
braked by friction and stray load; the stator (inertiaStator, Js) is fixed, or, with
``useSupport=True``, mounted on a ``support`` flange that takes the reaction torque.
The excitation: a constant current of 1 A in an inductance of 1 H (permanent magnet),
re -> lesigma -> a CompoundDCExcitation (its shunt side, or its series side) on the air
gap.  Every loss leaves through a heat port into ``thermalAmbient``, which holds the
armature at TaOperational, the excitation at TeOperational and the rest at 20 degC (the
MSL's ``useThermalPort = false``; the machines' thermal port is not here yet).

turnsRatio = ViNominal / (wNominal psi_eNominal) scales the air gap so that the machine
induces ViNominal, the nominal voltage less the resistive and brush drops at IaNominal
and TaNominal, at wNominal.
"""
import acausal as ac
from acausal.ports import NegativePin, PositivePin, RotationalFlange

from ...electrical import ConstantCurrent, Ground, HeatingResistor
from ...rotational import Fixed, Inertia
from .components import AirGapDC, CompoundDCExcitation, InductorDC
from .losses import Brush, Core, Friction, StrayLoad, brushVoltageDrop
from .records import (BrushParameters, CoreParameters, FrictionParameters,
                      StrayLoadParameters, passed)
from .thermal import (ThermalAmbientDCEE, ThermalAmbientDCPM, ThermalAmbientDCSE,
                      convertAlpha, convertResistance)

__all__ = ["PartialBasicMachine", "PartialBasicDCMachine", "DC_PermanentMagnet",
           "DC_ElectricalExcited", "DC_SeriesExcited"]


class PartialBasicMachine(ac.Component):
    """What every machine has (Modelica.Electrical.Machines.Interfaces.
    PartialBasicMachine): the shaft ``flange`` on the rotor's inertia, the stator's
    inertia, bearing friction, and

        phiMechanical = flange.phi - internalSupport.phi,   wMechanical = der(phiMechanical)
        tauElectrical = inertiaRotor.flange_a.tau,   tauShaft = -flange.tau
    """

    Jr = ac.Parameter(0.15, unit="kg.m2", description="rotor's moment of inertia")
    Js = ac.Parameter(lambda c: c.Jr, unit="kg.m2", description="stator's moment of "
                                                                "inertia")
    phiMechanical = ac.Variable(start=0.0, unit="rad",
                                description="mechanical angle of rotor against stator")
    wMechanical = ac.Variable(start=0.0, unit="rad/s", description="mechanical angular "
                                                                   "velocity of rotor "
                                                                   "against stator")
    tauElectrical = ac.Variable(unit="N.m", description="electromagnetic torque")
    tauShaft = ac.Variable(unit="N.m", description="shaft torque")
    flange = RotationalFlange()
    inertiaRotor = Inertia(J=ac.ref("Jr"))
    inertiaStator = Inertia(J=ac.ref("Js"))

    useSupport = ac.Parameter(False, structural=True,
                              description="use the support flange, else the housing is "
                                          "fixed")
    support = ac.Conditional(RotationalFlange(), "useSupport")
    fixed = ac.Conditional(Fixed(), "useSupport", when=False)

    def build(self):
        self.frictionParameters = FrictionParameters()
        self.friction = Friction(useHeatPort=True,
                                 frictionParameters=passed(self, "frictionParameters"))

    def support_side(self) -> list:
        """The flanges that act on the housing (the MSL's internalSupport)."""
        return [self.inertiaStator.flange_a, self.friction.support]

    def equations(self):
        support = self.support_side()
        eqs = [ac.connect(self.inertiaRotor.flange_b, self.flange),
               ac.connect(self.inertiaRotor.flange_b, self.friction.flange),
               ac.connect(*support, *([] if self.useSupport
                                      else [self.fixed.flange])),
               ac.Eq(self.phiMechanical, self.flange.phi - support[0].phi),
               ac.Eq(self.wMechanical, ac.der(self.phiMechanical)),
               ac.Eq(self.tauElectrical, self.inertiaRotor.flange_a.tau),
               ac.Eq(self.tauShaft, -self.flange.tau)]
        if self.useSupport:
            eqs.append(ac.connect(self.inertiaStator.flange_b, self.support))
        return eqs


class PartialBasicDCMachine(PartialBasicMachine):
    """What every DC machine has (Modelica.Electrical.Machines.Interfaces.
    PartialBasicDCMachine): the armature pins, its resistance (temperature dependent,
    Ra at TaRef with the coefficient alpha20a at 20 degC), inductance, brushes, core
    and stray load losses, and

        va = pin_ap.v - pin_an.v,   ia = pin_ap.i

    ``quasiStatic`` (a class constant; True in ``machines.quasi_static``) drops the
    electrical transients: la and the air gap's excitation have no voltage.
    """

    quasiStatic = False

    TaOperational = ac.Parameter(293.15, unit="K", min=0,
                                 description="operational armature temperature")
    VaNominal = ac.Parameter(100.0, unit="V", description="nominal armature voltage")
    IaNominal = ac.Parameter(100.0, unit="A", description="nominal armature current "
                                                          "(>0: motor, <0: generator)")
    wNominal = ac.Parameter(1425 * 2 * 3.141592653589793 / 60, unit="rad/s",
                            description="nominal speed")
    TaNominal = ac.Parameter(293.15, unit="K", min=0,
                             description="nominal armature temperature")
    Ra = ac.Parameter(0.05, unit="Ohm", description="armature resistance at TaRef")
    TaRef = ac.Parameter(293.15, unit="K", min=0,
                         description="reference temperature of armature resistance")
    alpha20a = ac.Parameter(0.0, unit="1/K", description="temperature coefficient of "
                                                         "armature resistance at 20 degC")
    La = ac.Parameter(0.0015, unit="H", description="armature inductance")
    alphaRef = ac.Parameter(lambda c: convertAlpha(c.alpha20a, c.TaRef), unit="1/K",
                            description="temperature coefficient of ra at TaRef")
    turnsRatio = ac.Parameter(lambda c: c.ViNominal / (c.wNominal * c.psi_eNominal),
                              unit="1", description="ratio of armature turns over number "
                              "of turns of the excitation winding")
    va = ac.Variable(unit="V", description="armature voltage")
    ia = ac.Variable(start=0.0, unit="A", description="armature current")
    pin_ap = PositivePin()
    pin_an = NegativePin()

    def build(self):
        super().build()
        self.frictionParameters = FrictionParameters(wRef=ac.ref("wNominal"))
        self.coreParameters = CoreParameters(m=1.0, VRef=ac.ref("ViNominal"),
                                             wRef=ac.ref("wNominal"))
        self.strayLoadParameters = StrayLoadParameters(IRef=ac.ref("IaNominal"),
                                                       wRef=ac.ref("wNominal"))
        self.brushParameters = BrushParameters(ILinear=self._bound(lambda m: 0.01
                                                                   * m.IaNominal))
        self.ra = HeatingResistor(R_ref=ac.ref("Ra"), T_ref=ac.ref("TaRef"),
                                  alpha=ac.ref("alphaRef"))
        self.la = InductorDC(L=ac.ref("La"), quasiStatic=self.quasiStatic)
        self.brush = Brush(useHeatPort=True, brushParameters=passed(self, "brushParameters"))
        self.core = Core(useHeatPort=True, coreParameters=passed(self, "coreParameters"))
        self.strayLoad = StrayLoad(useHeatPort=True,
                                   strayLoadParameters=passed(self, "strayLoadParameters"))
        self.airGapDC = AirGapDC(turnsRatio=ac.ref("turnsRatio"), Le=ac.ref("Lme"),
                                 quasiStatic=self.quasiStatic)

    def _bound(self, expression):
        """A parameter value that is an expression of this machine's parameters (a
        modification of a record in the MSL)."""
        return lambda _: expression(self)

    def nominal_drop(self):
        """The brushes' voltage drop at IaNominal (the MSL's brushVoltageDrop)."""
        return brushVoltageDrop(self.brushParameters, self.IaNominal)

    def support_side(self):
        return [*super().support_side(), self.strayLoad.support, self.airGapDC.support]

    def equations(self):
        port = self.thermalAmbient
        return [ac.Eq(self.va, self.pin_ap.v - self.pin_an.v),
                ac.Eq(self.ia, self.pin_ap.i),
                ac.connect(self.la.p, self.ra.n),
                ac.connect(self.brush.n, self.pin_an),
                ac.connect(self.pin_ap, self.strayLoad.p),
                ac.connect(self.strayLoad.n, self.ra.p),
                ac.connect(self.la.p, self.core.p),
                ac.connect(self.core.n, self.brush.p),
                ac.connect(self.inertiaRotor.flange_b, self.strayLoad.flange),
                ac.connect(self.airGapDC.pin_ap, self.la.n),
                ac.connect(self.airGapDC.flange, self.inertiaRotor.flange_a),
                ac.connect(self.airGapDC.pin_an, self.brush.p),
                ac.connect(self.core.heatPort, port.heatPortCore),
                ac.connect(self.brush.heatPort, port.heatPortBrush),
                ac.connect(self.strayLoad.heatPort, port.heatPortStrayLoad),
                ac.connect(self.friction.heatPort, port.heatPortFriction),
                ac.connect(self.ra.heatPort, port.heatPortArmature)]


class DC_PermanentMagnet(PartialBasicDCMachine):
    """Permanent magnet DC machine (Modelica.Electrical.Machines.BasicMachines.
    DCMachines.DC_PermanentMagnet): the magnet is an excitation of 1 A (ie, a constant
    current) in Lme = 1 H, so psi_eNominal = 1 Wb, and

        ViNominal = VaNominal - Ra(TaNominal) IaNominal - brushVoltageDrop(IaNominal)
    """

    TpmOperational = ac.Parameter(293.15, unit="K", min=0,
                                  description="operational temperature of permanent magnet")
    Lme = ac.Parameter(1.0, unit="H", description="field excitation inductance")
    IeNominal = ac.Parameter(1.0, unit="A", description="equivalent excitation current")
    psi_eNominal = ac.Parameter(lambda c: c.Lme * c.IeNominal, unit="Wb",
                                description="nominal magnetic flux")
    ViNominal = ac.Parameter(lambda c: c.VaNominal - convertResistance(
        c.Ra, c.TaRef, c.alpha20a, c.TaNominal) * c.IaNominal - c.nominal_drop(), unit="V",
        description="nominal induced voltage")
    eGround = Ground()
    ie = ConstantCurrent(I=ac.ref("IeNominal"))

    def build(self):
        super().build()
        self.thermalAmbient = ThermalAmbientDCPM(Ta=ac.ref("TaOperational"),
                                                 Tpm=ac.ref("TpmOperational"))

    def equations(self):
        return [ac.connect(self.eGround.p, self.ie.p),
                ac.connect(self.airGapDC.pin_ep, self.ie.n),
                ac.connect(self.airGapDC.pin_en, self.eGround.p)]


class _ExcitedDCMachine(PartialBasicDCMachine):
    """An excitation winding re -> lesigma on the compound excitation of the air gap
    (DC_ElectricalExcited and DC_SeriesExcited): Le = Lme + Lesigma, Lme = Le (1 -
    sigmae) the main and Lesigma = Le sigmae the stray part; re is Re at TeRef with the
    coefficient alpha20e at 20 degC, at the temperature TeOperational."""

    Re = ac.Parameter(100.0, unit="Ohm", description="field excitation resistance at TeRef")
    TeRef = ac.Parameter(293.15, unit="K", min=0,
                         description="reference temperature of excitation resistance")
    alpha20e = ac.Parameter(0.0, unit="1/K", description="temperature coefficient of "
                            "excitation resistance at 20 degC")
    Le = ac.Parameter(1.0, unit="H", description="total field excitation inductance")
    sigmae = ac.Parameter(0.0, unit="1", min=0, max=0.99,
                          description="stray fraction of total excitation inductance")
    TeOperational = ac.Parameter(293.15, unit="K", min=0,
                                 description="operational excitation temperature")
    Lme = ac.Parameter(lambda c: c.Le * (1 - c.sigmae), unit="H",
                       description="main part of excitation inductance")
    Lesigma = ac.Parameter(lambda c: c.Le * c.sigmae, unit="H",
                           description="stray part of excitation inductance")
    alphaRefe = ac.Parameter(lambda c: convertAlpha(c.alpha20e, c.TeRef), unit="1/K",
                             description="temperature coefficient of re at TeRef")
    ve = ac.Variable(unit="V", description="field excitation voltage")
    ie = ac.Variable(start=0.0, unit="A", description="field excitation current")
    pin_ep = PositivePin()
    pin_en = NegativePin()
    ground = Ground()
    compoundDCExcitation = CompoundDCExcitation(excitationTurnsRatio=1.0)

    def build(self):
        super().build()
        self.re = HeatingResistor(R_ref=ac.ref("Re"), T_ref=ac.ref("TeRef"),
                                  alpha=ac.ref("alphaRefe"))
        self.lesigma = InductorDC(L=ac.ref("Lesigma"), quasiStatic=self.quasiStatic)

    def equations(self):
        cde = self.compoundDCExcitation
        return [ac.Eq(self.ve, self.pin_ep.v - self.pin_en.v),
                ac.Eq(self.ie, self.pin_ep.i),
                ac.connect(self.re.n, self.lesigma.p),
                ac.connect(self.airGapDC.pin_en, cde.pin_n, self.ground.p),
                ac.connect(self.airGapDC.pin_ep, cde.pin_p)]


class DC_ElectricalExcited(_ExcitedDCMachine):
    """Shunt or separately excited linear DC machine (Modelica.Electrical.Machines.
    BasicMachines.DCMachines.DC_ElectricalExcited): the excitation pins pin_ep, pin_en
    feed the shunt side of the compound excitation; psi_eNominal = Lme IeNominal and

        ViNominal = VaNominal - Ra(TaNominal) IaNominal - brushVoltageDrop(IaNominal)
    """

    IeNominal = ac.Parameter(1.0, unit="A", description="nominal excitation current")
    psi_eNominal = ac.Parameter(lambda c: c.Lme * c.IeNominal, unit="Wb",
                                description="nominal magnetic flux")
    ViNominal = ac.Parameter(lambda c: c.VaNominal - convertResistance(
        c.Ra, c.TaRef, c.alpha20a, c.TaNominal) * c.IaNominal - c.nominal_drop(), unit="V",
        description="nominal induced voltage")
    groundSE = Ground()

    def build(self):
        super().build()
        self.thermalAmbient = ThermalAmbientDCEE(Ta=ac.ref("TaOperational"),
                                                 Te=ac.ref("TeOperational"))

    def equations(self):
        cde = self.compoundDCExcitation
        return [ac.connect(self.re.p, self.pin_ep),
                ac.connect(self.groundSE.p, cde.pin_sen),
                ac.connect(self.pin_en, cde.pin_en),
                ac.connect(cde.pin_ep, self.lesigma.n),
                ac.connect(self.re.heatPort, self.thermalAmbient.heatPortExcitation)]


class DC_SeriesExcited(_ExcitedDCMachine):
    """Series excited linear DC machine (Modelica.Electrical.Machines.BasicMachines.
    DCMachines.DC_SeriesExcited): the excitation pins pin_ep, pin_en feed the series side
    of the compound excitation, to be connected in series with the armature;
    psi_eNominal = Lme |IaNominal| and

        ViNominal = VaNominal - (Ra(TaNominal) + Re(TeNominal)) IaNominal
                    - brushVoltageDrop(IaNominal)
    """

    wNominal = ac.Parameter(1410 * 2 * 3.141592653589793 / 60, unit="rad/s",
                            description="nominal speed")
    Re = ac.Parameter(0.01, unit="Ohm", description="series excitation resistance at TeRef")
    Le = ac.Parameter(0.0005, unit="H", description="total field excitation inductance")
    TeNominal = ac.Parameter(293.15, unit="K", min=0,
                             description="nominal series excitation temperature")
    psi_eNominal = ac.Parameter(lambda c: c.Lme * ac.abs(c.IaNominal), unit="Wb",
                                description="nominal magnetic flux")
    ViNominal = ac.Parameter(lambda c: c.VaNominal - (
        convertResistance(c.Ra, c.TaRef, c.alpha20a, c.TaNominal)
        + convertResistance(c.Re, c.TeRef, c.alpha20e, c.TeNominal)) * c.IaNominal
        - c.nominal_drop(), unit="V", description="nominal induced voltage")
    groundE = Ground()

    def build(self):
        super().build()
        self.thermalAmbient = ThermalAmbientDCSE(Ta=ac.ref("TaOperational"),
                                                 Tse=ac.ref("TeOperational"))

    def equations(self):
        cde = self.compoundDCExcitation
        return [ac.connect(self.pin_ep, self.re.p),
                ac.connect(cde.pin_sen, self.pin_en),
                ac.connect(cde.pin_sep, self.lesigma.n),
                ac.connect(cde.pin_en, self.groundE.p),
                ac.connect(self.re.heatPort, self.thermalAmbient.heatPortSeriesExcitation)]
