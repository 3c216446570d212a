"""Modelica.Electrical.Analog.Examples.IdealTriacCircuit (MSL v4.0.0): an ideal triac in
series with 20 Ohm on a 5 V, 2 Hz sine, its gate fired by a Boolean pulse (50 % of
0.25 s from 0.1 s)."""
import acausal as ac
from acausal.library.blocks import BooleanPulse
from acausal.library.electrical import Ground, IdealTriac, Resistor, SineVoltage

__all__ = ["IdealTriacCircuit"]


class IdealTriacCircuit(ac.Component):
    """The triac's snubber capacitor starts discharged, both thyristors off."""

    msl_name = "Modelica.Electrical.Analog.Examples.IdealTriacCircuit"
    stop_time = 2.0
    tolerance = 1e-6

    ground = Ground()
    R = Resistor(R=20.0)
    V = SineVoltage(V=5.0, f=2.0)
    booleanPulse = BooleanPulse(width=50.0, period=0.25, startTime=0.1)
    idealTriac = IdealTriac(capacitor={"v": {"start": 0.0, "fixed": True}},
                            idealThyristor={"off": {"start": True, "fixed": True}},
                            idealThyristor1={"off": {"start": True, "fixed": True}})

    def equations(self):
        c = ac.connect
        return [c(self.V.n, self.ground.p), c(self.R.p, self.V.p),
                c(self.R.n, self.idealTriac.n), c(self.idealTriac.p, self.ground.p),
                c(self.idealTriac.fire1, self.booleanPulse.y)]


if __name__ == "__main__":
    res = ac.simulate(IdealTriacCircuit(), t_end=2.0, rtol=1e-6)
    print(f"idealTriac.capacitor.v at {res.t[-1]:g} s: "
          f"{res['idealTriac.capacitor.v'][-1]:.6g} V")
