"""Modelica.Electrical.Analog.Examples.HeatingRectifier, HeatingMOSInverter,
HeatingNPN_NORGate and HeatingPNP_NORGate (MSL v4.0.0): semiconductors whose
temperature-dependent laws read the temperature of their heat port, through which their
losses heat a thermal network."""
import acausal as ac
from acausal.library.electrical import (NMOS, NPN, PMOS, PNP, Capacitor, Diode, Ground,
                                        RampVoltage, Resistor, SineVoltage, TrapezoidVoltage)
from acausal.library.thermal import FixedTemperature, HeatCapacitor, ThermalConductor

__all__ = ["HeatingRectifier", "HeatingMOSInverter", "HeatingNPN_NORGate",
           "HeatingPNP_NORGate"]


class HeatingRectifier(ac.Component):
    """A temperature-dependent diode charges 1 F (loaded by 1 Ohm) from a 1 V, 1 Hz sine;
    its loss flows through 10 W/K into a heat capacity of 1 J/K, at 20 degC at the
    start."""

    msl_name = "Modelica.Electrical.Analog.Examples.HeatingRectifier"
    stop_time = 5.0
    tolerance = 1e-6

    HeatingDiode1 = Diode(useTemperatureDependency=True, useHeatPort=True)
    G = Ground()
    SineVoltage1 = SineVoltage(V=1.0, f=1.0)
    Capacitor1 = Capacitor(C=1.0, v={"start": 0.0, "fixed": True})
    HeatCapacitor1 = HeatCapacitor(C=1.0)
    ThermalConductor1 = ThermalConductor(G=10.0)
    R = Resistor(R=1.0)

    def initial_equations(self):
        return [ac.Eq(self.HeatCapacitor1.T, 293.15)]

    def equations(self):
        c = ac.connect
        return [c(self.SineVoltage1.p, self.HeatingDiode1.p),
                c(self.SineVoltage1.n, self.G.p), c(self.Capacitor1.n, self.G.p),
                c(self.HeatingDiode1.n, self.Capacitor1.p),
                c(self.HeatingDiode1.heatPort, self.ThermalConductor1.port_a),
                c(self.ThermalConductor1.port_b, self.HeatCapacitor1.port),
                c(self.R.p, self.Capacitor1.p), c(self.R.n, self.Capacitor1.n)]


class HeatingMOSInverter(ac.Component):
    """A CMOS inverter of a temperature-dependent PMOS and NMOS (supplied by a 5 V ramp
    of 10 ms) drives 10 uF from a 5 V, 1 Hz sine; each transistor heats a common heat
    capacity (0.01 J/K, at 20 degC at the start) through 0.01 W/K, which loses its heat
    through 0.01 W/K to 300 K."""

    msl_name = "Modelica.Electrical.Analog.Examples.HeatingMOSInverter"
    stop_time = 5.0
    tolerance = 1e-6

    G = Ground()
    Sin = SineVoltage(V=5.0, f=1.0)
    Capacitor1 = Capacitor(C=0.00001, v={"start": 0.0, "fixed": True})
    HeatCapacitor1 = HeatCapacitor(C=0.01)
    TC1 = ThermalConductor(G=0.01)
    H_PMOS = PMOS(useTemperatureDependency=True)
    H_NMOS = NMOS(useTemperatureDependency=True)
    V = RampVoltage(V=5.0, duration=1e-2)
    TC2 = ThermalConductor(G=0.01)
    FixedTemperature1 = FixedTemperature(T=300.0)
    TC3 = ThermalConductor(G=0.01)

    def initial_equations(self):
        return [ac.Eq(self.HeatCapacitor1.T, 293.15)]

    def equations(self):
        c = ac.connect
        return [c(self.Sin.n, self.G.p), c(self.Capacitor1.n, self.G.p),
                c(self.H_PMOS.S, self.H_NMOS.D), c(self.H_NMOS.D, self.Capacitor1.p),
                c(self.H_NMOS.B, self.H_NMOS.S), c(self.H_NMOS.S, self.G.p),
                c(self.H_PMOS.B, self.H_PMOS.D), c(self.V.p, self.H_PMOS.D),
                c(self.V.n, self.G.p), c(self.TC1.port_b, self.HeatCapacitor1.port),
                c(self.TC2.port_b, self.HeatCapacitor1.port),
                c(self.TC1.port_a, self.H_PMOS.heatPort),
                c(self.TC2.port_a, self.H_NMOS.heatPort),
                c(self.TC3.port_b, self.FixedTemperature1.port),
                c(self.TC3.port_a, self.HeatCapacitor1.port),
                c(self.Sin.p, self.H_NMOS.G), c(self.H_PMOS.G, self.Sin.p)]


CapVal = 0.0          # the examples' value for capacitances (a structural zero)
tauVal = 0.0          # their ideal forward and reverse transit time of semiconductors


