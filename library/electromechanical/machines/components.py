"""Parts of DC machines (Modelica.Electrical.Machines.BasicMachines.Components, MSL
v4.0.0): the air gap, the compound excitation and the inductor that may be
quasi-static."""
import acausal as ac
from acausal.ports import NegativePin, PositivePin, RotationalFlange

from ...electrical.interfaces import OnePort

__all__ = ["AirGapDC", "CompoundDCExcitation", "InductorDC"]


def _quasi_static(kind, value) -> bool:
    if not isinstance(value, bool):
        raise ac.ModelError(f"{kind}: quasiStatic must be True or False, not {value!r}")
    return value


class InductorDC(OnePort):
    """Inductor of a DC machine (BasicMachines.Components.InductorDC):

        v = L der(i),   or v = 0 when ``quasiStatic=True`` (no electrical transients)
    """

    L = ac.Parameter(1.0, unit="H", description="inductance")

    def stored_energy(self):
        """Magnetic energy L i^2/2 (none when quasi-static)."""
        return 0 * self.i if self.quasiStatic else self.L * self.i**2 / 2

    def __init__(self, *, quasiStatic=False, **modifications):
        super().__init__(**modifications)
        object.__setattr__(self, "quasiStatic", _quasi_static(type(self).__name__,
                                                              quasiStatic))

    def equations(self):
        return [ac.Eq(self.v, 0 if self.quasiStatic else self.L * ac.der(self.i))]


class AirGapDC(ac.Component):
    """Linear air gap of a DC machine (BasicMachines.Components.AirGapDC, with
    PartialAirGapDC):

        vai = pin_ap.v - pin_an.v,   ia = pin_ap.i = -pin_an.i
        vei = pin_ep.v - pin_en.v,   ie = pin_ep.i = -pin_en.i
        psi_e = Le ie,   vei = der(psi_e)  (0 with ``quasiStatic=True``)
        w = der(flange.phi) - der(support.phi)
        vai = turnsRatio psi_e w,   tauElectrical = turnsRatio psi_e ia
        flange.tau = -tauElectrical,   support.tau = tauElectrical
    """

    turnsRatio = ac.Parameter(1.0, unit="1", description="ratio of armature turns over "
                              "number of turns of the excitation winding")
    Le = ac.Parameter(1.0, unit="H", description="excitation inductance")
    flange = RotationalFlange()
    support = RotationalFlange()
    pin_ap = PositivePin()
    pin_ep = PositivePin()
    pin_an = NegativePin()
    pin_en = NegativePin()
    w = ac.Variable(unit="rad/s", description="angular velocity")
    vei = ac.Variable(unit="V", description="voltage drop across field excitation "
                                            "inductance")
    ie = ac.Variable(unit="A", description="excitation current")
    psi_e = ac.Variable(unit="Wb", description="excitation flux")
    vai = ac.Variable(unit="V", description="induced armature voltage")
    ia = ac.Variable(unit="A", description="armature current")
    tauElectrical = ac.Variable(unit="N.m", description="electrical torque")

    def stored_energy(self):
        """Magnetic energy of the excitation Le ie^2/2 (vei ie = its rate; none when
        quasi-static); vai ia = tauElectrical w is converted without loss."""
        return 0 * self.ie if self.quasiStatic else self.Le * self.ie**2 / 2

    def __init__(self, *, quasiStatic=False, **modifications):
        super().__init__(**modifications)
        object.__setattr__(self, "quasiStatic", _quasi_static(type(self).__name__,
                                                              quasiStatic))

    def equations(self):
        return [ac.Eq(self.vai, self.pin_ap.v - self.pin_an.v),
                ac.Eq(self.ia, self.pin_ap.i),
                ac.Eq(self.ia, -self.pin_an.i),
                ac.Eq(self.vei, self.pin_ep.v - self.pin_en.v),
                ac.Eq(self.ie, self.pin_ep.i),
                ac.Eq(self.ie, -self.pin_en.i),
                ac.Eq(self.vei, 0 if self.quasiStatic else ac.der(self.psi_e)),
                ac.Eq(self.w, ac.der(self.flange.phi) - ac.der(self.support.phi)),
                ac.Eq(self.vai, self.turnsRatio * self.psi_e * self.w),
                ac.Eq(self.tauElectrical, self.turnsRatio * self.psi_e * self.ia),
                ac.Eq(self.flange.tau, -self.tauElectrical),
                ac.Eq(self.support.tau, self.tauElectrical),
                ac.Eq(self.psi_e, self.Le * self.ie)]


class CompoundDCExcitation(ac.Component):
    """Shunt and series excitation acting on one air gap
    (BasicMachines.Components.CompoundDCExcitation):

        v = pin_p.v - pin_n.v,  i = pin_p.i;  ve = pin_ep.v - pin_en.v,  ie = pin_ep.i;
        vse = pin_sep.v - pin_sen.v,  ise = pin_sep.i;
        pin_p.i + pin_n.i = 0,  pin_ep.i + pin_en.i = 0,  pin_sep.i + pin_sen.i = 0
        -i = ie + excitationTurnsRatio ise,   ve = v,   vse = excitationTurnsRatio v
    """

    excitationTurnsRatio = ac.Parameter(1.0, unit="1", description="ratio of series "
                                        "excitation turns over shunt excitation turns")
    pin_p = PositivePin()
    pin_n = NegativePin()
    pin_ep = PositivePin()
    pin_en = NegativePin()
    pin_sep = PositivePin()
    pin_sen = NegativePin()
    v = ac.Variable(unit="V", description="voltage to the air gap")
    i = ac.Variable(unit="A", description="current to the air gap")
    ve = ac.Variable(unit="V", description="voltage of the shunt excitation")
    ie = ac.Variable(unit="A", description="current of the shunt excitation")
    vse = ac.Variable(unit="V", description="voltage of the series excitation")
    ise = ac.Variable(unit="A", description="current of the series excitation")

    energy_role = "lossless"   # an ideal transformer of excitations

    def equations(self):
        r = self.excitationTurnsRatio
        return [ac.Eq(self.v, self.pin_p.v - self.pin_n.v), ac.Eq(self.i, self.pin_p.i),
                ac.Eq(self.ve, self.pin_ep.v - self.pin_en.v), ac.Eq(self.ie, self.pin_ep.i),
                ac.Eq(self.vse, self.pin_sep.v - self.pin_sen.v),
                ac.Eq(self.ise, self.pin_sep.i),
                ac.Eq(self.pin_p.i + self.pin_n.i, 0),
                ac.Eq(self.pin_ep.i + self.pin_en.i, 0),
                ac.Eq(self.pin_sep.i + self.pin_sen.i, 0),
                ac.Eq(-self.i, self.ie + r * self.ise),
                ac.Eq(self.ve, self.v),
                ac.Eq(self.vse, self.v * r)]
