"""Transistors (Modelica.Electrical.Analog.Semiconductors, MSL v4.0.0): the Ebers-Moll
bipolar transistors ``NPN`` and ``PNP`` and the MOS transistors ``NMOS`` and ``PMOS``.

With ``useTemperatureDependency=True`` (structural) their parameters follow the device
temperature T_heatPort; the MSL then also gives them their heat port, which is not here
yet: the device is at the fixed temperature T (:class:`~.interfaces.ConditionalHeatPort`).
The substrate pin of the bipolar transistors (``useSubstrate``) is not here either: the
substrate is grounded, as with the MSL's default useSubstrate = false.
"""
from acausal._sympy import sympy as sp

import acausal as ac
from acausal.ports import Pin

from .interfaces import ConditionalHeatPort
from .semiconductors import boltzmann, electron_charge, exlin2, powlin

__all__ = ["NPN", "PNP", "NMOS", "PMOS"]


class _BipolarTransistor(ConditionalHeatPort):
    """Parameters, temperature laws and substrate of the MSL's NPN and PNP."""

    Bf = ac.Parameter(50.0, description="forward beta")
    Br = ac.Parameter(0.1, description="reverse beta")
    Is = ac.Parameter(1e-16, unit="A", description="transport saturation current")
    Vak = ac.Parameter(0.02, unit="1/V", description="early voltage (inverse)")
    Tauf = ac.Parameter(0.12e-9, unit="s", description="ideal forward transit time")
    Taur = ac.Parameter(5e-9, unit="s", description="ideal reverse transit time")
    Ccs = ac.Parameter(1e-12, unit="F", min=0, description="collector-substrate (ground) cap.")
    Cje = ac.Parameter(0.4e-12, unit="F", min=0, description="base-emitter zero bias depletion cap.")
    Cjc = ac.Parameter(0.5e-12, unit="F", min=0, description="base-coll. zero bias depletion cap.")
    Phie = ac.Parameter(0.8, unit="V", description="base-emitter diffusion voltage")
    Me = ac.Parameter(0.4, description="base-emitter gradation exponent")
    Phic = ac.Parameter(0.8, unit="V", description="base-collector diffusion voltage")
    Mc = ac.Parameter(0.333, description="base-collector gradation exponent")
    Gbc = ac.Parameter(1e-15, unit="S", description="base-collector conductance")
    Gbe = ac.Parameter(1e-15, unit="S", description="base-emitter conductance")
    EMin = ac.Parameter(-100.0, description="if x < EMin, the exp(x) function is linearized")
    EMax = ac.Parameter(40.0, description="if x > EMax, the exp(x) function is linearized")
    useTemperatureDependency = ac.Parameter(
        False, structural=True, description="Bf, Br, Is and Vt depend on temperature")
    Vt = ac.Parameter(0.02585, unit="V", description="voltage equivalent of temperature")
    Tnom = ac.Parameter(300.15, unit="K", min=0, description="parameter measurement temperature")
    XTI = ac.Parameter(3.0, description="temperature exponent for effect on Is")
    XTB = ac.Parameter(0.0, description="forward and reverse beta temperature exponent")
    EG = ac.Parameter(1.11, unit="V", description="energy gap for temperature effect on Is")
    NF = ac.Parameter(1.0, description="forward current emission coefficient")
    NR = ac.Parameter(1.0, description="reverse current emission coefficient")
    IC = ac.Parameter(0.0, unit="V", description="initial value of collector to substrate voltage")
    UIC = ac.Parameter(False, structural=True,
                       description="the initial value IC is used (vcs = IC at the start)")
    k = boltzmann()
    q = electron_charge()

    C = Pin()
    B = Pin()
    E = Pin()
    vcs = ac.Variable(unit="V", description="collector-substrate voltage")
    qbk = ac.Variable(description="relative majority carrier charge, inverse")
    Capcje = ac.Variable(unit="F", description="effective base-emitter depletion capacitance")
    Capcjc = ac.Variable(unit="F", description="effective base-collector depletion capacitance")
    is_t = ac.Variable(unit="A", description="temperature dependent transport saturation current")
    br_t = ac.Variable(description="temperature dependent reverse beta")
    bf_t = ac.Variable(description="temperature dependent forward beta")
    vt_t = ac.Variable(unit="V", description="voltage equivalent of effective temperature")
    hexp = ac.Variable(description="auxiliary quantity temperature dependent exponent")
    htempexp = ac.Variable(description="auxiliary quantity exp(hexp)")
    vS = ac.Variable(unit="V", description="substrate potential")
    iS = ac.Variable(unit="A", description="substrate current")

    def initial_equations(self):
        return [ac.Eq(self.vcs, self.IC)] if self.UIC else []

    def temperature_laws(self):
        T = self.T_heatPort
        ratio = T / self.Tnom
        if self.useTemperatureDependency:
            laws = [ac.Eq(self.is_t, self.Is * ratio**self.XTI * self.htempexp),
                    ac.Eq(self.br_t, self.Br * ratio**self.XTB),
                    ac.Eq(self.bf_t, self.Bf * ratio**self.XTB),
                    ac.Eq(self.vt_t, self.k / self.q * T)]
        else:
            laws = [ac.Eq(self.is_t, self.Is), ac.Eq(self.br_t, self.Br),
                    ac.Eq(self.bf_t, self.Bf), ac.Eq(self.vt_t, self.Vt)]
        return [ac.Eq(self.hexp, (ratio - 1) * self.EG / self.vt_t),
                # of the temperature alone: its relations may be events
                ac.Eq(self.htempexp, exlin2(self.hexp, self.EMin, self.EMax, events=True)),
                *laws,
                ac.Eq(self.vcs, self.C.v - self.vS),
                ac.Eq(self.iS, -self.Ccs * ac.der(self.vcs)),
                ac.Eq(self.vS, 0)]

    def junction(self, v, N):
        """The junction current is_t (exlin2(v/(N vt_t)) - 1) and its diffusion
        capacitance's factor is_t/(N vt_t) exlin2(v/(N vt_t))."""
        x = v / (N * self.vt_t)
        e = exlin2(x, self.EMin, self.EMax)
        return self.is_t * (e - 1), self.is_t / (N * self.vt_t) * e


