"""CRANK: the slider crank with an elastic connecting rod, an index-2 DAE of dimension 24.

Test Set for IVP Solvers (Mazzia & Magherini, Bari, release 2.4), problem "crank"
(``Ex_crank.f``; Simeon, "Modelling a flexible slider crank mechanism by a mixed system
of DAEs and PDEs", Math. Modelling of Systems 2 (1996)): the crank angle phi1, the rod
angle phi2 and the slider position x3 (the rigid motion), the rod's elastic coordinates
q1..q4 (two lateral modes, two longitudinal nodes), their velocities and accelerations
and three multipliers, in the index-2 formulation with the constraints on the velocity
level:

    p' = v,   v' = a,
    0 = A(p) a - f(p, v) + G(p)^T lam,
    0 = G(p) v - (0, 0, omega)^T,

A the mass matrix and f the forces of rigid and elastic motion with all coupling
terms, G the constraint Jacobian of the crank, rod and slider loop (its third row
drives the crank at omega = 150 rad/s), entries as ``RESMBS`` assembles them (linear
stiffness, no damping: the test set's default).  On [0, 0.1].  The test set's initial
values are consistent to their nine digits; the seven positions and seven velocities
are fixed as given (three velocities are redundant with the constraints).  The
reference is MEBDFI's at 1e-14; the test set's R driver measures the seven positions.
"""
import numpy as np

import acausal as ac

from ..testset import BariProblem

__all__ = ["Crank", "PROBLEM"]

# the test set's consistent initial values (its default, ``ini = 1``)
Y0 = [0.0, 0.0, 0.450016933, 0.0, 0.0, 0.103339863e-4, 0.169327969e-4,
      0.150000000e3, -.749957670e2, -.268938672e-5, 0.444896105, 0.463434311e-2,
      -.178591076e-5, -.268938672e-5,
      0.0, -1.344541576008661e-3, -5.062194923138079e3, -6.833142732779555e-5,
      1.449382650173157e-8, -4.268463211410861, 2.098334687947376e-1,
      -6.397251492537153e-08, 3.824589508329281e2, -4.376060460948886e-09]
PI = 3.1415927     # as RESMBS has it


