"""WHEELSET: a railway wheelset, an index-2 DAE of dimension 17.

Test Set for IVP Solvers (Mazzia & Magherini, Bari, release 2.4), problem "wheel"
(``Ex_wheelset.f``; Simeon, Führer & Rentrop, "Introduction to differential-algebraic
equations in vehicle system dynamics", Surv. Math. Ind. 1 (1991)): a wheelset on a
straight track at V = 30 m/s, with the lateral, vertical and angular displacements
p = (x, y, z, theta, phi), their velocities v, the rotation perturbation beta, the
contact-point coordinates q = (psi_R, xi_R, psi_L, xi_L) and the two scaled normal-force
multipliers lam:

    p' = v
    M(p) (v', beta')^T = f(p, v, beta, q, lam)        (rows as ``wheelres`` writes them)
    0 = Q_L(p, q) v,   0 = Q_R(p, q) v                 (the contact, index-2 form)
    0 = g(p, q)                                        (four contact-plane conditions)

with the wheel profile (a cone), the rail profile (a circle), the contact angles, the
normal forces and the creepage forces of Jaschinski (tanh law, normalized where it
exceeds mu N) written inline, as ``RESWHS``, ``WHEELP``, ``RAILP``, ``CONSTM`` and
``CREEP`` compute them: every intermediate quantity an expression, ``abs`` and ``sign``
of the profile coordinates (Fortran's ABS and SIGN(1, x)) and the normalization's IF
among them.  On [0, 10].  The test set's y(0) is consistent; positions, velocities
and beta are fixed as given (two velocities are redundant with the contact
constraints).  The reference is DASSL's at 1e-9 (the multipliers left out of its error
control), about 9 digits in p, v and q.
"""
import acausal as ac

from ..testset import BariProblem

__all__ = ["Wheelset", "PROBLEM"]

PI = 3.1415926       # CREEP's PI
Y0 = [0.14941e-02, 0.40089e-06, 0.11241e-05, -.28573e-03, 0.26459e-03,
      0, 0, 0, 0, 0, 0,
      -7.4122380357667139e-06, -0.1521364296121248, 7.5634406395172940e-06,
      0.1490635714733819, -8.3593e-3, -7.4144e-3]