class NPN(_BipolarTransistor):
    """Simple NPN bipolar transistor after Ebers-Moll (Modelica.Electrical.Analog.
    Semiconductors.NPN, MSL v4.0.0):

        vbc = B.v - C.v,   vbe = B.v - E.v,   qbk = 1 - vbc Vak
        ibc = is_t (exlin2(vbc/(NR vt_t)) - 1) + vbc Gbc     (ibe likewise with NF, Gbe)
        Capcjc = Cjc powlin(vbc/Phic, Mc),   Capcje = Cje powlin(vbe/Phie, Me)
        cbc = Taur is_t/(NR vt_t) exlin2(vbc/(NR vt_t)) + Capcjc   (cbe with Tauf, NF, Capcje)
        C.i = (ibe - ibc) qbk - ibc/br_t - cbc der(vbc) - iS
        B.i = ibe/bf_t + ibc/br_t + cbc der(vbc) + cbe der(vbe)
        E.i = -B.i - C.i - iS,   iS = -Ccs der(vcs),   vcs = C.v (substrate grounded)

    exlin2 and powlin continue exp and the power law linearly (:mod:`.semiconductors`);
    with ``UIC=True`` the initial vcs is IC.
    LossPower = vbc ibc/br_t + vbe ibe/bf_t + (ibe - ibc) qbk (C.v - E.v).
    """

    vbc = ac.Variable(unit="V", description="base-collector voltage")
    vbe = ac.Variable(unit="V", description="base-emitter voltage")
    ibc = ac.Variable(unit="A", description="base-collector diode current")
    ibe = ac.Variable(unit="A", description="base-emitter diode current")
    cbc = ac.Variable(unit="F", description="total base-collector capacitance")
    cbe = ac.Variable(unit="F", description="total base-emitter capacitance")

    def equations(self):
        ibc, diff_bc = self.junction(self.vbc, self.NR)
        ibe, diff_be = self.junction(self.vbe, self.NF)
        dvbc, dvbe = ac.der(self.vbc), ac.der(self.vbe)
        return [*self.temperature_laws(),
                ac.Eq(self.vbc, self.B.v - self.C.v),
                ac.Eq(self.vbe, self.B.v - self.E.v),
                ac.Eq(self.qbk, 1 - self.vbc * self.Vak),
                ac.Eq(self.ibc, ibc + self.vbc * self.Gbc),
                ac.Eq(self.ibe, ibe + self.vbe * self.Gbe),
                ac.Eq(self.Capcjc, self.Cjc * powlin(self.vbc / self.Phic, self.Mc)),
                ac.Eq(self.Capcje, self.Cje * powlin(self.vbe / self.Phie, self.Me)),
                ac.Eq(self.cbc, self.Taur * diff_bc + self.Capcjc),
                ac.Eq(self.cbe, self.Tauf * diff_be + self.Capcje),
                ac.Eq(self.C.i, (self.ibe - self.ibc) * self.qbk - self.ibc / self.br_t
                      - self.cbc * dvbc - self.iS),
                ac.Eq(self.B.i, self.ibe / self.bf_t + self.ibc / self.br_t
                      + self.cbc * dvbc + self.cbe * dvbe),
                ac.Eq(self.E.i, -self.B.i - self.C.i - self.iS),
                ac.Eq(self.LossPower, self.vbc * self.ibc / self.br_t
                      + self.vbe * self.ibe / self.bf_t
                      + (self.ibe - self.ibc) * self.qbk * (self.C.v - self.E.v))]


