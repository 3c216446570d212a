"""Modelica.Electrical.Analog.Examples.InvertingAmp (MSL v4.0.0): an inverting amplifier
of gain 2 around the ideal op-amp with output limits (+-15 V supply), driven by a
+-5 V, 10 Hz trapezoid."""
import acausal as ac
from acausal.library.electrical import (ConstantVoltage, Ground, IdealOpAmpLimited,
                                        Resistor, TrapezoidVoltage, VoltageSensor)

__all__ = ["InvertingAmp"]

Vps, Vns = 15.0, -15.0       # supply (V)
Vin = 5.0                    # amplitude of the input voltage (V)
f = 10.0                     # frequency of the input voltage (Hz)
k = 2.0                      # desired amplification
R1 = 1000.0                  # arbitrary resistance (Ohm)
R2 = k * R1                  # resistance for the amplification k


class InvertingAmp(ac.Component):
    """The input's trapezoid starts half-way along its top (startTime = -(rising +
    width/2)); the MSL's vIn.signalSource.y is the source's voltage vIn.v."""

    msl_name = "Modelica.Electrical.Analog.Examples.InvertingAmp"
    stop_time = 1.0
    tolerance = 1e-07
    msl_signals = {"vIn.signalSource.y": "vIn.v"}

    opAmp = IdealOpAmpLimited(out={"i": {"start": 0.0, "fixed": False}})
    ground = Ground()
    vIn = TrapezoidVoltage(V=2 * Vin, rising=0.2 / f, width=0.3 / f, falling=0.2 / f,
                           period=1 / f, nperiod=-1, offset=-Vin,
                           startTime=-(0.2 / f + 0.3 / f / 2))
    vOut = VoltageSensor()
    r1 = Resistor(R=R1)
    r2 = Resistor(R=R2)
    ground1 = Ground()
    vSourcePos = ConstantVoltage(V=Vps)
    vSourceNeg = ConstantVoltage(V=Vns)

    def equations(self):
        c = ac.connect
        return [c(self.r1.n, self.r2.n), c(self.r2.n, self.opAmp.in_n),
                c(self.r2.p, self.opAmp.out), c(self.ground.p, self.opAmp.in_p),
                c(self.vIn.p, self.r1.p), c(self.ground.p, self.vIn.n),
                c(self.ground.p, self.vOut.n), c(self.opAmp.out, self.vOut.p),
                c(self.ground1.p, self.vSourcePos.n), c(self.vSourcePos.p, self.opAmp.VMax),
                c(self.vSourcePos.n, self.vSourceNeg.n), c(self.vSourceNeg.p, self.opAmp.VMin)]


if __name__ == "__main__":
    res = ac.simulate(InvertingAmp(), t_end=1.0, rtol=1e-7)
    print(f"vOut at {res.t[-1]:g} s: {res['vOut.v'][-1]:.6g} V")