class Crank(ac.Component):
    """The flexible slider crank, index-2 form (module docstring)."""

    M1 = ac.Parameter(0.36)
    M2 = ac.Parameter(0.151104)
    M3 = ac.Parameter(0.075552)
    L1 = ac.Parameter(0.15)
    L2 = ac.Parameter(0.30)
    J1 = ac.Parameter(0.002727)
    J2 = ac.Parameter(0.0045339259)
    EE = ac.Parameter(0.20e12)
    NUE = ac.Parameter(0.30)
    BB = ac.Parameter(0.0080)
    HH = ac.Parameter(0.0080)
    RHO = ac.Parameter(7870.0)
    GRAV = ac.Parameter(0.0)
    OMEGA = ac.Parameter(150.0)
    p = ac.Variable(shape=3, start=Y0[0:3], fixed=True, description="phi1, phi2, x3")
    q = ac.Variable(shape=4, start=Y0[3:7], fixed=True, description="elastic coordinates")
    pd = ac.Variable(shape=3, start=Y0[7:10], fixed=True)
    qd = ac.Variable(shape=4, start=Y0[10:14], fixed=True)
    a = ac.Variable(shape=7, start=Y0[14:21], description="accelerations of p and q")
    la = ac.Variable(shape=3, start=Y0[21:24], description="multipliers")

    def _fe_matrices(self):
        """The finite-element matrices of the rod (RESMBS's first call)."""
        facm = self.RHO * self.BB * self.HH * self.L2
        fack = self.EE * self.BB * self.HH / self.L2
        facb = self.BB * self.HH * self.L2
        hl2 = (self.HH / self.L2)**2
        MQ = [[0] * 4 for _ in range(4)]
        KQ = [[0] * 4 for _ in range(4)]
        BQ = [[0] * 4 for _ in range(4)]
        MQ[0][0] = facm * .5
        MQ[1][1] = facm * .5
        MQ[2][2] = facm * 8
        MQ[2][3] = MQ[3][2] = facm * 1
        MQ[3][3] = facm * 2
        KQ[0][0] = fack * PI**4 / 24 * hl2
        KQ[1][1] = fack * PI**4 * 2 / 3 * hl2
        KQ[2][2] = fack * 16 / 3
        KQ[2][3] = KQ[3][2] = -fack * 8 / 3
        KQ[3][3] = fack * 7 / 3
        BQ[0][2] = -facb * 16 / PI**3
        BQ[0][3] = facb * (8 / PI**3 - 1 / PI)
        BQ[1][3] = facb * 0.5 / PI
        BQ[2][0] = facb * 16 / PI**3
        BQ[3][0] = -facb * (8 / PI**3 - 1 / PI)
        BQ[3][1] = -facb * 0.5 / PI
        c1 = [0, 0, facb * 2 / 3, facb / 6]
        c2 = [facb * 2 / PI, 0, 0, 0]
        c12 = [0, 0, self.L2 * facb / 3, self.L2 * facb / 6]
        c21 = [self.L2 * facb / PI, -self.L2 * facb * 0.5 / PI, 0, 0]
        return MQ, KQ, BQ, c1, c2, c12, c21

    def equations(self):
        MQ, KQ, BQ, c1, c2, c12, c21 = self._fe_matrices()
        M1, M2, M3, L1, L2, J1, J2 = (self.M1, self.M2, self.M3, self.L1, self.L2,
                                      self.J1, self.J2)
        RHO, GRAV = self.RHO, self.GRAV
        p, q, pd, qd, w, la = self.p, self.q, self.pd, self.qd, self.a, self.la
        x = list(p) + list(q)
        xd = list(pd) + list(qd)
        cosp1, cosp2 = ac.cos(p[0]), ac.cos(p[1])
        sinp1, sinp2 = ac.sin(p[0]), ac.sin(p[1])
        cosp12, sinp12 = ac.cos(p[0] - p[1]), ac.sin(p[0] - p[1])
        v1, v2 = pd[0], pd[1]

        def dot(a, b):
            return sum(ai * bi for ai, bi in zip(a, b))

        c1TQ, c1TQD = dot(c1, q), dot(c1, qd)
        c2TQ, c2TQD = dot(c2, q), dot(c2, qd)
        c12TQ, c12TQD = dot(c12, q), dot(c12, qd)
        MQQ = [dot([MQ[j][i] for j in range(4)], q) for i in range(4)]
        KQQ = [dot([KQ[j][i] for j in range(4)], q) for i in range(4)]
        QTBQ = [dot(q, [BQ[j][i] for j in range(4)]) for i in range(4)]
        BQQD = [dot(BQ[i], qd) for i in range(4)]
        QTMQQ, QDTMQQ, QDTBQQD = dot(q, MQQ), dot(qd, MQQ), dot(qd, BQQD)
        # mass matrix
        AM = [[0] * 7 for _ in range(7)]
        AM[0][0] = J1 + M2 * L1 * L1
        AM[0][1] = .5 * L1 * L2 * M2 * cosp12 + RHO * L1 * (sinp12 * c2TQ + cosp12 * c1TQ)
        AM[1][1] = J2 + QTMQQ + 2 * RHO * c12TQ
        AM[2][2] = M3
        for i in range(4):
            AM[0][3 + i] = RHO * L1 * (-sinp12 * c1[i] + cosp12 * c2[i])
            AM[1][3 + i] = RHO * c21[i] + RHO * QTBQ[i]
            for j in range(i + 1):
                AM[3 + j][3 + i] = MQ[j][i]
        for i in range(7):
            for j in range(i + 1, 7):
                AM[j][i] = AM[i][j]
        # constraint matrix (KU = 4: the longitudinal node q4; KV = 0)
        qku = q[3]
        GP = [[0] * 7 for _ in range(3)]
        GP[0][0] = L1 * cosp1
        GP[0][1] = L2 * cosp2 + qku * cosp2
        GP[1][0] = L1 * sinp1
        GP[1][1] = L2 * sinp2 + qku * sinp2
        GP[1][2] = 1
        GP[2][0] = 1
        GP[0][6] = sinp2
        GP[1][6] = -cosp2
        # forces: rigid motion, superposed flexible motion, Coriolis, gravity, stiffness
        F = [0] * 7
        F[0] = (-.5 * L1 * GRAV * (M1 + 2 * M2) * cosp1 - .5 * L1 * L2 * M2 * v2 * v2 * sinp12
                + RHO * L1 * v2 * v2 * (-sinp12 * c1TQ + cosp12 * c2TQ)
                - 2 * RHO * L1 * v2 * (cosp12 * c1TQD + sinp12 * c2TQD))
        F[1] = (-.5 * L2 * GRAV * M2 * cosp2 + .5 * L1 * L2 * M2 * v1 * v1 * sinp12
                + RHO * L1 * v1 * v1 * (sinp12 * c1TQ - cosp12 * c2TQ)
                - 2 * RHO * v2 * c12TQD - 2 * v2 * QDTMQQ
                - RHO * QDTBQQD - RHO * GRAV * (cosp2 * c1TQ - sinp2 * c2TQ))
        F[2] = 0
        for i in range(4):
            F[3 + i] = (v2 * v2 * MQQ[i]
                        + RHO * (v2 * v2 * c12[i]
                                 + L1 * v1 * v1 * (cosp12 * c1[i] + sinp12 * c2[i])
                                 + 2 * v2 * BQQD[i])
                        - RHO * GRAV * (sinp2 * c1[i] + cosp2 * c2[i])
                        - KQQ[i])
        eqs = [ac.Eq(ac.der(x[i]), xd[i]) for i in range(7)]
        eqs += [ac.Eq(ac.der(xd[i]), w[i]) for i in range(7)]
        eqs += [ac.Eq(0, dot(AM[i], w) - F[i] + sum(GP[j][i] * la[j] for j in range(3)))
                for i in range(7)]
        # velocity-level constraints (the index-2 system)
        vlc = [dot(GP[0], xd), dot(GP[1], xd), dot(GP[2], xd) - self.OMEGA]
        eqs += [ac.Eq(0, c) for c in vlc]
        return eqs


