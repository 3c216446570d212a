"""ANDREWS: Andrews' squeezing mechanism, an index-3 DAE of dimension 27.

Test Set for IVP Solvers (Mazzia & Magherini, Bari, release 2.4), problem "andrews"
(``Ex_andrews.f``; Hairer & Wanner II, section VII.7): seven rigid bodies joined by
revolute joints, driven by a torque on body 1 against a spring, in the index-3
formulation with the accelerations w as unknowns,

    q' = v,   v' = w,   0 = M(q) w - f(q, v) + G(q)^T lam,   0 = g(q),

q the seven angles (beta, Theta, gamma, Phi, delta, Omega, epsilon), lam the six
multipliers, M, f, g and G = dg/dq written entry by entry as ``Ex_andrews.f`` assembles
them.  On [0, 0.03].  The test set's initial values are consistent; the fourteen
angles and rates are fixed as given (twelve are redundant with the constraints and
their derivatives).  The test set's scd uses the seven angles.
"""
import numpy as np

import acausal as ac

from ..testset import BariProblem

__all__ = ["Andrews", "PROBLEM"]

Q0 = [-0.0617138900142764496358948458001, 0.0, 0.455279819163070380255912382449,
      0.222668390165885884674473185609, 0.487364979543842550225598953530,
      -0.222668390165885884674473185609, 1.23054744454982119249735015568]
W0 = [14222.4439199541138705911625887, -10666.8329399655854029433719415,
      0.0, 0.0, 0.0, 0.0, 0.0]
LAM0 = [98.5668703962410896057654982170, -6.12268834425566265503114393122,
        0.0, 0.0, 0.0, 0.0]

_PARAMETERS = dict(
    m1=.04325, m2=.00365, m3=.02373, m4=.00706, m5=.07050, m6=.00706, m7=.05498,
    xa=-.06934, ya=-.00227, xb=-0.03635, yb=.03273, xc=.014, yc=.072, c0=4530.0,
    i1=2.194e-6, i2=4.410e-7, i3=5.255e-6, i4=5.667e-7, i5=1.169e-5, i6=5.667e-7,
    i7=1.912e-5, d=28e-3, da=115e-4, e=2e-2, ea=1421e-5, rr=7e-3, ra=92e-5,
    l0=7785e-5, ss=35e-3, sa=1874e-5, sb=1043e-5, sc=18e-3, sd=2e-2, ta=2308e-5,
    tb=916e-5, u=4e-2, ua=1228e-5, ub=449e-5, zf=2e-2, zt=4e-2, fa=1421e-5, mom=33e-3)


