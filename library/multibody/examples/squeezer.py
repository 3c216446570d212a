"""Andrews' squeezing mechanism: seven rigid bodies on frictionless joints in a plane,
driven by a constant torque and pulled by a spring (Hairer & Wanner, *Solving Ordinary
Differential Equations II*, section VII.7, the system (7.11); problem "andrews" of
the Test Set for IVP Solvers, Bari).

In the book's minimal form, with the seven angles q = (beta, Theta, gamma, Phi, delta,
Omega, epsilon) and six Lagrange multipliers lam of the position constraints g(q) = 0
(the mechanism closed at the fixed point B, and through two branches at A):

    q' = v,   M(q) v' = f(q, v) - G(q)^T lam,   g(q) = 0,   G = dg/dq      (7.11)

20 unknowns (27 in the first-order form of the Test Set, which adds the accelerations)
and 42 parameters, which the arrays of the modelling language write as the book does:
q, v and lam are arrays, the masses, inertias and fixed points are arrays, and M, f, G
and g are built as numpy arrays of expressions.  The constraints are of index 3; the
compiler differentiates them twice.
"""
import numpy as np

import acausal as ac

__all__ = ["AndrewsSqueezer", "Q0"]

# the book's consistent initial angles (beta, Theta, gamma, Phi, delta, Omega, epsilon)
Q0 = (-0.0617138900142764496358948458001, 0.0, 0.455279819163070380255912382449,
      0.222668390165885884674473185609, 0.487364979543842550225598953530,
      -0.222668390165885884674473185609, 1.23054744454982119249735015568)