class PNP(_BipolarTransistor):
    """Simple PNP bipolar transistor after Ebers-Moll (Modelica.Electrical.Analog.
    Semiconductors.PNP, MSL v4.0.0), the NPN with the junction voltages reversed:

        vcb = C.v - B.v,   veb = E.v - B.v,   qbk = 1 - vcb Vak
        icb = is_t (exlin2(vcb/(NR vt_t)) - 1) + vcb Gbc     (ieb likewise with NF, Gbe)
        ccb = Taur is_t/(NR vt_t) exlin2(vcb/(NR vt_t)) + Capcjc   (ceb with Tauf, NF, Capcje)
        C.i = icb/br_t + ccb der(vcb) + (icb - ieb) qbk - iS
        B.i = -ieb/bf_t - icb/br_t - ceb der(veb) - ccb der(vcb)
        E.i = -B.i - C.i - iS,   iS = -Ccs der(vcs),   vcs = C.v (substrate grounded)

    LossPower = vcb icb/br_t + veb ieb/bf_t + (icb - ieb) qbk (C.v - E.v).
    """

    vcb = ac.Variable(unit="V", description="collector-base voltage")
    veb = ac.Variable(unit="V", description="emitter-base voltage")
    icb = ac.Variable(unit="A", description="collector-base diode current")
    ieb = ac.Variable(unit="A", description="emitter-base diode current")
    ccb = ac.Variable(unit="F", description="total collector-base capacitance")
    ceb = ac.Variable(unit="F", description="total emitter-base capacitance")

    def equations(self):
        icb, diff_cb = self.junction(self.vcb, self.NR)
        ieb, diff_eb = self.junction(self.veb, self.NF)
        dvcb, dveb = ac.der(self.vcb), ac.der(self.veb)
        return [*self.temperature_laws(),
                ac.Eq(self.vcb, self.C.v - self.B.v),
                ac.Eq(self.veb, self.E.v - self.B.v),
                ac.Eq(self.qbk, 1 - self.vcb * self.Vak),
                ac.Eq(self.icb, icb + self.vcb * self.Gbc),
                ac.Eq(self.ieb, ieb + self.veb * self.Gbe),
                ac.Eq(self.Capcjc, self.Cjc * powlin(self.vcb / self.Phic, self.Mc)),
                ac.Eq(self.Capcje, self.Cje * powlin(self.veb / self.Phie, self.Me)),
                ac.Eq(self.ccb, self.Taur * diff_cb + self.Capcjc),
                ac.Eq(self.ceb, self.Tauf * diff_eb + self.Capcje),
                ac.Eq(self.C.i, self.icb / self.br_t + self.ccb * dvcb
                      + (self.icb - self.ieb) * self.qbk - self.iS),
                ac.Eq(self.B.i, -self.ieb / self.bf_t - self.icb / self.br_t
                      - self.ceb * dveb - self.ccb * dvcb),
                ac.Eq(self.E.i, -self.B.i - self.C.i - self.iS),
                ac.Eq(self.LossPower, self.vcb * self.icb / self.br_t
                      + self.veb * self.ieb / self.bf_t
                      + (self.icb - self.ieb) * self.qbk * (self.C.v - self.E.v))]


