"""CHEMAKZO: the chemical Akzo Nobel problem, an index-1 DAE of dimension 6.

Test Set for IVP Solvers (Mazzia & Magherini, Bari, release 2.4), problem "chemakzo"
(``chemakzoi.f`` of the MEBDFI drivers): the reaction of two species in a reactor with
carbon dioxide fed in continuously,

    y1' = -2 r1 + r2 - r3 - r4
    y2' = -r1/2 - r4 - r5/2 + F_in
    y3' = r1 - r2 + r3
    y4' = -r2 + r3 - 2 r4
    y5' = r2 - r3 + r5
    0   = Ks y1 y4 - y6

with r1 = k1 y1^4 sqrt(y2), r2 = k2 y3 y4, r3 = k2/K y1 y5, r4 = k3 y1 y4^2,
r5 = k4 y6^2 sqrt(y2), F_in = klA (p(CO2)/H - y2), on [0, 180].  The reference
(16 digits) is the test set's.
"""
import acausal as ac

from ..testset import BariProblem

__all__ = ["Chemakzo", "PROBLEM"]


class Chemakzo(ac.Component):
    """The Akzo Nobel reaction (module docstring)."""

    k1 = ac.Parameter(18.7)
    k2 = ac.Parameter(0.58)
    k3 = ac.Parameter(0.09)
    k4 = ac.Parameter(0.42)
    kbig = ac.Parameter(34.4, description="equilibrium constant K")
    kla = ac.Parameter(3.3, description="mass transfer coefficient klA")
    ks = ac.Parameter(115.83, description="equilibrium constant Ks")
    po2 = ac.Parameter(0.9, description="partial pressure of CO2, p(CO2)")
    hen = ac.Parameter(737.0, description="Henry constant H")
    y1 = ac.Variable(start=0.444, fixed=True)
    y2 = ac.Variable(start=0.00123, fixed=True)
    y3 = ac.Variable(start=0.0, fixed=True)
    y4 = ac.Variable(start=0.007, fixed=True)
    y5 = ac.Variable(start=0.0, fixed=True)
    y6 = ac.Variable(start=115.83 * 0.444 * 0.007)

    def equations(self):
        r1 = self.k1 * self.y1**4 * ac.sqrt(self.y2)
        r2 = self.k2 * self.y3 * self.y4
        r3 = self.k2 / self.kbig * self.y1 * self.y5
        r4 = self.k3 * self.y1 * self.y4**2
        r5 = self.k4 * self.y6**2 * ac.sqrt(self.y2)
        fin = self.kla * (self.po2 / self.hen - self.y2)
        return [ac.Eq(ac.der(self.y1), -2 * r1 + r2 - r3 - r4),
                ac.Eq(ac.der(self.y2), -0.5 * r1 - r4 - 0.5 * r5 + fin),
                ac.Eq(ac.der(self.y3), r1 - r2 + r3),
                ac.Eq(ac.der(self.y4), -r2 + r3 - 2 * r4),
                ac.Eq(ac.der(self.y5), r2 - r3 + r5),
                ac.Eq(0, self.ks * self.y1 * self.y4 - self.y6)]


PROBLEM = BariProblem(
    "CHEMAKZO", "Chemical Akzo Nobel", Chemakzo, 180.0,
    {"y1": 0.1150794920661702, "y2": 0.1203831471567715e-2, "y3": 0.1611562887407974,
     "y4": 0.3656156421249283e-3, "y5": 0.1708010885264404e-1,
     "y6": 0.4873531310307455e-2},
    index=1,
    rtol=1e-8, min_scd=5.0)
