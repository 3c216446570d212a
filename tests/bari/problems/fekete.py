"""FEKETE: the Fekete points on the sphere, a stabilized index-2 DAE of dimension 160.

Test Set for IVP Solvers (Mazzia & Magherini, Bari, release 2.4), problem "fekete"
(``Ex_fekete.f``): 20 particles p_i on the unit sphere repel each other and come to
rest at an elliptic Fekete configuration; with velocities q_i, multipliers lam_i
(constraint force) and mu_i (the stabilizing multiplier of Gear, Gupta & Leimkuhler),
alpha = 1/2,

    p_i' = q_i + 2 mu_i p_i
    q_i' = -alpha q_i + 2 lam_i p_i + sum_{j != i} (p_i - p_j) / |p_i - p_j|^2
    0 = |p_i|^2 - 1
    0 = 2 p_i . q_i

on [0, 1000].  The initial positions lie on four circles of latitude as ``fekinit``
places them, the particles at rest, mu = 0 and lam as ``fekinit`` computes it; the
positions and velocities are fixed as given (forty conditions are redundant with the
constraints).  The test set's scd uses the 60 position coordinates; its reference
(RADAU5 at 1e-12) is the rest configuration, to about 12 digits.
"""
import numpy as np

import acausal as ac

from ..testset import BariProblem

__all__ = ["Fekete", "PROBLEM"]

NART = 20
ALPHA = 0.5


def initial_positions() -> np.ndarray:
    """``fekinit``'s positions: 3, 7, 6 and 4 particles on four circles of latitude."""
    rings = [(range(0, 3), 3, np.pi / 13, 3 * np.pi / 8),
             (range(3, 10), 7, np.pi / 29, np.pi / 8),
             (range(10, 16), 6, np.pi / 7, -2 * np.pi / 15),
             (range(16, 20), 4, np.pi / 17, -3 * np.pi / 10)]
    p = np.zeros((NART, 3))
    for idx, count, shift, beta in rings:
        for k, i in enumerate(idx):
            # fekinit's alpha = 2 pi m / count + shift, m counted from 1 on the first
            # three circles and from 0 on the last (i-17 for i = 17..20)
            m = k + 1 if count != 4 else k
            a = 2 * np.pi * m / count + shift
            p[i] = (np.cos(a) * np.cos(beta), np.sin(a) * np.cos(beta), np.sin(beta))
    return p


def initial_lambda(p: np.ndarray) -> np.ndarray:
    """``fekinit``'s lam: with q = 0 and mu = 0, lam_i = -p_i . f_i / 2, f_i the
    repulsion on particle i."""
    f = np.zeros_like(p)
    for i in range(NART):
        for j in range(NART):
            if i != j:
                d = p[i] - p[j]
                f[i] += d / d.dot(d)
    return -0.5 * np.einsum("ij,ij->i", p, f)


P0 = initial_positions()
LAM0 = initial_lambda(P0)


class Fekete(ac.Component):
    """The Fekete problem (module docstring)."""

    alpha = ac.Parameter(ALPHA)
    p = ac.Variable(shape=(NART, 3), start=P0, fixed=True)
    q = ac.Variable(shape=(NART, 3), start=0.0, fixed=True)
    lam = ac.Variable(shape=NART, start=LAM0)
    mu = ac.Variable(shape=NART, start=0.0)

    def equations(self):
        p, q, lam, mu = self.p, self.q, self.lam, self.mu
        eqs = []
        for i in range(NART):
            for k in range(3):
                force = 0
                for j in range(NART):
                    if j != i:
                        rn = sum((p[i, m] - p[j, m])**2 for m in range(3))
                        force = force + (p[i, k] - p[j, k]) / rn
                eqs.append(ac.Eq(ac.der(p[i, k]), q[i, k] + 2 * mu[i] * p[i, k]))
                eqs.append(ac.Eq(ac.der(q[i, k]),
                                 -self.alpha * q[i, k] + 2 * lam[i] * p[i, k] + force))
        for i in range(NART):
            eqs.append(ac.Eq(0, -1 + sum(p[i, k]**2 for k in range(3))))
            eqs.append(ac.Eq(0, sum(2 * p[i, k] * q[i, k] for k in range(3))))
        return eqs


_POSITIONS = [
    (-0.4070263380333202, 0.3463758772791802, 0.8451942450030429),
    (0.0775293475252155, -0.2628662719972299, 0.9617122871829146),
    (0.7100577833343567, 0.121294805558612, 0.6936177005172217),
    (0.2348267744557627, 0.7449277976923311, 0.6244509285956391),
    (-0.4341114738782885, 0.8785430442262876, 0.199272044423766),
    (-0.9515059600312596, 0.2203508762787005, 0.2146669498274008),
    (-0.6385191643609878, -0.4310833259390688, 0.6375425027722121),
    (-0.1464175087914336, -0.9380871635228862, 0.313933729874469),
    (0.5666974065069942, -0.6739221885076542, 0.4740073135462156),
    (0.9843259538440293, -0.1696995357819996, -0.0480050429060909),
    (0.1464175087914331, 0.9380871635228875, -0.3139337298744656),
    (-0.7092757549979014, 0.5264062637139616, -0.4688542938854929),
    (-0.8665731819284478, -0.4813878059756024, -0.1315929352982178),
    (-0.2347897778700538, -0.859434040801313, -0.4541441287957579),
    (0.5530976940074118, -0.7674370265615124, -0.3242273140037833),
    (0.7711050969896927, 0.6357041816577034, 0.03573685519777001),
    (0.7103951209379591, 0.2403570431280519, -0.6614886725910596),
    (-0.0303820873873566, 0.4501923293640461, -0.8924145871442046),
    (-0.5772996158107093, -0.1766763414971813, -0.7971892020969544),
    (0.2414481766969039, -0.3416456818373135, -0.908284650344625),]
_REF = {f"p[{i},{k}]": _POSITIONS[i][k] for i in range(NART) for k in range(3)}
_REF.update({f"lam[{i}]": -4.75 for i in range(NART)})

PROBLEM = BariProblem(
    "FEKETE", "Fekete points", Fekete, 1000.0, _REF, index=2,
    scd_names=[f"p[{i},{k}]" for i in range(NART) for k in range(3)],
    rtol=1e-8, min_scd=5.0)
