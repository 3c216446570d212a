"""Modelica.Electrical.Analog.Examples.Utilities (MSL v4.0.0): the sub-circuits the
examples are built of."""
import acausal as ac
from acausal.library.electrical import (NMOS, NPN, PMOS, Capacitor,
                                        Conductor as BasicConductor, GeneralCurrentToVoltageAdaptor,
                                        GeneralVoltageToCurrentAdaptor, Ground, Inductor,
                                        OnePort, Resistor as BasicResistor, SignalCurrent,
                                        SignalVoltage)
from acausal.ports import Pin, RealInput, RealOutput

__all__ = ["NonlinearResistor", "Transistor", "Nand", "DirectCapacitor",
           "InverseCapacitor", "DirectInductor", "InverseInductor", "Resistor",
           "Conductor"]


class NonlinearResistor(OnePort):
    """Chua's resistor (Modelica.Electrical.Analog.Examples.Utilities.NonlinearResistor),
    piecewise linear:

        i = Gb (v + Ve) - Ga Ve   (v < -Ve),   Gb (v - Ve) + Ga Ve   (v > Ve),   Ga v
    """

    Ga = ac.Parameter(-0.757576, unit="S", description="conductance in inner voltage range")
    Gb = ac.Parameter(-0.409091, unit="S", description="conductance in outer voltage range")
    Ve = ac.Parameter(1.0, unit="V", description="inner voltage range limit")

    def equations(self):
        v, Ga, Gb, Ve = self.v, self.Ga, self.Gb, self.Ve
        return [ac.Eq(self.i, ac.if_else(v < -Ve, Gb * (v + Ve) - Ga * Ve,
                                         ac.if_else(v > Ve, Gb * (v - Ve) + Ga * Ve, Ga * v)))]


class Transistor(ac.Component):
    """NPN transistor with base and collector resistances and a base capacitance to
    ground (Modelica.Electrical.Analog.Examples.Utilities.Transistor)."""

    rtb = BasicResistor(R=0.05)
    rtc = BasicResistor(R=0.1)
    ct = Capacitor(C=1e-10)
    Tr = NPN(Bf=50.0, Br=0.1, Is=1e-16, Vak=0.02, Tauf=0.12e-9, Taur=5e-9, Ccs=1e-12,
             Cje=0.4e-12, Cjc=0.5e-12, Phie=0.8, Me=0.4, Phic=0.8, Mc=0.333, Gbc=1e-15,
             Gbe=1e-15, Vt=0.02585, UIC=True)
    Ground1 = Ground()
    c = Pin()
    b = Pin()
    e = Pin()

    def equations(self):
        c = ac.connect
        return [c(self.rtb.n, self.Tr.B), c(self.rtb.n, self.ct.p),
                c(self.ct.n, self.Ground1.p), c(self.Tr.C, self.rtc.p),
                c(self.rtc.n, self.c), c(self.b, self.rtb.p), c(self.Tr.E, self.e)]


def _pmos():
    return PMOS(W=6.5e-6, L=3.1e-6, Beta=1.05e-5, Vt=-1.0, K2=0.41, K5=0.8385, dW=-2.5e-6,
                dL=-2.1e-6)


def _nmos():
    return NMOS(W=6.5e-6, L=3.1e-6, Beta=4.1e-5, Vt=0.8, K2=1.144, K5=0.7311, dW=-2.5e-6,
                dL=-1.5e-6)


