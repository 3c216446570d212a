"""Semiconductor devices (Modelica.Electrical.Analog.Semiconductors, MSL v4.0.0): diodes,
the thyristor and the triac.  The transistors are in :mod:`.transistors`.

The MSL writes the exponential laws through the package's functions ``exlin``,
``exlin2`` and ``powlin``; relations inside a Modelica function generate no events, so
:func:`exlin`, :func:`exlin2` and :func:`powlin` evaluate theirs directly
(``ac.no_event``): each is continuous with its first derivative at its break points.
"""
from acausal._sympy import sympy as sp

import acausal as ac
from acausal.ports import NegativePin, PositivePin

from .ideal import IdealDiode
from .interfaces import ConditionalHeatPort, OnePort

__all__ = ["Diode", "ZDiode", "Thyristor", "SimpleTriac", "exlin", "exlin2", "powlin"]


def boltzmann():
    """Boltzmann's constant k (Modelica.Constants.k), a parameter in J/K."""
    return ac.Parameter(1.380649e-23, unit="J/K", description="Boltzmann's constant")


def electron_charge():
    """The elementary charge q (Modelica.Constants.q), a parameter in C."""
    return ac.Parameter(1.602176634e-19, unit="C", description="elementary charge")


def exlin(x, Maxexp):
    """exp(x), continued by its tangent above x = Maxexp (the MSL's ``exlin``)."""
    return ac.no_event(ac.if_else(x > Maxexp, sp.exp(Maxexp) * (1 + x - Maxexp), sp.exp(x)))


def exlin2(x, Minexp, Maxexp, *, events=False):
    """exp(x), continued by its tangents below x = Minexp and above x = Maxexp (the
    MSL's ``exlin2``); ``events=True`` lets its relations generate events (for an
    argument that depends on parameters and temperatures only)."""
    law = ac.if_else(x < Minexp, sp.exp(Minexp) * (1 + x - Minexp),
                     ac.if_else(x > Maxexp, sp.exp(Maxexp) * (1 + x - Maxexp), sp.exp(x)))
    return law if events else ac.no_event(law)


def powlin(x, y):
    """(1 - x)^(-y), continued by its tangent above x = 0 (the MSL's ``powlin``)."""
    return ac.no_event(ac.if_else(x > 0, 1 + y * x, (1 - x) ** (-y)))


class Diode(OnePort, ConditionalHeatPort):
    """Simple diode (Modelica.Electrical.Analog.Semiconductors.Diode, MSL v4.0.0): the
    Shockley law continued linearly above Maxexp, with a parallel ohmic resistance:

        i = Ids (exlin(v/Vt, Maxexp) - 1) + v/R

    With ``useTemperatureDependency=True`` (structural) the thermal voltage and the
    saturation current follow the device temperature T_heatPort:

        vt_t = k T_heatPort / q,   aux = (T_heatPort/TNOM - 1) EG / (N vt_t)
        i = Ids (exlin(v/(N vt_t), Maxexp) - 1) (T_heatPort/TNOM)^(XTI/N) exp(aux) + v/R

    LossPower = v i.  (The MSL also gives the diode its heat port when it depends on
    temperature; without it the device is at the fixed temperature T.)
    """

    Ids = ac.Parameter(1e-6, unit="A", description="saturation current")
    useTemperatureDependency = ac.Parameter(False, structural=True,
                                            description="the current depends on temperature")
    Vt = ac.Parameter(0.04, unit="V", description="voltage equivalent of temperature (kT/qn)")
    Maxexp = ac.Parameter(15.0, min=1e-60,
                          description="max. exponent for linear continuation")
    R = ac.Parameter(1e8, unit="Ohm", description="parallel ohmic resistance")
    EG = ac.Parameter(1.11, unit="V", description="activation energy")
    N = ac.Parameter(1.0, description="emission coefficient")
    TNOM = ac.Parameter(300.15, unit="K", min=0, description="parameter measurement temperature")
    XTI = ac.Parameter(3.0, description="temperature exponent of saturation current")
    k = boltzmann()
    q = electron_charge()
    vt_t = ac.Variable(unit="V", description="temperature voltage")
    id = ac.Variable(unit="A", description="diode current")

    def equations(self):
        htemp = self.T_heatPort
        if self.useTemperatureDependency:
            aux = (htemp / self.TNOM - 1) * self.EG / (self.N * self.vt_t)
            law = [ac.Eq(self.id, self.Ids * (exlin(self.v / (self.N * self.vt_t),
                                                    self.Maxexp) - 1)),
                   ac.Eq(self.i, self.id * (htemp / self.TNOM) ** (self.XTI / self.N)
                         * sp.exp(aux) + self.v / self.R)]
        else:
            law = [ac.Eq(self.id, self.Ids * (exlin(self.v / self.Vt, self.Maxexp) - 1)),
                   ac.Eq(self.i, self.id + self.v / self.R)]
        return [ac.Eq(self.vt_t, self.k * htemp / self.q),
                *law,
                ac.Eq(self.LossPower, self.v * self.i)]