class AndrewsSqueezer(ac.Component):
    """Seven bodies, two closed loops, a driving torque mom and a spring c0 (HW VII.7)."""

    stop_time = 0.03
    m = ac.Parameter([0.04325, 0.00365, 0.02373, 0.00706, 0.07050, 0.00706, 0.05498],
                     unit="kg", min=0, description="masses of bodies 1..7")
    I = ac.Parameter([2.194e-6, 4.410e-7, 5.255e-6, 5.667e-7, 1.169e-5, 5.667e-7, 1.912e-5],
                     unit="kg.m2", min=0, description="moments of inertia of bodies 1..7")
    A = ac.Parameter([-0.06934, -0.00227], unit="m", description="fixed point A (x, y)")
    B = ac.Parameter([-0.03635, 0.03273], unit="m", description="fixed point B (x, y)")
    C = ac.Parameter([0.014, 0.072], unit="m", description="spring anchor C (x, y)")
    d = ac.Parameter(0.028, unit="m")
    da = ac.Parameter(0.0115, unit="m")
    e = ac.Parameter(0.02, unit="m")
    ea = ac.Parameter(0.01421, unit="m")
    rr = ac.Parameter(0.007, unit="m")
    ra = ac.Parameter(0.00092, unit="m")
    ss = ac.Parameter(0.035, unit="m")
    sa = ac.Parameter(0.01874, unit="m")
    sb = ac.Parameter(0.01043, unit="m")
    sc = ac.Parameter(0.018, unit="m")
    sd = ac.Parameter(0.02, unit="m")
    ta = ac.Parameter(0.02308, unit="m")
    tb = ac.Parameter(0.00916, unit="m")
    u = ac.Parameter(0.04, unit="m")
    ua = ac.Parameter(0.01228, unit="m")
    ub = ac.Parameter(0.00449, unit="m")
    zf = ac.Parameter(0.02, unit="m")
    zt = ac.Parameter(0.04, unit="m")
    fa = ac.Parameter(0.01421, unit="m")
    mom = ac.Parameter(0.033, unit="N.m", description="driving torque on body 1")
    c0 = ac.Parameter(4530.0, unit="N/m", min=0, description="spring constant")
    l0 = ac.Parameter(0.07785, unit="m", min=0, description="unstretched spring length")
    # beta fixed; the constraints determine the other angles (started at the book's values)
    q = ac.Variable(shape=7, start=Q0, fixed=[True] + [False] * 6, unit="rad")
    v = ac.Variable(shape=7, start=0.0, fixed=[True] + [False] * 6, unit="rad/s")
    lam = ac.Variable(shape=6, start=0.0, description="Lagrange multipliers of g(q) = 0")

    def equations(self):
        b, th, ga, ph, de, om, ep = self.q
        bp, thp, gap, php, dep, omp, epp = self.v
        m, i = self.m, self.I
        rr, d, da, ss, e, ea, zt, zf, u, fa = (self.rr, self.d, self.da, self.ss, self.e,
                                               self.ea, self.zt, self.zf, self.u, self.fa)
        cb, sb_, cth, sth = ac.cos(b), ac.sin(b), ac.cos(th), ac.sin(th)
        cbth, sbth = ac.cos(b + th), ac.sin(b + th)
        cphde, sphde = ac.cos(ph + de), ac.sin(ph + de)
        comep, somep = ac.cos(om + ep), ac.sin(om + ep)
        ee, ff = e - ea, zf - fa
        M = np.zeros((7, 7), dtype=object)                                  # M(q)
        M[0, 0] = m[0] * self.ra**2 + m[1] * (rr**2 - 2 * da * rr * cth + da**2) + i[0] + i[1]
        M[1, 0] = M[0, 1] = m[1] * (da**2 - da * rr * cth) + i[1]
        M[1, 1] = m[1] * da**2 + i[1]
        M[2, 2] = m[2] * (self.sa**2 + self.sb**2) + i[2]
        M[3, 3] = m[3] * ee**2 + i[3]
        M[4, 3] = M[3, 4] = m[3] * (ee**2 + zt * ee * ac.sin(ph)) + i[3]
        M[4, 4] = (m[3] * (zt**2 + 2 * zt * ee * ac.sin(ph) + ee**2)
                   + m[4] * (self.ta**2 + self.tb**2) + i[3] + i[4])
        M[5, 5] = m[5] * ff**2 + i[5]
        M[6, 5] = M[5, 6] = m[5] * (ff**2 - u * ff * ac.sin(om)) + i[5]
        M[6, 6] = (m[5] * (ff**2 - 2 * u * ff * ac.sin(om) + u**2)
                   + m[6] * (self.ua**2 + self.ub**2) + i[5] + i[6])
        # the spring from D on body 3 to the fixed point C
        D = self.B + np.array([self.sd * ac.cos(ga) + self.sc * ac.sin(ga),
                               self.sd * ac.sin(ga) - self.sc * ac.cos(ga)])
        length = ac.sqrt((D - self.C) @ (D - self.C))
        F = -self.c0 * (length - self.l0) / length * (D - self.C)
        f = np.array([                                                        # f(q, v)
            self.mom - m[1] * da * rr * thp * (thp + 2 * bp) * sth,
            m[1] * da * rr * bp**2 * sth,
            F[0] * (self.sc * ac.cos(ga) - self.sd * ac.sin(ga))
            + F[1] * (self.sd * ac.cos(ga) + self.sc * ac.sin(ga)),
            m[3] * zt * ee * dep**2 * ac.cos(ph),
            -m[3] * zt * ee * php * (php + 2 * dep) * ac.cos(ph),
            -m[5] * u * ff * epp**2 * ac.cos(om),
            m[5] * u * ff * omp * (omp + 2 * epp) * ac.cos(om)])
        # g(q): closed at B, and at A through bodies 4-5 and through bodies 6-7
        tip = np.array([rr * cb - d * cbth, rr * sb_ - d * sbth])
        g = np.concatenate([tip + ss * np.array([-ac.sin(ga), ac.cos(ga)]) - self.B,
                            tip + np.array([-e * sphde - zt * ac.cos(de),
                                            e * cphde - zt * ac.sin(de)]) - self.A,
                            tip + np.array([-zf * comep - u * ac.sin(ep),
                                            -zf * somep + u * ac.cos(ep)]) - self.A])
        dtip = np.array([[-rr * sb_ + d * sbth, d * sbth], [rr * cb - d * cbth, -d * cbth]])
        G = np.zeros((6, 7), dtype=object)                                  # dg/dq
        G[:, :2] = np.vstack([dtip, dtip, dtip])
        G[0:2, 2] = [-ss * ac.cos(ga), -ss * ac.sin(ga)]
        G[2:4, 3] = [-e * cphde, -e * sphde]
        G[2:4, 4] = [-e * cphde + zt * ac.sin(de), -e * sphde - zt * ac.cos(de)]
        G[4:6, 5] = [zf * somep, -zf * comep]
        G[4:6, 6] = [zf * somep - u * ac.cos(ep), -zf * comep - u * ac.sin(ep)]
        return [ac.Eq(ac.der(self.q), self.v),
                ac.Eq(M @ ac.der(self.v), f - G.T @ self.lam),
                ac.Eq(g, 0)]


if __name__ == "__main__":
    model = AndrewsSqueezer()
    compiled = ac.compile(model)
    print(compiled.report)
    res = ac.simulate(compiled, t_end=model.stop_time, rtol=1e-8)
    print(res["q"][-1])
