"""Modelica.Electrical.Analog.Examples.ShowVariableResistor (MSL v4.0.0): two paths of
three resistors in parallel on a 1 V, 1 Hz sine source, the middle one of the lower path
a VariableResistor driven by a ramp from 2 to 7 Ohm."""
import acausal as ac
from acausal.library.blocks import Ramp
from acausal.library.electrical import Ground, Resistor, SineVoltage, VariableResistor

__all__ = ["ShowVariableResistor"]


class ShowVariableResistor(ac.Component):
    """R1 ... R5 = 1 Ohm; the ramp rises by 5 from 2 over 2 s."""

    msl_name = "Modelica.Electrical.Analog.Examples.ShowVariableResistor"
    stop_time = 1.0
    tolerance = 1e-6

    VariableResistor = VariableResistor()
    Ground1 = Ground()
    Ground2 = Ground()
    R1 = Resistor(R=1.0)
    R2 = Resistor(R=1.0)
    R3 = Resistor(R=1.0)
    R4 = Resistor(R=1.0)
    R5 = Resistor(R=1.0)
    SineVoltage1 = SineVoltage(V=1.0, f=1.0)
    Ramp1 = Ramp(height=5.0, offset=2.0, duration=2.0)

    def equations(self):
        c = ac.connect
        return [c(self.R1.n, self.R2.p), c(self.R2.n, self.R3.p),
                c(self.R4.n, self.VariableResistor.p), c(self.VariableResistor.n, self.R5.p),
                c(self.R3.n, self.Ground2.p), c(self.Ground2.p, self.R5.n),
                c(self.SineVoltage1.p, self.Ground1.p), c(self.SineVoltage1.n, self.R1.p),
                c(self.SineVoltage1.n, self.R4.p), c(self.Ramp1.y, self.VariableResistor.R)]


if __name__ == "__main__":
    res = ac.simulate(ShowVariableResistor(), t_end=1.0, rtol=1e-6)
    print(f"VariableResistor.i at {res.t[-1]:g} s: {res['VariableResistor.i'][-1]:.6g} A")