class ZDiode(OnePort, ConditionalHeatPort):
    """Zener diode with three working areas (Modelica.Electrical.Analog.Semiconductors.
    ZDiode, MSL v4.0.0): forward, blocking and breakthrough, each exponential branch
    continued by its tangent beyond Maxexp:

        v > Maxexp Vt:               i = Ids (e^Maxexp (1 + v/Vt - Maxexp) - 1) + v/R
        v + Bv < -Maxexp Nbv Vt:     i = -Ids - Ibv e^Maxexp (1 - (v+Bv)/(Nbv Vt) - Maxexp) + v/R
        otherwise:                   i = Ids (e^(v/Vt) - 1) - Ibv e^(-(v+Bv)/(Nbv Vt)) + v/R

    LossPower = v i.
    """

    Ids = ac.Parameter(1e-6, unit="A", description="saturation current")
    Vt = ac.Parameter(0.04, unit="V", description="voltage equivalent of temperature (kT/qn)")
    Maxexp = ac.Parameter(30.0, min=1e-60,
                          description="max. exponent for linear continuation")
    R = ac.Parameter(1e8, unit="Ohm", description="parallel ohmic resistance")
    Bv = ac.Parameter(5.1, unit="V", description="breakthrough voltage = Zener voltage")
    Ibv = ac.Parameter(0.7, unit="A", description="breakthrough knee current")
    Nbv = ac.Parameter(0.74, description="breakthrough emission coefficient")

    def equations(self):
        v, Vt, Mx = self.v, self.Vt, self.Maxexp
        nvt = self.Nbv * Vt
        forward = self.Ids * (sp.exp(Mx) * (1 + v / Vt - Mx) - 1)
        breakthrough = -self.Ids - self.Ibv * sp.exp(Mx) * (1 - (v + self.Bv) / nvt - Mx)
        between = self.Ids * (sp.exp(v / Vt) - 1) - self.Ibv * sp.exp(-(v + self.Bv) / nvt)
        return [ac.Eq(self.i, ac.if_else(v > Mx * Vt, forward,
                                         ac.if_else(v + self.Bv < -Mx * nvt, breakthrough,
                                                    between)) + v / self.R),
                ac.Eq(self.LossPower, v * self.i)]


