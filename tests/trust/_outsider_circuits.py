"""Circuits and DAE test problems written from their published descriptions, as a user
new to acausal writes them (library components where they exist, small components where
they do not).  References are in ``test_outsider_models.py``.

* ``Chua``: Modelica.Electrical.Analog.Examples.ChuaCircuit (L = 18 H, Ro = 12.5 mOhm,
  G = 0.565 S, C1 = 10 F, C2 = 100 F, the piecewise-linear Nr with Ga, Gb, Ve).
* ``CauerLowPass``: Modelica.Electrical.Analog.Examples.CauerLowPassAnalog (a 1 V step at
  1 s into a fifth-order elliptic ladder; C1, C2, C3 close a capacitor loop through
  ground).
* ``HalfWaveRectifier``: a sine source, a source resistance, the exponential ``Diode`` and
  a smoothing capacitor with its load (after Modelica's Rectifier examples).
* ``IdealDiodes``: Modelica.Electrical.Analog.Examples.CharacteristicIdealDiodes (three
  ideal diodes with different Ron, Goff, Vknee, each on a small resistor).
* ``HeatedResistor``: a temperature-dependent ``HeatingResistor`` on a sine source,
  heating a thermal capacitance that loses heat to the ambient.
* ``BridgeRectifier``: Modelica.Electrical.Analog.Examples.Rectifier's six-pulse bridge
  (400 V, 50 Hz, line inductance 60 uH, ideal diodes Ron = Goff = 1e-3, Vknee = 2 V,
  two 15 mF DC capacitors with a grounded midpoint), on a 1 Ohm load.
* ``OpAmpIntegrator``: an inverting integrator on an ideal op amp.
* ``TransistorAmplifier``: the two-stage transistor amplifier of Hairer & Wanner (and of
  the Test Set for IVP Solvers, Mazzia & Magherini, problem "transamp").
"""
import numpy as np

import acausal as ac
from acausal.library import electrical as el
from acausal.library import thermal as th
from acausal.library.electrical.interfaces import OnePort
from acausal.ports import Pin


class NonlinearResistor(OnePort):
    """Chua's diode (MSL ChuaCircuit's NonlinearResistor), piecewise linear:

        i = Gb (v + Ve) - Ga Ve    for v < -Ve
        i = Ga v                   for |v| <= Ve
        i = Gb (v - Ve) + Ga Ve    for v > Ve
    """

    Ga = ac.Parameter(-0.757576, unit="S", description="inner slope")
    Gb = ac.Parameter(-0.409091, unit="S", description="outer slope")
    Ve = ac.Parameter(1.0, unit="V", min=0, description="breakpoint voltage")

    def equations(self):
        outer_low = self.Gb * (self.v + self.Ve) - self.Ga * self.Ve
        outer_high = self.Gb * (self.v - self.Ve) + self.Ga * self.Ve
        return [ac.Eq(self.i, ac.if_else(self.v < -self.Ve, outer_low,
                                         ac.if_else(self.v > self.Ve, outer_high,
                                                    self.Ga * self.v)))]


class Chua(ac.Component):
    L = el.Inductor(L=18.0, i={"start": 0.0, "fixed": True})
    Ro = el.Resistor(R=12.5e-3)
    G = el.Resistor(R=1 / 0.565)
    C1 = el.Capacitor(C=10.0, v={"start": 4.0, "fixed": True})
    C2 = el.Capacitor(C=100.0, v={"start": 0.0, "fixed": True})
    Nr = NonlinearResistor()
    gnd = el.Ground()

    def equations(self):
        return [ac.connect(self.L.p, self.G.p, self.C2.p),
                ac.connect(self.L.n, self.Ro.p),
                ac.connect(self.G.n, self.Nr.p, self.C1.p),
                ac.connect(self.Ro.n, self.Nr.n, self.C1.n, self.C2.n, self.gnd.p)]


CAUER_L = (1.304, 0.8586)
CAUER_C = (1.072, 1 / (1.704992 ** 2 * 1.304), 1.682, 1 / (1.179945 ** 2 * 0.8586), 0.7262)


class CauerLowPass(ac.Component):
    V = el.StepVoltage(V=1.0, startTime=1.0)
    R1 = el.Resistor(R=1.0)
    R2 = el.Resistor(R=1.0)
    C1 = el.Capacitor(C=CAUER_C[0])
    C2 = el.Capacitor(C=CAUER_C[1])
    C3 = el.Capacitor(C=CAUER_C[2])
    C4 = el.Capacitor(C=CAUER_C[3])
    C5 = el.Capacitor(C=CAUER_C[4])
    L1 = el.Inductor(L=CAUER_L[0])
    L2 = el.Inductor(L=CAUER_L[1])
    G = el.Ground()

    def equations(self):
        return [ac.connect(self.V.p, self.R1.p),
                ac.connect(self.R1.n, self.C1.p, self.C2.p, self.L1.p),
                ac.connect(self.C2.n, self.L1.n, self.C3.p, self.C4.p, self.L2.p),
                ac.connect(self.C4.n, self.L2.n, self.C5.p, self.R2.p),
                ac.connect(self.V.n, self.C1.n, self.C3.n, self.C5.n, self.R2.n, self.G.p)]


