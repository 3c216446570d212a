"""Modelica.Electrical.Analog.Examples.NandGate (MSL v4.0.0): a CMOS NAND gate
(Utilities.Nand, after Tietze/Schenk) supplied by a 5 V ramp, its inputs two 3.5 V
trapezoid pulse trains of a 40 ns period shifted by 10 ns."""
import acausal as ac
from acausal.library.electrical import Ground, RampVoltage, TrapezoidVoltage

from .utilities import Nand

__all__ = ["NandGate"]


class NandGate(ac.Component):
    """VIN1 from 20 ns, VIN2 from 10 ns: 1 ns edges, 19 ns high; VDD: 5 V over 1 ns."""

    msl_name = "Modelica.Electrical.Analog.Examples.NandGate"
    stop_time = 1e-07
    tolerance = 1e-06

    VIN1 = TrapezoidVoltage(V=3.5, startTime=20e-9, rising=1e-9, width=19e-9, falling=1e-9,
                            period=40e-9, nperiod=-1)
    VIN2 = TrapezoidVoltage(V=3.5, startTime=10e-9, rising=1e-9, width=19e-9, falling=1e-9,
                            period=40e-9, nperiod=-1)
    VDD = RampVoltage(V=5.0, duration=1e-9)
    Gnd1 = Ground()
    Gnd4 = Ground()
    Gnd5 = Ground()
    Nand = Nand(C4={"v": {"start": 0.0, "fixed": True}}, C7={"v": {"start": 0.0, "fixed": True}})

    def equations(self):
        c = ac.connect
        return [c(self.VDD.n, self.Gnd1.p), c(self.VIN1.n, self.Gnd4.p),
                c(self.VIN2.n, self.Gnd5.p), c(self.Nand.Vdd, self.VDD.p),
                c(self.VIN1.p, self.Nand.x1), c(self.VIN2.p, self.Nand.x2)]


if __name__ == "__main__":
    res = ac.simulate(NandGate(), t_end=1e-7, rtol=1e-6)
    print(f"Nand.C4.v at {res.t[-1]:g} s: {res['Nand.C4.v'][-1]:.6g} V")