class Thyristor(ConditionalHeatPort):
    """Simple thyristor (Modelica.Electrical.Analog.Semiconductors.Thyristor, MSL
    v4.0.0).  The gate is a resistive diode, the anode-cathode path a resistance between
    Roff = VDRM^2/(VTM IH) and Ron = (VTM - 0.7 V)/ITM set by the control voltage
    vControl, which follows its target vContot with the switch-on time constant 1.87 TON
    when rising and 0.638 TOFF when falling:

        vGK = VGT/IGT iGK                                (vGK < 0.65 V)
        vGK = (0.65 V)^2/VGT + iGK (VGT - 0.65 V)/IGT    (otherwise)
        vConmain = Von if Anode.i > IH or vAK > VDRM else 0
        vContot = vConmain + {0, 1e4/A (iGK - 0.95 IGT) vAK, 10 vAK}  by iGK
        der(vControl) = (vContot - vControl) / (1.87 TON | 0.638 TOFF)
        Anode.i = -VRRM/Roff exp(-(vAK + VRRM)/(Nbv Vt))    (vAK < -VRRM, breakthrough)
                  vAK/Roff                                  (vControl < Voff)
                  vAK/(sqrt(Ron Roff) (Ron/Roff)^((3 z - 4 z^3)/2))   (Voff <= vControl < Von)
                  vAK/Ron                                   (vControl >= Von)
        z = (2 vControl - Von - Voff)/(2 (Von - Voff)),  Von = 5 V,  Voff = 1.5 V

    and the pins' currents sum to zero.  LossPower is the power into the three pins.
    """

    VDRM = ac.Parameter(100.0, unit="V", min=0, description="forward breakthrough voltage")
    VRRM = ac.Parameter(100.0, unit="V", min=0, description="reverse breakthrough voltage")
    IDRM = ac.Parameter(0.1, unit="A", description="saturation current")
    VTM = ac.Parameter(1.7, unit="V", description="conducting voltage")
    IH = ac.Parameter(6e-3, unit="A", description="holding current")
    ITM = ac.Parameter(25.0, unit="A", description="conducting current")
    VGT = ac.Parameter(0.7, unit="V", description="gate trigger voltage")
    IGT = ac.Parameter(5e-3, unit="A", description="gate trigger current")
    TON = ac.Parameter(1e-6, unit="s", description="switch on time")
    TOFF = ac.Parameter(15e-6, unit="s", description="switch off time")
    Vt = ac.Parameter(0.04, unit="V", description="voltage equivalent of temperature (kT/qn)")
    Nbv = ac.Parameter(0.74, description="reverse breakthrough emission coefficient")
    Von = ac.Parameter(5.0, unit="V", description="control voltage of the conducting state")
    Voff = ac.Parameter(1.5, unit="V", description="control voltage of the blocking state")
    Ron = ac.Parameter(lambda c: (c.VTM - 0.7) / c.ITM, unit="Ohm",
                       description="forward conducting mode resistance")
    Roff = ac.Parameter(lambda c: c.VDRM**2 / c.VTM / c.IH, unit="Ohm",
                        description="blocking mode resistance")
    vGKknee = ac.Parameter(0.65, unit="V", description="knee of the gate (the MSL's 0.65)")
    gainGate = ac.Parameter(1e4, unit="1/A",
                            description="slope of the gate's firing ramp (the MSL's 10000)")

    Anode = PositivePin()
    Cathode = NegativePin()
    Gate = PositivePin()
    iGK = ac.Variable(unit="A", description="gate current")
    vGK = ac.Variable(unit="V", description="voltage between gate and cathode")
    vAK = ac.Variable(unit="V", description="voltage between anode and cathode")
    vControl = ac.Variable(start=0.0, unit="V", description="control voltage")
    vContot = ac.Variable(unit="V", description="target of the control voltage")
    vConmain = ac.Variable(unit="V", description="holding and breakthrough part of vContot")

    def equations(self):
        vAK, iGK, vCon = self.vAK, self.iGK, self.vControl
        knee = self.vGKknee
        gate = ac.if_else(self.vGK < knee, self.VGT / self.IGT * iGK,
                          knee**2 / self.VGT + iGK * (self.VGT - knee) / self.IGT)
        fire = ac.if_else(iGK < 0.95 * self.IGT, 0,
                          ac.if_else(iGK < 0.95 * self.IGT + 1e-3,
                                     self.gainGate * (iGK - 0.95 * self.IGT) * vAK,
                                     10 * vAK))
        rising = self.vContot - vCon > 0
        z = (2 * vCon - self.Von - self.Voff) / (2 * (self.Von - self.Voff))
        between = vAK / (sp.sqrt(self.Ron * self.Roff)
                         * (self.Ron / self.Roff) ** ((3 * z - 4 * z**3) / 2))
        anode = ac.if_else(vAK < -self.VRRM,
                           -self.VRRM / self.Roff * sp.exp(-(vAK + self.VRRM)
                                                           / (self.Nbv * self.Vt)),
                           ac.if_else(vCon < self.Voff, vAK / self.Roff,
                                      ac.if_else(vCon < self.Von, between, vAK / self.Ron)))
        holding = sp.Or(self.Anode.i > self.IH, vAK > self.VDRM)
        return [ac.Eq(0, self.Anode.i + self.Gate.i + self.Cathode.i),
                ac.Eq(self.vGK, self.Gate.v - self.Cathode.v),
                ac.Eq(self.vAK, self.Anode.v - self.Cathode.v),
                ac.Eq(self.iGK, self.Gate.i),
                ac.Eq(self.vGK, gate),
                ac.Eq(self.vContot, self.vConmain + fire),
                ac.Eq(ac.der(vCon), (self.vContot - vCon)
                      / ac.if_else(rising, 1.87 * self.TON, 0.638 * self.TOFF)),
                ac.Eq(self.Anode.i, anode),
                ac.Eq(self.vConmain, ac.if_else(holding, self.Von, 0)),
                ac.Eq(self.LossPower, self.Anode.i * self.Anode.v
                      + self.Cathode.i * self.Cathode.v + self.Gate.i * self.Gate.v)]