class HalfWaveRectifier(ac.Component):
    src = el.SineVoltage(V=10.0, f=50.0)
    Ri = el.Resistor(R=10.0)
    D = el.Diode(Ids=1e-6, Vt=0.04, Maxexp=15.0, R=1e8)
    C = el.Capacitor(C=1e-4, v={"start": 0.0, "fixed": True})
    RL = el.Resistor(R=1000.0)
    gnd = el.Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.Ri.p), ac.connect(self.Ri.n, self.D.p),
                ac.connect(self.D.n, self.C.p, self.RL.p),
                ac.connect(self.src.n, self.C.n, self.RL.n, self.gnd.p)]


IDEAL_DIODES = ((1e-5, 1e-5, 0.0), (0.1, 0.1, 0.0), (0.2, 0.2, 5.0))   # Ron, Goff, Vknee


class IdealDiodes(ac.Component):
    src = el.SineVoltage(V=10.0, f=1.0, phase=0.3)
    D1 = el.IdealDiode(Ron=IDEAL_DIODES[0][0], Goff=IDEAL_DIODES[0][1], Vknee=IDEAL_DIODES[0][2])
    D2 = el.IdealDiode(Ron=IDEAL_DIODES[1][0], Goff=IDEAL_DIODES[1][1], Vknee=IDEAL_DIODES[1][2])
    D3 = el.IdealDiode(Ron=IDEAL_DIODES[2][0], Goff=IDEAL_DIODES[2][1], Vknee=IDEAL_DIODES[2][2])
    R1 = el.Resistor(R=1e-3)
    R2 = el.Resistor(R=1e-3)
    R3 = el.Resistor(R=1e-3)
    gnd = el.Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.D1.p, self.D2.p, self.D3.p),
                ac.connect(self.D1.n, self.R1.p), ac.connect(self.D2.n, self.R2.p),
                ac.connect(self.D3.n, self.R3.p),
                ac.connect(self.src.n, self.R1.n, self.R2.n, self.R3.n, self.gnd.p)]


class HeatedResistor(ac.Component):
    src = el.SineVoltage(V=10.0, f=5.0)
    R = el.HeatingResistor(R_ref=10.0, T_ref=300.0, alpha=4e-3)
    gnd = el.Ground()
    Cth = th.HeatCapacitor(C=2.0, T={"start": 300.0, "fixed": True})
    loss = th.ThermalConductor(G=0.5)
    amb = th.FixedTemperature(T=300.0)

    def equations(self):
        return [ac.connect(self.src.p, self.R.p), ac.connect(self.src.n, self.R.n, self.gnd.p),
                ac.connect(self.R.heatPort, self.Cth.port, self.loss.port_a),
                ac.connect(self.loss.port_b, self.amb.port)]


BRIDGE = dict(VAC=400.0, f=50.0, LAC=60e-6, Ron=1e-3, Goff=1e-3, Vknee=2.0, CDC=15e-3, RL=1.0)


def _bridge_diode():
    return el.IdealDiode(Ron=BRIDGE["Ron"], Goff=BRIDGE["Goff"], Vknee=BRIDGE["Vknee"])


def _line():
    return el.Inductor(L=BRIDGE["LAC"], i={"start": 0.0, "fixed": True})


