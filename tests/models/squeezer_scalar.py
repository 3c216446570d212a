"""Andrews' squeezing mechanism written in the scalar form: one declaration per scalar
parameter and variable, one equation per scalar equation, as a model had to be written
before the language had arrays.

The physics is that of ``library/multibody/examples/squeezer.py`` (Hairer & Wanner,
*Solving Ordinary Differential Equations II*, section VII.7, the system (7.11)), entry by
entry: the mass matrix M(q), the forces f(q, v), the position constraints g(q) and their
Jacobian G(q) = dg/dq are written out element by element, and the seven equations of
motion carry the products M q'' and G^T lam term by term.
"""
import acausal as ac
from acausal.library.multibody.examples.squeezer import Q0

__all__ = ["AndrewsSqueezerScalars", "ANGLES", "RATES", "MULTIPLIERS"]

# the names of the scalar form in the order of the array form's q, v and lam
ANGLES = ("beta", "Theta", "gamma", "Phi", "delta", "Omega", "epsilon")
RATES = tuple("w" + name for name in ANGLES)
MULTIPLIERS = ("lam1", "lam2", "lam3", "lam4", "lam5", "lam6")


class AndrewsSqueezerScalars(ac.Component):
    """``AndrewsSqueezer`` with one declaration per scalar (HW VII.7, (7.11)):

        q' = v,   M(q) v' = f(q, v) - G(q)^T lam,   g(q) = 0,   G = dg/dq
    """

    stop_time = 0.03
    m1 = ac.Parameter(0.04325, unit="kg", min=0, description="mass of body 1")
    m2 = ac.Parameter(0.00365, unit="kg", min=0, description="mass of body 2")
    m3 = ac.Parameter(0.02373, unit="kg", min=0, description="mass of body 3")
    m4 = ac.Parameter(0.00706, unit="kg", min=0, description="mass of body 4")
    m5 = ac.Parameter(0.07050, unit="kg", min=0, description="mass of body 5")
    m6 = ac.Parameter(0.00706, unit="kg", min=0, description="mass of body 6")
    m7 = ac.Parameter(0.05498, unit="kg", min=0, description="mass of body 7")
    I1 = ac.Parameter(2.194e-6, unit="kg.m2", min=0, description="inertia of body 1")
    I2 = ac.Parameter(4.410e-7, unit="kg.m2", min=0, description="inertia of body 2")
    I3 = ac.Parameter(5.255e-6, unit="kg.m2", min=0, description="inertia of body 3")
    I4 = ac.Parameter(5.667e-7, unit="kg.m2", min=0, description="inertia of body 4")
    I5 = ac.Parameter(1.169e-5, unit="kg.m2", min=0, description="inertia of body 5")
    I6 = ac.Parameter(5.667e-7, unit="kg.m2", min=0, description="inertia of body 6")
    I7 = ac.Parameter(1.912e-5, unit="kg.m2", min=0, description="inertia of body 7")
    xa = ac.Parameter(-0.06934, unit="m", description="fixed point A, x")
    ya = ac.Parameter(-0.00227, unit="m", description="fixed point A, y")
    xb = ac.Parameter(-0.03635, unit="m", description="fixed point B, x")
    yb = ac.Parameter(0.03273, unit="m", description="fixed point B, y")
    xc = ac.Parameter(0.014, unit="m", description="spring anchor C, x")
    yc = ac.Parameter(0.072, unit="m", description="spring anchor C, y")
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
    beta = ac.Variable(start=Q0[0], fixed=True, unit="rad")
    Theta = ac.Variable(start=Q0[1], unit="rad")
    gamma = ac.Variable(start=Q0[2], unit="rad")
    Phi = ac.Variable(start=Q0[3], unit="rad")
    delta = ac.Variable(start=Q0[4], unit="rad")
    Omega = ac.Variable(start=Q0[5], unit="rad")
    epsilon = ac.Variable(start=Q0[6], unit="rad")
    wbeta = ac.Variable(start=0.0, fixed=True, unit="rad/s")
    wTheta = ac.Variable(start=0.0, unit="rad/s")
    wgamma = ac.Variable(start=0.0, unit="rad/s")
    wPhi = ac.Variable(start=0.0, unit="rad/s")
    wdelta = ac.Variable(start=0.0, unit="rad/s")
    wOmega = ac.Variable(start=0.0, unit="rad/s")
    wepsilon = ac.Variable(start=0.0, unit="rad/s")
    lam1 = ac.Variable(start=0.0, description="Lagrange multiplier of g1 = 0")
    lam2 = ac.Variable(start=0.0, description="Lagrange multiplier of g2 = 0")
    lam3 = ac.Variable(start=0.0, description="Lagrange multiplier of g3 = 0")
    lam4 = ac.Variable(start=0.0, description="Lagrange multiplier of g4 = 0")
    lam5 = ac.Variable(start=0.0, description="Lagrange multiplier of g5 = 0")
    lam6 = ac.Variable(start=0.0, description="Lagrange multiplier of g6 = 0")

    def equations(self):
        b, th, ga, ph, de, om, ep = (self.beta, self.Theta, self.gamma, self.Phi, self.delta,
                                     self.Omega, self.epsilon)
        bp, thp, gap, php, dep, omp, epp = (self.wbeta, self.wTheta, self.wgamma, self.wPhi,
                                            self.wdelta, self.wOmega, self.wepsilon)
        rr, d, da, ss, e, ea, zt, zf, u, fa = (self.rr, self.d, self.da, self.ss, self.e,
                                               self.ea, self.zt, self.zf, self.u, self.fa)
        sd, sc = self.sd, self.sc
        cb, sb_, cth, sth = ac.cos(b), ac.sin(b), ac.cos(th), ac.sin(th)
        cbth, sbth = ac.cos(b + th), ac.sin(b + th)
        cphde, sphde = ac.cos(ph + de), ac.sin(ph + de)
        comep, somep = ac.cos(om + ep), ac.sin(om + ep)
        ee, ff = e - ea, zf - fa
        # M(q), symmetric
        m11 = (self.m1 * self.ra**2 + self.m2 * (rr**2 - 2 * da * rr * cth + da**2)
               + self.I1 + self.I2)
        m12 = self.m2 * (da**2 - da * rr * cth) + self.I2
        m22 = self.m2 * da**2 + self.I2
        m33 = self.m3 * (self.sa**2 + self.sb**2) + self.I3
        m44 = self.m4 * ee**2 + self.I4
        m45 = self.m4 * (ee**2 + zt * ee * ac.sin(ph)) + self.I4
        m55 = (self.m4 * (zt**2 + 2 * zt * ee * ac.sin(ph) + ee**2)
               + self.m5 * (self.ta**2 + self.tb**2) + self.I4 + self.I5)
        m66 = self.m6 * ff**2 + self.I6
        m67 = self.m6 * (ff**2 - u * ff * ac.sin(om)) + self.I6
        m77 = (self.m6 * (ff**2 - 2 * u * ff * ac.sin(om) + u**2)
               + self.m7 * (self.ua**2 + self.ub**2) + self.I6 + self.I7)
        # the spring from D on body 3 to the fixed point C
        xd = self.xb + sd * ac.cos(ga) + sc * ac.sin(ga)
        yd = self.yb + sd * ac.sin(ga) - sc * ac.cos(ga)
        length = ac.sqrt((xd - self.xc)**2 + (yd - self.yc)**2)
        fx = -self.c0 * (length - self.l0) / length * (xd - self.xc)
        fy = -self.c0 * (length - self.l0) / length * (yd - self.yc)
        # f(q, v)
        f1 = self.mom - self.m2 * da * rr * thp * (thp + 2 * bp) * sth
        f2 = self.m2 * da * rr * bp**2 * sth
        f3 = fx * (sc * ac.cos(ga) - sd * ac.sin(ga)) + fy * (sd * ac.cos(ga) + sc * ac.sin(ga))
        f4 = self.m4 * zt * ee * dep**2 * ac.cos(ph)
        f5 = -self.m4 * zt * ee * php * (php + 2 * dep) * ac.cos(ph)
        f6 = -self.m6 * u * ff * epp**2 * ac.cos(om)
        f7 = self.m6 * u * ff * omp * (omp + 2 * epp) * ac.cos(om)
        # g(q): closed at B, and at A through bodies 4-5 and through bodies 6-7
        g1 = rr * cb - d * cbth - ss * ac.sin(ga) - self.xb
        g2 = rr * sb_ - d * sbth + ss * ac.cos(ga) - self.yb
        g3 = rr * cb - d * cbth - e * sphde - zt * ac.cos(de) - self.xa
        g4 = rr * sb_ - d * sbth + e * cphde - zt * ac.sin(de) - self.ya
        g5 = rr * cb - d * cbth - zf * comep - u * ac.sin(ep) - self.xa
        g6 = rr * sb_ - d * sbth - zf * somep + u * ac.cos(ep) - self.ya
        # G = dg/dq: the beta and Theta columns are the same in rows 1, 3, 5 and in 2, 4, 6
        gx_b, gx_th = -rr * sb_ + d * sbth, d * sbth
        gy_b, gy_th = rr * cb - d * cbth, -d * cbth
        g13, g23 = -ss * ac.cos(ga), -ss * ac.sin(ga)
        g34, g44 = -e * cphde, -e * sphde
        g35, g45 = -e * cphde + zt * ac.sin(de), -e * sphde - zt * ac.cos(de)
        g56, g66 = zf * somep, -zf * comep
        g57, g67 = zf * somep - u * ac.cos(ep), -zf * comep - u * ac.sin(ep)
        lam1, lam2, lam3, lam4, lam5, lam6 = (self.lam1, self.lam2, self.lam3, self.lam4,
                                              self.lam5, self.lam6)
        return [ac.Eq(ac.der(b), bp), ac.Eq(ac.der(th), thp), ac.Eq(ac.der(ga), gap),
                ac.Eq(ac.der(ph), php), ac.Eq(ac.der(de), dep), ac.Eq(ac.der(om), omp),
                ac.Eq(ac.der(ep), epp),
                ac.Eq(m11 * ac.der(bp) + m12 * ac.der(thp),
                      f1 - gx_b * lam1 - gy_b * lam2 - gx_b * lam3 - gy_b * lam4
                      - gx_b * lam5 - gy_b * lam6),
                ac.Eq(m12 * ac.der(bp) + m22 * ac.der(thp),
                      f2 - gx_th * lam1 - gy_th * lam2 - gx_th * lam3 - gy_th * lam4
                      - gx_th * lam5 - gy_th * lam6),
                ac.Eq(m33 * ac.der(gap), f3 - g13 * lam1 - g23 * lam2),
                ac.Eq(m44 * ac.der(php) + m45 * ac.der(dep), f4 - g34 * lam3 - g44 * lam4),
                ac.Eq(m45 * ac.der(php) + m55 * ac.der(dep), f5 - g35 * lam3 - g45 * lam4),
                ac.Eq(m66 * ac.der(omp) + m67 * ac.der(epp), f6 - g56 * lam5 - g66 * lam6),
                ac.Eq(m67 * ac.der(omp) + m77 * ac.der(epp), f7 - g57 * lam5 - g67 * lam6),
                ac.Eq(g1, 0), ac.Eq(g2, 0), ac.Eq(g3, 0), ac.Eq(g4, 0), ac.Eq(g5, 0),
                ac.Eq(g6, 0)]