class _MOS(ConditionalHeatPort):
    """Parameters and temperature laws of the MSL's NMOS and PMOS."""

    W = ac.Parameter(20.0e-6, unit="m", description="width")
    L = ac.Parameter(6.0e-6, unit="m", description="length")
    RDS = ac.Parameter(1e7, unit="Ohm", description="drain-source resistance")
    useTemperatureDependency = ac.Parameter(
        False, structural=True, description="Beta, K2 and Vt depend on temperature")
    Tnom = ac.Parameter(300.15, unit="K", min=0, description="parameter measurement temperature")
    D = Pin()
    G = Pin()
    S = Pin()
    B = Pin()
    v = ac.Variable(unit="A/V2", description="beta_t (W + dW)/(L + dL)")
    uds = ac.Variable(unit="V", description="drain-source voltage, ordered")
    ubs = ac.Variable(unit="V", description="bulk-source voltage, limited")
    ugst = ac.Variable(unit="V", description="effective gate voltage")
    ud = ac.Variable(unit="V", description="the higher (NMOS) potential of drain and source")
    us = ac.Variable(unit="V", description="the lower (NMOS) potential of drain and source")
    id = ac.Variable(unit="A", description="drain current")
    gds = ac.Variable(unit="S", description="drain-source conductance")
    beta_t = ac.Variable(unit="A/V2", description="temperature dependent Beta")
    vt_t = ac.Variable(unit="V", description="temperature dependent Vt")
    k2_t = ac.Variable(description="temperature dependent K2")

    def common(self):
        T = self.T_heatPort
        if self.useTemperatureDependency:
            laws = [ac.Eq(self.beta_t, self.Beta * (T / self.Tnom)**-1.5),
                    ac.Eq(self.vt_t, self.Vt * (1 + (T - self.Tnom) * self.kvt)),
                    ac.Eq(self.k2_t, self.K2 * (1 + (T - self.Tnom) * self.kk2))]
        else:
            laws = [ac.Eq(self.beta_t, self.Beta), ac.Eq(self.vt_t, self.Vt),
                    ac.Eq(self.k2_t, self.K2)]
        # the MSL's gds = 1e20 for RDS = 0 (a structural zero here)
        gds = 1e20 if self.parameter_value("RDS") == 0 else 1 / self.RDS
        return [*laws,
                ac.Eq(self.gds, gds),
                ac.Eq(self.v, self.beta_t * (self.W + self.dW) / (self.L + self.dL)),
                ac.Eq(self.uds, self.ud - self.us),
                ac.Eq(self.ugst, (self.G.v - self.us - self.vt_t + self.k2_t * self.ubs) * self.K5),
                ac.Eq(self.G.i, 0), ac.Eq(self.B.i, 0),
                ac.Eq(self.LossPower, self.D.i * (self.D.v - self.S.v))]