class BridgeRectifier(ac.Component):
    """Phase voltages of amplitude VAC sqrt(2/3), star point and DC midpoint grounded."""

    sa = el.SineVoltage(V=BRIDGE["VAC"] * np.sqrt(2 / 3), f=BRIDGE["f"], phase=0.0)
    sb = el.SineVoltage(V=BRIDGE["VAC"] * np.sqrt(2 / 3), f=BRIDGE["f"], phase=-2 * np.pi / 3)
    sc = el.SineVoltage(V=BRIDGE["VAC"] * np.sqrt(2 / 3), f=BRIDGE["f"], phase=2 * np.pi / 3)
    La, Lb, Lc = _line(), _line(), _line()
    Dap, Dbp, Dcp = _bridge_diode(), _bridge_diode(), _bridge_diode()
    Dna, Dnb, Dnc = _bridge_diode(), _bridge_diode(), _bridge_diode()
    C1 = el.Capacitor(C=BRIDGE["CDC"], v={"start": 0.0, "fixed": True})
    C2 = el.Capacitor(C=BRIDGE["CDC"], v={"start": 0.0, "fixed": True})
    load = el.Resistor(R=BRIDGE["RL"])
    gnd = el.Ground()

    def equations(self):
        return [ac.connect(self.sa.n, self.sb.n, self.sc.n, self.C1.n, self.C2.p, self.gnd.p),
                ac.connect(self.sa.p, self.La.p), ac.connect(self.sb.p, self.Lb.p),
                ac.connect(self.sc.p, self.Lc.p),
                ac.connect(self.La.n, self.Dap.p, self.Dna.n),
                ac.connect(self.Lb.n, self.Dbp.p, self.Dnb.n),
                ac.connect(self.Lc.n, self.Dcp.p, self.Dnc.n),
                ac.connect(self.Dap.n, self.Dbp.n, self.Dcp.n, self.C1.p, self.load.p),
                ac.connect(self.Dna.p, self.Dnb.p, self.Dnc.p, self.C2.n, self.load.n)]


class OpAmpIntegrator(ac.Component):
    src = el.SineVoltage(V=1.0, f=10.0)
    R = el.Resistor(R=1e3)
    C = el.Capacitor(C=1e-5, v={"start": 0.0, "fixed": True})
    op = el.IdealOpAmp3Pin()
    gnd = el.Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.R.p), ac.connect(self.R.n, self.op.in_n, self.C.p),
                ac.connect(self.C.n, self.op.out),
                ac.connect(self.op.in_p, self.src.n, self.gnd.p)]


class NPN(ac.Component):
    """Hairer & Wanner's transistor model (transistor amplifier problem):

        I_E = beta (exp((v_b - v_e)/U_F) - 1),   I_B = (1 - alpha) I_E,   I_C = alpha I_E

    (currents into the base and the collector, I_E out of the emitter)."""

    b = Pin()
    c = Pin()
    e = Pin()
    alpha = ac.Parameter(0.99, min=0, max=1, description="common-base current gain")
    beta = ac.Parameter(1e-6, unit="A", min=0, description="saturation current")
    UF = ac.Parameter(0.026, unit="V", min=0, description="thermal voltage")

    def equations(self):
        g = self.beta * (ac.exp((self.b.v - self.e.v) / self.UF) - 1)
        return [ac.Eq(self.b.i, (1 - self.alpha) * g), ac.Eq(self.c.i, self.alpha * g),
                ac.Eq(self.e.i, -g)]


def _r9k():
    return el.Resistor(R=9000.0)


class TransistorAmplifier(ac.Component):
    """Nodes 1..8 of the test set; Ub = 6 V, Ue = 0.1 sin(200 pi t), R0 = 1 kOhm, R1..R9 =
    9 kOhm, C_k = k uF; the consistent start y2 = y3 = y5 = y6 = 3 V, y4 = y7 = 6 V."""

    Ue = el.SineVoltage(V=0.1, f=100.0)
    Ub = el.ConstantVoltage(V=6.0)
    R0 = el.Resistor(R=1000.0)
    R1, R2, R3, R4, R5, R6, R7, R8, R9 = (_r9k() for _ in range(9))
    C1 = el.Capacitor(C=1e-6, v={"start": -3.0, "fixed": True})
    C2 = el.Capacitor(C=2e-6, v={"start": 3.0, "fixed": True})
    C3 = el.Capacitor(C=3e-6, v={"start": 3.0, "fixed": True})
    C4 = el.Capacitor(C=4e-6, v={"start": 3.0, "fixed": True})
    C5 = el.Capacitor(C=5e-6, v={"start": 6.0, "fixed": True})
    T1 = NPN()
    T2 = NPN()
    gnd = el.Ground()

    def equations(self):
        return [ac.connect(self.gnd.p, self.Ue.n, self.Ub.n, self.R1.n, self.R3.n, self.C2.n,
                           self.R5.n, self.R7.n, self.C4.n, self.R9.n),
                ac.connect(self.Ue.p, self.R0.p),
                ac.connect(self.R0.n, self.C1.p),
                ac.connect(self.C1.n, self.R1.p, self.R2.n, self.T1.b),
                ac.connect(self.T1.e, self.R3.p, self.C2.p),
                ac.connect(self.T1.c, self.R4.n, self.C3.p),
                ac.connect(self.C3.n, self.R5.p, self.R6.n, self.T2.b),
                ac.connect(self.T2.e, self.R7.p, self.C4.p),
                ac.connect(self.T2.c, self.R8.n, self.C5.p),
                ac.connect(self.C5.n, self.R9.p),
                ac.connect(self.Ub.p, self.R2.p, self.R4.p, self.R6.p, self.R8.p)]