class Andrews(ac.Component):
    """Andrews' squeezing mechanism, index-3 form (module docstring)."""

    locals().update({k: ac.Parameter(v) for k, v in _PARAMETERS.items()})
    q = ac.Variable(shape=7, start=Q0, fixed=True)
    v = ac.Variable(shape=7, start=0.0, fixed=True)
    w = ac.Variable(shape=7, start=W0)
    lam = ac.Variable(shape=6, start=LAM0)

    def _matrices(self):
        """M(q), f(q, v), G(q) and g(q) as ``andfunc`` builds them."""
        P, q, v = self, self.q, self.v
        sibe, sith, siga, siph, side, siom, siep = (ac.sin(x) for x in q)
        cobe, coth, coga, coph, code, coom, coep = (ac.cos(x) for x in q)
        sibeth, siphde, siomep = ac.sin(q[0] + q[1]), ac.sin(q[3] + q[4]), ac.sin(q[5] + q[6])
        cobeth, cophde, coomep = ac.cos(q[0] + q[1]), ac.cos(q[3] + q[4]), ac.cos(q[5] + q[6])
        bep, thp, php, dep, omp, epp = v[0], v[1], v[3], v[4], v[5], v[6]
        M = [[0] * 7 for _ in range(7)]
        M[0][0] = P.m1 * P.ra**2 + P.m2 * (P.rr**2 - 2 * P.da * P.rr * coth + P.da**2) \
            + P.i1 + P.i2
        M[1][0] = P.m2 * (P.da**2 - P.da * P.rr * coth) + P.i2
        M[1][1] = P.m2 * P.da**2 + P.i2
        M[2][2] = P.m3 * (P.sa**2 + P.sb**2) + P.i3
        M[3][3] = P.m4 * (P.e - P.ea)**2 + P.i4
        M[4][3] = P.m4 * ((P.e - P.ea)**2 + P.zt * (P.e - P.ea) * siph) + P.i4
        M[4][4] = P.m4 * (P.zt**2 + 2 * P.zt * (P.e - P.ea) * siph + (P.e - P.ea)**2) \
            + P.m5 * (P.ta**2 + P.tb**2) + P.i4 + P.i5
        M[5][5] = P.m6 * (P.zf - P.fa)**2 + P.i6
        M[6][5] = P.m6 * ((P.zf - P.fa)**2 - P.u * (P.zf - P.fa) * siom) + P.i6
        M[6][6] = P.m6 * ((P.zf - P.fa)**2 - 2 * P.u * (P.zf - P.fa) * siom + P.u**2) \
            + P.m7 * (P.ua**2 + P.ub**2) + P.i6 + P.i7
        for j in range(1, 7):
            for i in range(j):
                M[i][j] = M[j][i]
        xd = P.sd * coga + P.sc * siga + P.xb
        yd = P.sd * siga - P.sc * coga + P.yb
        lang = ac.sqrt((xd - P.xc)**2 + (yd - P.yc)**2)
        force = -P.c0 * (lang - P.l0) / lang
        fx, fy = force * (xd - P.xc), force * (yd - P.yc)
        ff = [P.mom - P.m2 * P.da * P.rr * thp * (thp + 2 * bep) * sith,
              P.m2 * P.da * P.rr * bep**2 * sith,
              fx * (P.sc * coga - P.sd * siga) + fy * (P.sd * coga + P.sc * siga),
              P.m4 * P.zt * (P.e - P.ea) * dep**2 * coph,
              -P.m4 * P.zt * (P.e - P.ea) * php * (php + 2 * dep) * coph,
              -P.m6 * P.u * (P.zf - P.fa) * epp**2 * coom,
              P.m6 * P.u * (P.zf - P.fa) * omp * (omp + 2 * epp) * coom]
        gp = [[0] * 7 for _ in range(6)]
        gp[0][0] = -P.rr * sibe + P.d * sibeth
        gp[0][1] = P.d * sibeth
        gp[0][2] = -P.ss * coga
        gp[1][0] = P.rr * cobe - P.d * cobeth
        gp[1][1] = -P.d * cobeth
        gp[1][2] = -P.ss * siga
        gp[2][0] = -P.rr * sibe + P.d * sibeth
        gp[2][1] = P.d * sibeth
        gp[2][3] = -P.e * cophde
        gp[2][4] = -P.e * cophde + P.zt * side
        gp[3][0] = P.rr * cobe - P.d * cobeth
        gp[3][1] = -P.d * cobeth
        gp[3][3] = -P.e * siphde
        gp[3][4] = -P.e * siphde - P.zt * code
        gp[4][0] = -P.rr * sibe + P.d * sibeth
        gp[4][1] = P.d * sibeth
        gp[4][5] = P.zf * siomep
        gp[4][6] = P.zf * siomep - P.u * coep
        gp[5][0] = P.rr * cobe - P.d * cobeth
        gp[5][1] = -P.d * cobeth
        gp[5][5] = -P.zf * coomep
        gp[5][6] = -P.zf * coomep - P.u * siep
        g = [P.rr * cobe - P.d * cobeth - P.ss * siga - P.xb,
             P.rr * sibe - P.d * sibeth + P.ss * coga - P.yb,
             P.rr * cobe - P.d * cobeth - P.e * siphde - P.zt * code - P.xa,
             P.rr * sibe - P.d * sibeth + P.e * cophde - P.zt * side - P.ya,
             P.rr * cobe - P.d * cobeth - P.zf * coomep - P.u * siep - P.xa,
             P.rr * sibe - P.d * sibeth - P.zf * siomep + P.u * coep - P.ya]
        return M, ff, gp, g

    def equations(self):
        M, ff, gp, g = self._matrices()
        q, v, w, lam = self.q, self.v, self.w, self.lam
        eqs = [ac.Eq(ac.der(q[i]), v[i]) for i in range(7)]
        eqs += [ac.Eq(ac.der(v[i]), w[i]) for i in range(7)]
        eqs += [ac.Eq(0, sum(M[i][j] * w[j] for j in range(7)) - ff[i]
                      + sum(gp[j][i] * lam[j] for j in range(6))) for i in range(7)]
        eqs += [ac.Eq(0, gi) for gi in g]
        return eqs


_REF = [0.1581077119629904e+2, -0.1575637105984298e+2, 0.4082224013073101e-1,
        -0.5347301163226948e+0, 0.5244099658805304e+0, 0.5347301163226948e+0,
        0.1048080741042263e+1, 0.1139920302151208e+4, -0.1424379294994111e+4,
        0.1103291221937134e+2, 0.1929337464421385e+2, 0.5735699284790808e+0,
        -0.1929337464421385e+2, 0.3231791658026955e+0, -0.2463176316945196e+5,
        0.5185037701610329e+5, 0.3241025686413781e+6, 0.5667493645176213e+6,
        0.1674362929479361e+5, -0.5667493645176222e+6, 0.9826520791458422e+4,
        0.1991753333731910e+3, -0.2975531228015052e+2, 0.2306654119098399e+2,
        0.3145271365475927e+2, 0.2264249232082739e+2, 0.1161740700019673e+2]
_NAMES = ([f"q[{i}]" for i in range(7)] + [f"v[{i}]" for i in range(7)]
          + [f"w[{i}]" for i in range(7)] + [f"lam[{i}]" for i in range(6)])

PROBLEM = BariProblem(
    "ANDREWS", "Andrews' squeezing mechanism", Andrews, 0.03,
    dict(zip(_NAMES, _REF)), index=3, scd_names=_NAMES[:7],
    rtol=1e-8, min_scd=5.0)