class NMOS(_MOS):
    """Simple NMOS transistor (Modelica.Electrical.Analog.Semiconductors.NMOS, MSL
    v4.0.0), a Shichman-Hodges model with a parallel drain-source resistance:

        ud = max(D.v, S.v),   us = min(D.v, S.v),   uds = ud - us
        ubs = 0 if B.v > us else B.v - us
        ugst = (G.v - us - vt_t + k2_t ubs) K5,   v = beta_t (W + dW)/(L + dL)
        id = uds gds                              (ugst <= 0)
             v uds (ugst - uds/2) + uds gds       (ugst > uds)
             v ugst^2/2 + uds gds                 (otherwise)
        D.i = -id if D.v < S.v else id,   S.i = -D.i,   G.i = B.i = 0

    gds = 1/RDS; with ``useTemperatureDependency=True`` beta_t = Beta (T/Tnom)^-1.5,
    vt_t = Vt (1 + (T - Tnom) kvt), k2_t = K2 (1 + (T - Tnom) kk2).
    LossPower = D.i (D.v - S.v).
    """

    Beta = ac.Parameter(0.041e-3, unit="A/V2", description="transconductance parameter")
    Vt = ac.Parameter(0.8, unit="V", description="zero bias threshold voltage")
    K2 = ac.Parameter(1.144, description="bulk threshold parameter")
    K5 = ac.Parameter(0.7311, description="reduction of pinch-off region")
    dW = ac.Parameter(-2.5e-6, unit="m", description="narrowing of channel")
    dL = ac.Parameter(-1.5e-6, unit="m", description="shortening of channel")
    kvt = ac.Parameter(-6.96e-3, unit="1/K", description="fitting parameter for Vt")
    kk2 = ac.Parameter(6e-4, unit="1/K", description="fitting parameter for K2")

    def equations(self):
        reversed_ = self.D.v < self.S.v
        uds, ugst, gds = self.uds, self.ugst, self.gds
        return [*self.common(),
                ac.Eq(self.ud, ac.if_else(reversed_, self.S.v, self.D.v)),
                ac.Eq(self.us, ac.if_else(reversed_, self.D.v, self.S.v)),
                ac.Eq(self.ubs, ac.if_else(self.B.v > self.us, 0, self.B.v - self.us)),
                ac.Eq(self.id, ac.if_else(ugst <= 0, uds * gds, ac.if_else(
                    ugst > uds, self.v * uds * (ugst - uds / 2) + uds * gds,
                    self.v * ugst * ugst / 2 + uds * gds))),
                ac.Eq(self.D.i, ac.if_else(reversed_, -self.id, self.id)),
                ac.Eq(self.S.i, ac.if_else(reversed_, self.id, -self.id))]


class PMOS(_MOS):
    """Simple PMOS transistor (Modelica.Electrical.Analog.Semiconductors.PMOS, MSL
    v4.0.0), the NMOS with the polarities reversed:

        ud = min(D.v, S.v),   us = max(D.v, S.v),   uds = ud - us
        ubs = 0 if B.v < us else B.v - us
        ugst = (G.v - us - vt_t + k2_t ubs) K5,   v = beta_t (W + dW)/(L + dL)
        id = uds gds                              (ugst >= 0)
             -v uds (ugst - uds/2) + uds gds      (ugst < uds)
             -v ugst^2/2 + uds gds                (otherwise)
        D.i = -id if D.v > S.v else id,   S.i = -D.i,   G.i = B.i = 0

    LossPower = D.i (D.v - S.v).
    """

    Beta = ac.Parameter(0.0105e-3, unit="A/V2", description="transconductance parameter")
    Vt = ac.Parameter(-1.0, unit="V", description="zero bias threshold voltage")
    K2 = ac.Parameter(0.41, description="bulk threshold parameter")
    K5 = ac.Parameter(0.839, description="reduction of pinch-off region")
    dW = ac.Parameter(-2.5e-6, unit="m", description="narrowing of channel")
    dL = ac.Parameter(-2.1e-6, unit="m", description="shortening of channel")
    kvt = ac.Parameter(-2.9e-3, unit="1/K", description="fitting parameter for Vt")
    kk2 = ac.Parameter(6.2e-4, unit="1/K", description="fitting parameter for K2")

    def equations(self):
        reversed_ = self.D.v > self.S.v
        uds, ugst, gds = self.uds, self.ugst, self.gds
        return [*self.common(),
                ac.Eq(self.ud, ac.if_else(reversed_, self.S.v, self.D.v)),
                ac.Eq(self.us, ac.if_else(reversed_, self.D.v, self.S.v)),
                ac.Eq(self.ubs, ac.if_else(self.B.v < self.us, 0, self.B.v - self.us)),
                ac.Eq(self.id, ac.if_else(ugst >= 0, uds * gds, ac.if_else(
                    ugst < uds, -self.v * uds * (ugst - uds / 2) + uds * gds,
                    -self.v * ugst * ugst / 2 + uds * gds))),
                ac.Eq(self.D.i, ac.if_else(reversed_, -self.id, self.id)),
                ac.Eq(self.S.i, ac.if_else(reversed_, self.id, -self.id))]
