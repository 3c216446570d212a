"""Modelica.Electrical.Analog.Examples.CauerLowPassAnalog (MSL v4.0.0): a fifth-order
Cauer low-pass filter of inductors and capacitors between two 1 Ohm terminations, fed
by a 1 V step at t = 1 s."""
import acausal as ac
from acausal.library.electrical import Capacitor, Ground, Inductor, Resistor, StepVoltage

__all__ = ["CauerLowPassAnalog"]

l1, l2 = 1.304, 0.8586                     # filter coefficients (H)
c1, c3, c5 = 1.072, 1.682, 0.7262          # (F)
c2 = 1 / (1.704992**2 * l1)
c4 = 1 / (1.179945**2 * l2)


class CauerLowPassAnalog(ac.Component):
    """l1 = 1.304 H, l2 = 0.8586 H, c1 = 1.072 F, c3 = 1.682 F, c5 = 0.7262 F,
    c2 = 1/(1.704992^2 l1), c4 = 1/(1.179945^2 l2)."""

    msl_name = "Modelica.Electrical.Analog.Examples.CauerLowPassAnalog"
    stop_time = 60.0
    tolerance = 1e-6

    G = Ground()
    C1 = Capacitor(C=c1, v={"start": 0.0, "fixed": True})
    C2 = Capacitor(C=c2)
    C3 = Capacitor(C=c3, v={"start": 0.0, "fixed": True})
    C4 = Capacitor(C=c4)
    C5 = Capacitor(C=c5, v={"start": 0.0, "fixed": True})
    L1 = Inductor(L=l1, i={"start": 0.0, "fixed": True})
    L2 = Inductor(L=l2, i={"start": 0.0, "fixed": True})
    R1 = Resistor(R=1.0)
    R2 = Resistor(R=1.0)
    V = StepVoltage(startTime=1.0, offset=0.0, V=1.0)

    def equations(self):
        return [ac.connect(self.R1.n, self.C1.p),
                ac.connect(self.C1.n, self.G.p),
                ac.connect(self.L1.p, self.C2.p),
                ac.connect(self.L1.p, self.C1.p),
                ac.connect(self.L1.n, self.C2.n),
                ac.connect(self.C2.n, self.C3.p),
                ac.connect(self.C2.n, self.C4.p),
                ac.connect(self.C2.n, self.L2.p),
                ac.connect(self.L2.n, self.C4.n),
                ac.connect(self.C4.n, self.C5.p),
                ac.connect(self.C4.n, self.R2.p),
                ac.connect(self.C1.n, self.C3.n),
                ac.connect(self.C1.n, self.C5.n),
                ac.connect(self.R2.n, self.C1.n),
                ac.connect(self.R1.p, self.V.p),
                ac.connect(self.V.n, self.G.p)]


if __name__ == "__main__":
    res = ac.simulate(CauerLowPassAnalog(), t_end=CauerLowPassAnalog.stop_time,
                      rtol=CauerLowPassAnalog.tolerance)
    print(f"C5.v at {res.t[-1]:g} s: {res['C5.v'][-1]:.6g} V")
