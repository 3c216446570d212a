"""Modelica.Electrical.Analog.Examples.CharacteristicIdealDiodes (MSL v4.0.0): three
ideal diodes on sine sources, each in series with 1 mOhm: an ideal one (Ron = Goff =
0), one with Ron = Goff = 0.1 and one with Ron = Goff = 0.2 and Vknee = 5 V."""
import acausal as ac
from acausal.library.electrical import Ground, IdealDiode, Resistor, SineVoltage

__all__ = ["CharacteristicIdealDiodes"]


class CharacteristicIdealDiodes(ac.Component):
    """The three characteristics i(v) over a 1 Hz sine of 10 V."""

    msl_name = "Modelica.Electrical.Analog.Examples.CharacteristicIdealDiodes"
    stop_time = 1.0
    tolerance = 1e-6

    Ideal = IdealDiode(Ron=0.0, Goff=0.0, Vknee=0.0)
    With_Ron_Goff = IdealDiode(Ron=0.1, Goff=0.1, Vknee=0.0)
    With_Ron_Goff_Vknee = IdealDiode(Ron=0.2, Goff=0.2, Vknee=5.0)
    SineVoltage1 = SineVoltage(V=10.0, offset=-9.0, f=1.0)
    Ground1 = Ground()
    R1 = Resistor(R=1e-3)
    R2 = Resistor(R=1e-3)
    R3 = Resistor(R=1e-3)
    SineVoltage2 = SineVoltage(V=10.0, offset=0.0, f=1.0)
    SineVoltage3 = SineVoltage(V=10.0, offset=0.0, f=1.0)

    def equations(self):
        c = ac.connect
        return [c(self.Ground1.p, self.SineVoltage1.n), c(self.Ideal.n, self.R1.p),
                c(self.With_Ron_Goff.n, self.R2.p), c(self.With_Ron_Goff_Vknee.n, self.R3.p),
                c(self.R1.n, self.R2.n), c(self.R2.n, self.R3.n), c(self.R3.n, self.Ground1.p),
                c(self.SineVoltage2.p, self.Ideal.p), c(self.SineVoltage2.n, self.Ground1.p),
                c(self.SineVoltage1.p, self.With_Ron_Goff.p),
                c(self.With_Ron_Goff_Vknee.p, self.SineVoltage3.p),
                c(self.SineVoltage3.n, self.Ground1.p)]


if __name__ == "__main__":
    res = ac.simulate(CharacteristicIdealDiodes(), t_end=1.0, rtol=1e-6)
    print(f"With_Ron_Goff.v at {res.t[-1]:g} s: {res['With_Ron_Goff.v'][-1]:.6g} V")