class Nand(ac.Component):
    """CMOS NAND gate (Modelica.Electrical.Analog.Examples.Utilities.Nand, after
    Tietze/Schenk, page 157): two PMOS in parallel from Vdd, two NMOS in series to
    ground, the output y loaded by C4, the node between the NMOS by C7."""

    TP1 = _pmos()
    TP2 = _pmos()
    TN1 = _nmos()
    TN2 = _nmos()
    C4 = Capacitor(C=0.4e-13)
    C7 = Capacitor(C=0.4e-13)
    Gnd = Ground()
    Gnd2 = Ground()
    Gnd3 = Ground()
    Gnd6 = Ground()
    Gnd7 = Ground()
    Gnd8 = Ground()
    x1 = Pin()
    x2 = Pin()
    Vdd = Pin()
    y = Pin()

    def equations(self):
        c = ac.connect
        return [c(self.TN1.S, self.TN2.D), c(self.TN2.B, self.Gnd.p), c(self.TN2.D, self.C7.p),
                c(self.TN2.S, self.Gnd.p), c(self.TP1.S, self.TN1.D), c(self.TP1.G, self.TN1.G),
                c(self.C4.n, self.Gnd2.p), c(self.C7.n, self.Gnd3.p), c(self.TP2.B, self.Gnd6.p),
                c(self.TN1.B, self.Gnd7.p), c(self.TP1.B, self.Gnd8.p), c(self.TP2.G, self.x1),
                c(self.TP2.G, self.TN2.G), c(self.TN1.G, self.x2), c(self.TP2.S, self.TN1.D),
                c(self.TN1.D, self.C4.p), c(self.Vdd, self.TP1.D), c(self.TP2.D, self.Vdd),
                c(self.C4.p, self.y)]


class DirectCapacitor(ac.Component):
    """Input/output block of a direct capacitor model (Modelica.Electrical.Analog.
    Examples.Utilities.DirectCapacitor): the current iDrive charges the capacitor, the
    current i (from outside) leaves it; the outputs are its voltage v and dv = der(v)."""

    C = ac.Parameter(1.0, unit="F", min=0, description="capacitance")
    capacitor = Capacitor(C=ac.ref("C"), v={"fixed": True, "start": 0.0})
    currentSource = SignalCurrent()
    iDrive = RealInput()
    currentToVoltage = GeneralCurrentToVoltageAdaptor(use_pder=True, use_fder=False)
    v = RealOutput()
    dv = RealOutput()
    i = RealInput()
    ground = Ground()

    def equations(self):
        c = ac.connect
        return [c(self.currentToVoltage.f, self.i), c(self.currentToVoltage.p, self.v),
                c(self.currentToVoltage.pder, self.dv), c(self.iDrive, self.currentSource.i),
                c(self.capacitor.p, self.currentToVoltage.pin_p),
                c(self.capacitor.n, self.currentToVoltage.pin_n),
                c(self.currentSource.p, self.ground.p), c(self.ground.p, self.capacitor.n),
                c(self.currentSource.n, self.capacitor.p)]


class InverseCapacitor(ac.Component):
    """Input/output block of an inverse capacitor model (Modelica.Electrical.Analog.
    Examples.Utilities.InverseCapacitor): the voltage v (and its derivative dv) is
    imposed on the capacitor, whose current is the output i."""

    C = ac.Parameter(1.0, unit="F", min=0, description="capacitance")
    capacitor = Capacitor(C=ac.ref("C"), v={"fixed": True, "start": 0.0})
    voltageToCurrent = GeneralVoltageToCurrentAdaptor(use_fder=False)
    v = RealInput()
    dv = RealInput()
    i = RealOutput()
    ground = Ground()

    def equations(self):
        c = ac.connect
        return [c(self.voltageToCurrent.f, self.i), c(self.voltageToCurrent.p, self.v),
                c(self.voltageToCurrent.pder, self.dv),
                c(self.voltageToCurrent.pin_p, self.capacitor.p),
                c(self.ground.p, self.capacitor.n),
                c(self.voltageToCurrent.pin_n, self.ground.p)]


class DirectInductor(ac.Component):
    """Input/output block of a direct inductor model (Modelica.Electrical.Analog.
    Examples.Utilities.DirectInductor): the voltage vDrive drives the inductor, the
    voltage v (from outside) is across the adaptor after it; the outputs are its current
    i and di = der(i)."""

    L = ac.Parameter(1.0, unit="H", description="inductance")
    inductor = Inductor(i={"fixed": True, "start": 0.0}, L=ac.ref("L"))
    voltageSource = SignalVoltage()
    vDrive = RealInput()
    currentToVoltage = GeneralVoltageToCurrentAdaptor(use_pder=False, use_fder=True)
    i = RealOutput()
    di = RealOutput()
    v = RealInput()
    ground = Ground()

    def equations(self):
        c = ac.connect
        return [c(self.vDrive, self.voltageSource.v), c(self.voltageSource.n, self.ground.p),
                c(self.voltageSource.p, self.inductor.p),
                c(self.inductor.n, self.currentToVoltage.pin_p),
                c(self.ground.p, self.currentToVoltage.pin_n),
                c(self.currentToVoltage.p, self.v), c(self.currentToVoltage.f, self.i),
                c(self.currentToVoltage.fder, self.di)]