_REF = [0.1500000000000104e+2, -0.3311734988256260e+0, 0.1697373328427860e+0,
        0.1893192899613509e-3, 0.2375751249879174e-4, -0.5323896770569702e-5,
        -0.8363313279112129e-5, 0.1500000000000000e+3, 0.6025346755138369e+2,
        -0.8753116326670527e+1, -0.3005541400289738e-1, -0.5500431812571696e-2,
        0.4974111734266989e-3, 0.1105560003626645e-2, 0.0, 0.6488737541276957e+4,
        0.2167938629509884e+4, 0.3391137060286523e+2, 0.1715134772216488e+0,
        -0.1422449408912512e+1, 0.1003946428124810e+1, -0.6232935833287916e+2,
        -0.1637920993367306e+3, 0.2529857947066878e+2]
_NAMES = ([f"p[{i}]" for i in range(3)] + [f"q[{i}]" for i in range(4)]
          + [f"pd[{i}]" for i in range(3)] + [f"qd[{i}]" for i in range(4)]
          + [f"a[{i}]" for i in range(7)] + [f"la[{i}]" for i in range(3)])

PROBLEM = BariProblem(
    "CRANK", "Slider crank (flexible rod)", Crank, 0.1,
    dict(zip(_NAMES, _REF)), index=2, scd_names=_NAMES[:7],
    rtol=1e-8, min_scd=5.0)