_THYRISTOR_PARAMETERS = ("VDRM", "VRRM", "IDRM", "VTM", "IH", "ITM", "VGT", "IGT", "TON",
                         "TOFF", "Vt", "Nbv", "T")


class SimpleTriac(ConditionalHeatPort):
    """Simple triac (Modelica.Electrical.Analog.Semiconductors.SimpleTriac, MSL v4.0.0):
    two anti-parallel :class:`Thyristor` s (``thyristor`` from n to p, ``thyristor1`` from
    p to n) whose gates are fed from ``g`` through ideal diodes (Vknee = 0).  The
    parameters are those of the thyristors.  LossPower is the power into the three pins.
    """

    VDRM = ac.Parameter(100.0, unit="V", min=0, description="forward breakthrough voltage")
    VRRM = ac.Parameter(100.0, unit="V", min=0, description="reverse breakthrough voltage")
    IDRM = ac.Parameter(0.1, unit="A", description="saturation current")
    VTM = ac.Parameter(1.7, unit="V", description="conducting voltage")
    IH = ac.Parameter(6e-3, unit="A", description="holding current")
    ITM = ac.Parameter(25.0, unit="A", description="conducting current")
    VGT = ac.Parameter(0.7, unit="V", description="gate trigger voltage")
    IGT = ac.Parameter(5e-3, unit="A", description="gate trigger current")
    TON = ac.Parameter(1e-6, unit="s", description="switch on time")
    TOFF = ac.Parameter(15e-6, unit="s", description="switch off time")
    Vt = ac.Parameter(0.04, unit="V", description="voltage equivalent of temperature (kT/qn)")
    Nbv = ac.Parameter(0.74, description="reverse breakthrough emission coefficient")

    n = NegativePin()
    p = PositivePin()
    g = PositivePin()
    thyristor = Thyristor(**{name: ac.ref(name) for name in _THYRISTOR_PARAMETERS})
    thyristor1 = Thyristor(**{name: ac.ref(name) for name in _THYRISTOR_PARAMETERS})
    idealDiode = IdealDiode(Vknee=0.0)
    idealDiode1 = IdealDiode(Vknee=0.0)

    def equations(self):
        return [ac.connect(self.thyristor.Anode, self.n),
                ac.connect(self.thyristor1.Anode, self.p),
                ac.connect(self.thyristor1.Anode, self.thyristor.Cathode),
                ac.connect(self.thyristor1.Cathode, self.thyristor.Anode),
                ac.connect(self.thyristor.Gate, self.idealDiode.n),
                ac.connect(self.idealDiode.p, self.g),
                ac.connect(self.idealDiode1.n, self.thyristor1.Gate),
                ac.connect(self.idealDiode1.p, self.g),
                ac.Eq(self.LossPower, self.p.i * self.p.v + self.n.i * self.n.v
                      + self.g.i * self.g.v)]