class InverseInductor(ac.Component):
    """Input/output block of an inverse inductor model (Modelica.Electrical.Analog.
    Examples.Utilities.InverseInductor): the current i (and its derivative di) is
    imposed on the inductor, whose voltage is the output v."""

    L = ac.Parameter(1.0, unit="H", description="inductance")
    inductor = Inductor(i={"fixed": True, "start": 0.0}, L=ac.ref("L"))
    currentToVoltage = GeneralCurrentToVoltageAdaptor(use_pder=False, use_fder=True)
    i = RealInput()
    di = RealInput()
    v = RealOutput()
    ground = Ground()

    def equations(self):
        c = ac.connect
        return [c(self.currentToVoltage.pin_p, self.inductor.p),
                c(self.ground.p, self.inductor.n),
                c(self.currentToVoltage.pin_n, self.ground.p),
                c(self.i, self.currentToVoltage.f), c(self.di, self.currentToVoltage.fder),
                c(self.currentToVoltage.p, self.v)]


class Resistor(ac.Component):
    """Input/output block of a resistance model (Modelica.Electrical.Analog.Examples.
    Utilities.Resistor): the voltages v1, v2 on the two ends give the currents i1, i2
    out of them."""

    R = ac.Parameter(1.0, unit="Ohm", description="resistance")
    voltageToCurrent1 = GeneralVoltageToCurrentAdaptor(use_pder=False, use_fder=False)
    v1 = RealInput()
    i1 = RealOutput()
    resistor = BasicResistor(R=ac.ref("R"))
    v2 = RealInput()
    i2 = RealOutput()
    voltageToCurrent2 = GeneralVoltageToCurrentAdaptor(use_fder=False, use_pder=False)
    ground = Ground()

    def equations(self):
        c = ac.connect
        return [c(self.i1, self.voltageToCurrent1.f), c(self.voltageToCurrent2.f, self.i2),
                c(self.voltageToCurrent1.p, self.v1), c(self.voltageToCurrent2.p, self.v2),
                c(self.voltageToCurrent1.pin_p, self.resistor.p),
                c(self.resistor.n, self.voltageToCurrent2.pin_p),
                c(self.voltageToCurrent1.pin_n, self.ground.p),
                c(self.ground.p, self.voltageToCurrent2.pin_n)]


class Conductor(ac.Component):
    """Input/output block of a conductance model (Modelica.Electrical.Analog.Examples.
    Utilities.Conductor): the currents i1, i2 into the two ends give the voltages v1,
    v2."""

    G = ac.Parameter(1.0, unit="S", description="conductance")
    currentToVoltage1 = GeneralCurrentToVoltageAdaptor(use_pder=False, use_fder=False)
    i1 = RealInput()
    v1 = RealOutput()
    conductor = BasicConductor(G=ac.ref("G"))
    i2 = RealInput()
    v2 = RealOutput()
    currentToVoltage2 = GeneralCurrentToVoltageAdaptor(use_fder=False, use_pder=False)
    ground = Ground()

    def equations(self):
        c = ac.connect
        return [c(self.currentToVoltage1.p, self.v1), c(self.currentToVoltage1.f, self.i1),
                c(self.currentToVoltage2.f, self.i2), c(self.v2, self.currentToVoltage2.p),
                c(self.currentToVoltage1.pin_p, self.conductor.p),
                c(self.conductor.p, self.currentToVoltage2.pin_p),
                c(self.currentToVoltage1.pin_n, self.conductor.n),
                c(self.conductor.n, self.currentToVoltage2.pin_n),
                c(self.conductor.n, self.ground.p)]
