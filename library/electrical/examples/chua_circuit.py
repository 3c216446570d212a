"""Modelica.Electrical.Analog.Examples.ChuaCircuit (MSL v4.0.0): Chua's circuit, an
inductor and two capacitors with a conductor between them and Chua's piecewise-linear
negative resistor (units ns, V, A as in the MSL: L = 18, C1 = 10, C2 = 100).

MAP-LIB's reference of this example is not available here (its result file is missing
from the archive), and over its 5e4 time units the chaotic orbit of any two solvers
parts; it is checked against an independent solution of its equations over a shorter
run (``tests/library/test_electrical_examples.py``)."""
import acausal as ac
from acausal.library.electrical import Capacitor, Conductor, Ground, Inductor, Resistor

from .msl.utilities import NonlinearResistor

__all__ = ["ChuaCircuit"]


class ChuaCircuit(ac.Component):
    """L = 18, Ro = 12.5e-3, G = 0.565, C1 = 10 (v = 4 at the start), C2 = 100;
    Nr: Ga = -0.757576, Gb = -0.409091, Ve = 1."""

    stop_time = 5e4
    tolerance = 1e-6

    L = Inductor(L=18.0, i={"start": 0.0, "fixed": True})
    Ro = Resistor(R=12.5e-3)
    G = Conductor(G=0.565)
    C1 = Capacitor(C=10.0, v={"start": 4.0, "fixed": True})
    C2 = Capacitor(C=100.0, v={"start": 0.0, "fixed": True})
    Nr = NonlinearResistor(Ga=-0.757576, Gb=-0.409091, Ve=1.0)
    Gnd = Ground()

    def equations(self):
        c = ac.connect
        return [c(self.L.n, self.Ro.p), c(self.C2.p, self.G.p), c(self.L.p, self.G.p),
                c(self.G.n, self.Nr.p), c(self.C1.p, self.G.n), c(self.Ro.n, self.Gnd.p),
                c(self.C2.n, self.Gnd.p), c(self.Gnd.p, self.C1.n), c(self.Gnd.p, self.Nr.n)]


if __name__ == "__main__":
    res = ac.simulate(ChuaCircuit(), t_end=1000.0, rtol=1e-6)
    print(f"C1.v at {res.t[-1]:g}: {res['C1.v'][-1]:.6g} V")