def _bipolar(cls, **mods):
    """The NOR gates' transistor data (CapVal, tauVal: the examples' parameters)."""
    return cls(Bf=100.0, Br=1.0, Is=1e-14, Vak=0.0, Tauf=tauVal, Taur=tauVal, Ccs=CapVal,
               Cje=CapVal, Cjc=CapVal, Phie=1.0, Me=0.5, Phic=1.0, Mc=0.5, Gbc=1e-12,
               Gbe=1e-12, EMax=40.0, vt_t={"start": 0.01, "fixed": False},
               useTemperatureDependency=True, **mods)


class _NORGate(ac.Component):
    """The NOR gate of two temperature-dependent bipolar transistors T1, T2 behind
    1800 Ohm base resistors, a 40 Ohm collector resistor RI on a supply ramped over 5 s;
    each transistor heats a heat capacity of 0.1 J/K (20 degC at the start) through
    0.01 W/K.  The capacitances (CapVal = 0) are structural zeros."""

    stop_time = 200.0
    tolerance = 1e-6

    HeatCapacitor1 = HeatCapacitor(C=0.1)
    TC1 = ThermalConductor(G=0.01)
    TC2 = ThermalConductor(G=0.01)
    R1 = Resistor(R=1800.0)
    R2 = Resistor(R=1800.0)
    RI = Resistor(R=40.0)
    Gnd = Ground()
    Gnd2 = Ground()
    Gnd3 = Ground()
    Gnd4 = Ground()
    C1 = Capacitor(C=CapVal)
    C2 = Capacitor(C=CapVal)
    C3 = Capacitor(C=CapVal)
    Gnd5 = Ground()
    Gnd6 = Ground()
    Gnd7 = Ground()
    Gnd1 = Ground()

    def initial_equations(self):
        return [ac.Eq(self.HeatCapacitor1.T, 293.15)]

    def equations(self):
        c = ac.connect
        return [c(self.Gnd7.p, self.C1.n), c(self.C3.p, self.R2.n), c(self.C1.p, self.R1.n),
                c(self.Gnd5.p, self.C3.n), c(self.T1.B, self.R1.n), c(self.T1.E, self.Gnd3.p),
                c(self.RI.p, self.T1.C), c(self.T2.B, self.R2.n), c(self.T2.E, self.Gnd4.p),
                c(self.T2.C, self.RI.p), c(self.TC1.port_b, self.HeatCapacitor1.port),
                c(self.TC2.port_b, self.HeatCapacitor1.port),
                c(self.TC2.port_a, self.T2.heatPort), c(self.TC1.port_a, self.T1.heatPort),
                c(self.V1.p, self.R1.p), c(self.V1.n, self.Gnd1.p), c(self.V2.p, self.R2.p),
                c(self.V2.n, self.Gnd2.p), c(self.C2.p, self.RI.p), c(self.C2.n, self.Gnd6.p)]


class HeatingNPN_NORGate(_NORGate):
    """Heating NPN NOR gate: inputs V1, V2 are 6 V trapezoids (50 s period, from 55 s
    and 65 s), the supply V a 6 V ramp into RI."""

    msl_name = "Modelica.Electrical.Analog.Examples.HeatingNPN_NORGate"

    V = RampVoltage(V=6.0, duration=5.0)
    V1 = TrapezoidVoltage(V=6.0, startTime=55.0, rising=5.0, width=15.0, falling=5.0,
                          period=50.0, nperiod=10)
    V2 = TrapezoidVoltage(V=6.0, startTime=65.0, rising=5.0, width=15.0, falling=5.0,
                          period=50.0, nperiod=10)
    T1 = _bipolar(NPN, ibe={"start": 0.0}, vbc={"start": 0.0})
    T2 = _bipolar(NPN, ibe={"start": 0.0}, vbc={"start": 0.0})

    def equations(self):
        c = ac.connect
        return [c(self.RI.n, self.V.p), c(self.Gnd.p, self.V.n)]


class HeatingPNP_NORGate(_NORGate):
    """Heating PNP NOR gate: the NPN gate with the polarities reversed, inputs -6 V
    trapezoids and the supply's ramp from ground to RI.n reversed."""

    msl_name = "Modelica.Electrical.Analog.Examples.HeatingPNP_NORGate"

    V = RampVoltage(V=6.0, duration=5.0)
    V1 = TrapezoidVoltage(V=-6.0, startTime=55.0, rising=5.0, width=15.0, falling=5.0,
                          period=50.0, nperiod=10)
    V2 = TrapezoidVoltage(V=-6.0, startTime=65.0, rising=5.0, width=15.0, falling=5.0,
                          period=50.0, nperiod=10)
    T1 = _bipolar(PNP)
    T2 = _bipolar(PNP)

    def equations(self):
        c = ac.connect
        return [c(self.V.n, self.RI.n), c(self.Gnd.p, self.V.p)]


if __name__ == "__main__":
    for model in (HeatingRectifier, HeatingMOSInverter, HeatingNPN_NORGate,
                  HeatingPNP_NORGate):
        res = ac.simulate(model(), t_end=model.stop_time, rtol=model.tolerance)
        print(f"{model.__name__}: HeatCapacitor1.T at {res.t[-1]:g} s: "
              f"{res['HeatCapacitor1.T'][-1]:.6g} K")