class Wheelset(ac.Component):
    """The wheelset, index-2 form (module docstring)."""

    MR = ac.Parameter(16.08)
    G = ac.Parameter(9.81)
    V = ac.Parameter(30.0)
    RN0 = ac.Parameter(0.1)
    LI1 = ac.Parameter(0.0605)
    LI2 = ac.Parameter(0.366)
    MA = ac.Parameter(0.0)
    HA = ac.Parameter(0.2)
    MU = ac.Parameter(0.12)
    XL = ac.Parameter(0.19)
    CX = ac.Parameter(6400.0)
    CZ = ac.Parameter(6400.0)
    E = ac.Parameter(1.3537956)
    GG = ac.Parameter(0.7115218)
    SIGMA = ac.Parameter(0.28)
    GM = ac.Parameter(7.92e10)
    C11 = ac.Parameter(4.72772197)
    C22 = ac.Parameter(4.27526987)
    C23 = ac.Parameter(1.97203505)
    DELTA0 = ac.Parameter(0.0262)
    AR = ac.Parameter(0.1506)
    RS = ac.Parameter(0.06)
    S = ac.Parameter(0.0, description="track curvature (straight track)")
    ALPHA = ac.Parameter(0.0, description="track inclination")
    x = ac.Variable(start=Y0[0], fixed=True)
    y = ac.Variable(start=Y0[1], fixed=True)
    z = ac.Variable(start=Y0[2], fixed=True)
    theta = ac.Variable(start=Y0[3], fixed=True)
    phi = ac.Variable(start=Y0[4], fixed=True)
    v = ac.Variable(shape=5, start=0.0, fixed=True)
    beta = ac.Variable(start=0.0, fixed=True)
    q = ac.Variable(shape=4, start=Y0[11:15], description="psi_R, xi_R, psi_L, xi_L")
    lam = ac.Variable(shape=2, start=Y0[15:17], description="normal forces / 1e4")

    # -- profiles (WHEELP, RAILP) and the constraint Jacobian (CONSTM) ---------------------
    def wheel(self, x):
        """Cone: r(x) and r'(x)."""
        ta = ac.tan(self.DELTA0)
        return self.RN0 + ta * (self.AR - ac.abs(x)), ac.sign(x) * (-ta)

    def rail(self, x):
        """Circle: g(x), g'(x), g''(x)."""
        sir = ac.sin(self.DELTA0) * self.RS
        xabs = ac.abs(x)
        t = ac.sqrt(self.RS**2 - (xabs - self.AR - sir)**2)
        return (t - self.RN0 - ac.cos(self.DELTA0) * self.RS,
                ac.sign(x) * (-xabs + self.AR + sir) / t,
                -self.RS**2 / t**3)

    @staticmethod
    def constm(xr, rx, dgx, sit, cot, sip, cop, sips, cops):
        return [dgx, -1, 0,
                dgx * (rx * (-cot * sips - cops * sip * sit) - cop * sit * xr),
                -(cops * rx * sip) - cop * xr + dgx * (cop * cops * cot * rx - cot * sip * xr)]

    # -- creepage forces (CREEP) ------------------------------------------------------------
    def _contact(self, fn, rx, drx, d2rx, dgx, d2gx, delta, side, sis, cos_, xr, omega):
        """Creepage force (T1, T2, T3) at one contact point; ``side`` is +1 on the left,
        -1 on the right (CREEP's two halves differ only in the signs it takes)."""
        P = self
        xx, yy, zz = P.x, P.y, P.z
        xxp, yyp, zzp, tetap, phip = P.v
        betap = P.beta
        S, sia, coa = P.S, ac.sin(P.ALPHA), ac.cos(P.ALPHA)
        sip, cop = ac.sin(P.phi), ac.cos(P.phi)
        sid, cod = ac.sin(delta), ac.cos(delta)
        sit, cot = ac.sin(P.theta / cod), ac.cos(P.theta / cod)
        rr = rx * ac.sqrt(1 + drx * drx)
        rhog = -d2gx / (1 + dgx * dgx)**1.5
        rhor = d2rx / (1 + drx * drx)**1.5
        a, b = 0.5 / rr, 0.5 * (rhog + rhor)
        wabs = ac.abs(fn) * 3
        c = ((wabs * (1 - P.SIGMA) * P.E) / (2 * PI * (a + b) * P.GM * ac.sqrt(P.GG)))**(1 / 3)
        # relative velocity
        wvk1 = (-(omega + betap) * rx * (sit * cos_ + cot * sip * sis)
                + P.V * S * coa * (rx * (sit * sip * cos_ + cot * sis) + xr * sit * cop - zz)
                + xxp - tetap * (rx * (sit * sip * cos_ + cot * sis) + xr * sit * cop)
                - phip * cot * (xr * sip - rx * cop * cos_))
        wvk2 = ((omega + betap) * rx * cop * sis
                + P.V * S * sia * (zz - xr * sit * cop - rx * (sit * sip * cos_ + cot * sis))
                + yyp + phip * (xr * cop + rx * sip * cos_))
        wvk3 = (-(omega + betap) * rx * (cot * cos_ - sit * sip * sis) + P.V + zzp
                + P.V * S * (xx * coa - yy * sia
                             + coa * (rx * (cot * sip * cos_ - sit * sis) + xr * cot * cop)
                             + sia * (rx * cop * cos_ - xr * sip))
                - tetap * (xr * cot * cop + rx * (cot * sip * cos_ - sit * sis))
                + phip * sit * (xr * sip - rx * cop * cos_))
        # rolling velocity
        wvk4 = wvk1 - 2 * xxp + 2 * P.V * S * zz * coa
        wvk5 = wvk2 - 2 * yyp - 2 * P.V * S * zz * sia
        wvk6 = wvk3 - 2 * zzp - 2 * P.V * S * (xx * coa - yy * sia) - 2 * P.V
        wvr = 0.5 * ac.sqrt(wvk4 * wvk4 + wvk5 * wvk5 + wvk6 * wvk6)
        # creepage
        wnux = (sit * wvk1 + cot * wvk3) / wvr
        wnuy = (cot * cod * wvk1 + side * sid * wvk2 - sit * cod * wvk3) / wvr
        wphis = (-side * sid * (omega + betap - P.V * S * sia) + cod * (tetap - P.V * S * coa)) / wvr
        # creepage forces, normalized where they exceed mu N
        wt = P.MU * fn
        tx = -wt * ac.tanh(P.GM * c * c * P.C11 * wnux / wt)
        ty = -wt * ac.tanh(P.GM * c * c * P.C22 * wnuy / wt + P.GM * c**3 * P.C23 * wphis / wt)
        sqt = ac.sqrt(tx * tx + ty * ty)
        over = sqt * sqt > wt * wt
        tx = ac.if_else(over, tx * ac.abs(wt) / sqt, tx)
        ty = ac.if_else(over, ty * ac.abs(wt) / sqt, ty)
        # transformation to the nominal reference frame
        return [sit * tx + cot * cod * ty, side * sid * ty, cot * tx - sit * cod * ty]

    def equations(self):
        P = self
        psir, xrr, psil, xrl = P.q
        e1, e2 = P.lam[0] * 1e4, P.lam[1] * 1e4
        xxp, yyp, zzp, tetap, phip = P.v
        betap, teta, phi, xx, yy, zz = P.beta, P.theta, P.phi, P.x, P.y, P.z
        S, V = P.S, P.V
        omega = V / P.RN0
        sit, cot, sip, cop = ac.sin(teta), ac.cos(teta), ac.sin(phi), ac.cos(phi)
        sia, coa = ac.sin(P.ALPHA), ac.cos(P.ALPHA)
        sisl, cosl, sisr, cosr = ac.sin(psil), ac.cos(psil), ac.sin(psir), ac.cos(psir)
        # profiles at the contact points
        rxl, drxl = P.wheel(xrl)
        xgl = xx + xrl * cot * cop + rxl * (cot * sip * cosl - sit * sisl)
        gxl, dgxl, d2gxl = P.rail(xgl)
        rxr, drxr = P.wheel(xrr)
        xgr = xx + xrr * cot * cop + rxr * (cot * sip * cosr - sit * sisr)
        gxr, dgxr, d2gxr = P.rail(xgr)
        ql = P.constm(xrl, rxl, dgxl, sit, cot, sip, cop, sisl, cosl)
        qr = P.constm(xrr, rxr, dgxr, sit, cot, sip, cop, sisr, cosr)
        # angles of the contact planes
        deltal = ac.atan(((drxl * cop - sip * cosl) * cot + sisl * sit) / (-drxl * sip - cosl * cop))
        deltar = ac.atan(((drxr * cop - sip * cosr) * cot + sisr * sit) / (drxr * sip + cosr * cop))
        sidl, codl, sidr, codr = ac.sin(deltal), ac.cos(deltal), ac.sin(deltar), ac.cos(deltar)
        # normal forces
        deter = -sidl * codr - sidr * codl
        w1 = ql[0] * e1 + qr[0] * e2
        w2 = ql[1] * e1 + qr[1] * e2
        fnl = (codr * w1 - sidr * w2) / deter
        fnr = (-codl * w1 - sidl * w2) / deter
        tl = P._contact(fnl, rxl, drxl, 0, dgxl, d2gxl, deltal, 1, sisl, cosl, xrl, omega)
        tr = P._contact(fnr, rxr, drxr, 0, dgxr, d2gxr, deltar, -1, sisr, cosr, xrr, omega)
        # forces of the chassis
        fq1 = P.MA * P.G * (V * V * S / P.G - ac.tan(P.ALPHA)) / coa
        fq2 = -P.MA * P.G * coa * (V * V * S * ac.tan(P.ALPHA) / P.G + 1)
        fq3 = -2 * P.CZ * zz
        lm1, lm2, lm3 = 0, -2 * P.XL**2 * P.CZ * teta, -P.HA * fq1
        # dynamics: Newton's law
        d6 = (P.MR * (V * V * S * coa * (1 + (xx * coa - yy * sia) * S) + 2 * V * S * coa * zzp)
              + tl[0] + tr[0] + fq1 - P.MR * P.G * sia + ql[0] * e1 + qr[0] * e2
              - 2 * P.CX * xx)
        d7 = (P.MR * (-V * V * S * sia * (1 + (xx * coa - yy * sia) * S) - 2 * V * S * sia * zzp)
              + tl[1] + tr[1] + fq2 - P.MR * P.G * coa + ql[1] * e1 + qr[1] * e2)
        d8 = (P.MR * (-2 * V * S * (xxp * coa - yyp * sia) + V * V * S * S * zz)
              + tl[2] + tr[2] + fq3 + ql[2] * e1 + qr[2] * e2)
        # dynamics: Euler's law
        w1 = (-(xrl * sit + rxl * sisl * cot * cop) * tl[0] - rxl * sisl * sip * tl[1]
              + (-xrl * cot + rxl * sisl * sit * cop) * tl[2])
        w2 = (-(xrr * sit + rxr * sisr * cot * cop) * tr[0] - rxr * sisr * sip * tr[1]
              + (-xrr * cot + rxr * sisr * sit * cop) * tr[2])
        d9 = (-P.LI2 * (-tetap * phip * sip + V * S * (phip * (sia * cot * cop + coa * sip)
                                                      - tetap * sia * sit * sip))
              - P.LI1 * (omega + betap) * (phip - V * S * sit * sia)
              - (P.LI1 - P.LI2) * (tetap * sip - V * S * (cot * cop * sia + sip * coa))
              * (phip - V * S * sit * sia)
              + w1 + w2 + cop * lm2 - cot * sip * lm1 + sit * sip * lm3 + ql[3] * e1 + qr[3] * e2)
        w1 = (-(xrl * cot * sip - rxl * cosl * cot * cop) * tl[0]
              + (xrl * cop + rxl * cosl * sip) * tl[1]
              + (xrl * sit * sip - rxl * cosl * sit * cop) * tl[2])
        w2 = (-(xrr * cot * sip - rxr * cosr * cot * cop) * tr[0]
              + (xrr * cop + rxr * cosr * sip) * tr[1]
              + (xrr * sit * sip - rxr * cosr * sit * cop) * tr[2])
        d10 = (-P.LI2 * (-tetap * V * S * sia * cot)
               + P.LI1 * (omega + betap) * (tetap * cop + V * S * (cot * sip * sia - cop * coa))
               + (P.LI1 - P.LI2) * (tetap * sip - V * S * (cot * cop * sia + sip * coa))
               * (tetap * cop + V * S * (cot * sip * sia - cop * coa))
               + w1 + w2 + lm3 + ql[4] * e1 + qr[4] * e2)
        w1 = (-rxl * (cosl * sit + sisl * cot * sip) * tl[0] + rxl * sisl * cop * tl[1]
              - rxl * (cosl * cot - sisl * sit * sip) * tl[2])
        w2 = (-rxr * (cosr * sit + sisr * cot * sip) * tr[0] + rxr * sisr * cop * tr[1]
              - rxr * (cosr * cot - sisr * sit * sip) * tr[2])
        d11 = (-P.LI1 * (tetap * phip * cop - V * S * (phip * (coa * cop - sia * cot * sip)
                                                       - tetap * sia * sit * cop))
               + w1 + w2 + sip * lm2)
        vel = [xxp, yyp, zzp, tetap, phip]
        return [
            ac.Eq(ac.der(xx), xxp), ac.Eq(ac.der(yy), yyp), ac.Eq(ac.der(zz), zzp),
            ac.Eq(ac.der(teta), tetap), ac.Eq(ac.der(phi), phip),
            ac.Eq(P.MR * ac.der(xxp), d6),
            ac.Eq(P.MR * ac.der(yyp), d7),
            ac.Eq(P.MR * ac.der(zzp), d8),
            ac.Eq(P.LI2 * cop * ac.der(tetap), d9),
            ac.Eq(P.LI2 * ac.der(phip), d10),
            ac.Eq(P.LI1 * sip * ac.der(tetap) + P.LI1 * ac.der(betap), d11),
            # contact condition, index-2 form
            ac.Eq(0, sum(ql[i] * vel[i] for i in range(5))),
            ac.Eq(0, sum(qr[i] * vel[i] for i in range(5))),
            # normal vectors of the contact planes parallel (non-intersection)
            ac.Eq(0, dgxl * (drxl * sip + cop * cosl) + drxl * cot * cop - cot * sip * cosl
                  + sit * sisl),
            ac.Eq(0, drxl * sit * cop - sit * sip * cosl - cot * sisl),
            ac.Eq(0, dgxr * (drxr * sip + cop * cosr) + drxr * cot * cop - cot * sip * cosr
                  + sit * sisr),
            ac.Eq(0, drxr * sit * cop - sit * sip * cosr - cot * sisr)]


_REF = {"x": 0.86355386965811e-2, "y": 0.13038281022727e-4, "z": -0.93635784016818e-4,
        "theta": -0.13642299804033e-1, "phi": 0.15292895005422e-2,
        "v[0]": -0.76985374142666e-1, "v[1]": -0.25151106429207e-3,
        "v[2]": 0.20541188079539e-2, "v[3]": -0.23904837703692, "v[4]": -0.13633468454173e-1,
        "beta": -0.24421377661131, "q[0]": -0.33666751972196e-3,
        "q[1]": -0.15949425684022, "q[2]": 0.37839614386969e-3, "q[3]": 0.14173214964613,
        "lam[0]": -0.10124044903201e-1, "lam[1]": -0.56285630573753e-2}

PROBLEM = BariProblem("WHEELSET", "Wheelset", Wheelset, 10.0, _REF, index=2,
    rtol=1e-8, min_scd=5.0)
