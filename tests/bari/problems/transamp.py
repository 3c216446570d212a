"""TRANSAMP: the transistor amplifier, an index-1 DAE of dimension 8.

Test Set for IVP Solvers (Mazzia & Magherini, Bari, release 2.4), problem "transamp"
(``Ex_transistor.f``; Rentrop, Roche & Steinebach 1989): eight node voltages U1..U8,
five capacitors between nodes and two transistors,

    M U' = f(t, U),   M the capacitance matrix (rank 5),

    f1 = (U1 - Ue(t))/R0,                     Ue(t) = 0.1 sin(200 pi t)
    f2 = U2/R1 + (U2 - Ub)/R2 + (1 - alpha) g(U2 - U3)
    f3 = U3/R3 - g(U2 - U3)
    f4 = (U4 - Ub)/R4 + alpha g(U2 - U3)
    f5 = U5/R5 + (U5 - Ub)/R6 + (1 - alpha) g(U5 - U6)
    f6 = U6/R7 - g(U5 - U6)
    f7 = (U7 - Ub)/R8 + alpha g(U5 - U6)
    f8 = U8/R9,                               g(U) = beta (exp(U/Uf) - 1),

the residual rows as ``Ex_transistor.f`` writes them (-C1 U1' + C1 U2' - f1, ...), on
[0, 0.2].  The test set gives consistent values for all eight voltages; written with
``fixed=True`` on each, three are redundant (8 conditions, 5 states).  The reference
(PSIDE at 1e-14) carries 16 digits.
"""
import numpy as np

import acausal as ac

from ..testset import BariProblem

__all__ = ["Transamp", "PROBLEM"]

UB, R1, R2, R5, R6 = 6.0, 9000.0, 9000.0, 9000.0, 9000.0
U0 = [0.0, UB / (R2 / R1 + 1), UB / (R2 / R1 + 1), UB, UB / (R6 / R5 + 1),
      UB / (R6 / R5 + 1), UB, 0.0]


class Transamp(ac.Component):
    """The transistor amplifier (module docstring)."""

    ub = ac.Parameter(UB, description="operating voltage Ub")
    uf = ac.Parameter(0.026)
    alpha = ac.Parameter(0.99)
    beta = ac.Parameter(1e-6)
    r0 = ac.Parameter(1000.0)
    r1 = ac.Parameter(R1)
    r2 = ac.Parameter(R2)
    r3 = ac.Parameter(9000.0)
    r4 = ac.Parameter(9000.0)
    r5 = ac.Parameter(R5)
    r6 = ac.Parameter(R6)
    r7 = ac.Parameter(9000.0)
    r8 = ac.Parameter(9000.0)
    r9 = ac.Parameter(9000.0)
    c1 = ac.Parameter(1e-6)
    c2 = ac.Parameter(2e-6)
    c3 = ac.Parameter(3e-6)
    c4 = ac.Parameter(4e-6)
    c5 = ac.Parameter(5e-6)
    U = ac.Variable(shape=8, start=U0, fixed=True)

    def equations(self):
        U, d = self.U, [ac.der(u) for u in self.U]
        ue = 0.1 * ac.sin(200 * np.pi * ac.time)
        g1 = self.beta * (ac.exp((U[1] - U[2]) / self.uf) - 1)
        g2 = self.beta * (ac.exp((U[4] - U[5]) / self.uf) - 1)
        c1, c2, c3, c4, c5 = self.c1, self.c2, self.c3, self.c4, self.c5
        return [
            ac.Eq(-c1 * d[0] + c1 * d[1], (U[0] - ue) / self.r0),
            ac.Eq(c1 * d[0] - c1 * d[1],
                  U[1] / self.r1 + (U[1] - self.ub) / self.r2 + (1 - self.alpha) * g1),
            ac.Eq(-c2 * d[2], U[2] / self.r3 - g1),
            ac.Eq(-c3 * d[3] + c3 * d[4], (U[3] - self.ub) / self.r4 + self.alpha * g1),
            ac.Eq(c3 * d[3] - c3 * d[4],
                  U[4] / self.r5 + (U[4] - self.ub) / self.r6 + (1 - self.alpha) * g2),
            ac.Eq(-c4 * d[5], U[5] / self.r7 - g2),
            ac.Eq(-c5 * d[6] + c5 * d[7], (U[6] - self.ub) / self.r8 + self.alpha * g2),
            ac.Eq(c5 * d[6] - c5 * d[7], U[7] / self.r9)]


_REF = [-0.5562145012262709e-2, 0.3006522471903042e+1, 0.2849958788608128e+1,
        0.2926422536206241e+1, 0.2704617865010554e+1, 0.2761837778393145e+1,
        0.4770927631616772e+1, 0.1236995868091548e+1]

PROBLEM = BariProblem(
    "TRANSAMP", "Transistor amplifier", Transamp, 0.2,
    {f"U[{i}]": v for i, v in enumerate(_REF)}, index=1,
    rtol=1e-10, min_scd=5.0)
