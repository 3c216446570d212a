"""Modelica.Electrical.Analog.Examples.CharacteristicThyristors (MSL v4.0.0): two ideal
thyristors and two ideal GTO thyristors (Vknee = 1 V), each in series with 1 mOhm on a
10 V, 1 Hz sine; the first pair fired by a Boolean table, the second by a Boolean pulse
(20 % of 1 s from 0.15 s)."""
import acausal as ac
from acausal.library.blocks import BooleanPulse, BooleanTable
from acausal.library.electrical import (Ground, IdealGTOThyristor, IdealThyristor,
                                        Resistor, SineVoltage)

__all__ = ["CharacteristicThyristors"]


class CharacteristicThyristors(ac.Component):
    """A thyristor keeps conducting after its fire signal ends, a GTO thyristor stops."""

    msl_name = "Modelica.Electrical.Analog.Examples.CharacteristicThyristors"
    stop_time = 6.0
    tolerance = 1e-6

    IdealThyristor1 = IdealThyristor(off={"start": True, "fixed": True}, Vknee=1.0)
    SineVoltage1 = SineVoltage(V=10.0, offset=0.0, f=1.0)
    Ground1 = Ground()
    R3 = Resistor(R=1e-3)
    IdealGTOThyristor1 = IdealGTOThyristor(off={"fixed": True, "start": True}, Vknee=1.0)
    R1 = Resistor(R=1e-3)
    booleanStep1 = BooleanTable(table=(1.25, 3.2, 4.2, 4.25, 5.7, 5.72))
    IdealThyristor2 = IdealThyristor(off={"start": True, "fixed": True}, Vknee=1.0)
    R2 = Resistor(R=1e-3)
    IdealGTOThyristor2 = IdealGTOThyristor(off={"fixed": True, "start": True}, Vknee=1.0)
    R4 = Resistor(R=1e-3)
    booleanPulse = BooleanPulse(width=20.0, period=1.0, startTime=0.15)

    def equations(self):
        c = ac.connect
        return [c(self.IdealThyristor1.n, self.R3.p), c(self.Ground1.p, self.SineVoltage1.n),
                c(self.SineVoltage1.p, self.IdealThyristor1.p),
                c(self.IdealGTOThyristor1.n, self.R1.p), c(self.R3.n, self.R1.n),
                c(self.IdealGTOThyristor1.p, self.IdealThyristor1.p),
                c(self.IdealGTOThyristor1.fire, self.IdealThyristor1.fire),
                c(self.IdealThyristor1.fire, self.booleanStep1.y),
                c(self.IdealThyristor2.n, self.R2.p), c(self.IdealGTOThyristor2.n, self.R4.p),
                c(self.R2.n, self.R4.n),
                c(self.IdealGTOThyristor2.p, self.IdealThyristor2.p),
                c(self.IdealGTOThyristor2.fire, self.IdealThyristor2.fire),
                c(self.R4.n, self.Ground1.p), c(self.R2.n, self.R1.n),
                c(self.SineVoltage1.p, self.IdealThyristor2.p),
                c(self.booleanPulse.y, self.IdealThyristor2.fire)]


if __name__ == "__main__":
    res = ac.simulate(CharacteristicThyristors(), t_end=6.0, rtol=1e-6)
    print(f"R3.i at {res.t[-1]:g} s: {res['R3.i'][-1]:.6g} A")
