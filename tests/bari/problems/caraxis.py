"""CARAXIS: the car axis, an index-3 DAE of dimension 10.

Test Set for IVP Solvers (Mazzia & Magherini, Bari, release 2.4), problem "caraxis"
(``Ex_car.f``; Schneider & Hairer): a car axis on a bumpy road, the left wheel at
(xl, yl), the right at (xr, yr), the axis of length L between them, springs of rest
length L0 to the chassis; the road lifts the right end as yb(t) = r sin(w t),
xb(t) = sqrt(L^2 - yb^2).  With k = M eps^2 / 2,

    p' = u
    k u' = f(t, p, lam)          (the spring forces, gravity and the constraints' forces)
    0 = xb xl + yb yl
    0 = (xl - xr)^2 + (yl - yr)^2 - L^2

on [0, 3].  The test set's initial values are consistent; the four positions and
velocities are fixed as given (two of each are redundant with the constraints).
"""
import acausal as ac

from ..testset import BariProblem

__all__ = ["CarAxis", "PROBLEM"]


class CarAxis(ac.Component):
    """The car axis (module docstring)."""

    eps = ac.Parameter(1e-2)
    M = ac.Parameter(10.0)
    L = ac.Parameter(1.0)
    L0 = ac.Parameter(0.5)
    r = ac.Parameter(0.1)
    w = ac.Parameter(10.0)
    g = ac.Parameter(1.0)
    xl = ac.Variable(start=0.0, fixed=True)
    yl = ac.Variable(start=0.5, fixed=True)
    xr = ac.Variable(start=1.0, fixed=True)
    yr = ac.Variable(start=0.5, fixed=True)
    ul = ac.Variable(start=-0.5, fixed=True)
    vl = ac.Variable(start=0.0, fixed=True)
    ur = ac.Variable(start=-0.5, fixed=True)
    vr = ac.Variable(start=0.0, fixed=True)
    lam1 = ac.Variable(start=0.0)
    lam2 = ac.Variable(start=0.0)

    def equations(self):
        xl, yl, xr, yr = self.xl, self.yl, self.xr, self.yr
        yb = self.r * ac.sin(self.w * ac.time)
        xb = ac.sqrt(self.L * self.L - yb * yb)
        Ll = ac.sqrt(xl**2 + yl**2)
        Lr = ac.sqrt((xr - xb)**2 + (yr - yb)**2)
        k = self.M * self.eps * self.eps / 2
        return [
            ac.Eq(ac.der(xl), self.ul),
            ac.Eq(ac.der(yl), self.vl),
            ac.Eq(ac.der(xr), self.ur),
            ac.Eq(ac.der(yr), self.vr),
            ac.Eq(k * ac.der(self.ul),
                  (self.L0 - Ll) * xl / Ll + self.lam1 * xb + 2 * self.lam2 * (xl - xr)),
            ac.Eq(k * ac.der(self.vl),
                  (self.L0 - Ll) * yl / Ll + self.lam1 * yb + 2 * self.lam2 * (yl - yr)
                  - self.M * self.eps * self.eps * self.g / 2),
            ac.Eq(k * ac.der(self.ur),
                  (self.L0 - Lr) * (xr - xb) / Lr - 2 * self.lam2 * (xl - xr)),
            ac.Eq(k * ac.der(self.vr),
                  (self.L0 - Lr) * (yr - yb) / Lr - 2 * self.lam2 * (yl - yr)
                  - self.M * self.eps * self.eps * self.g / 2),
            ac.Eq(0, xb * xl + yb * yl),
            ac.Eq(0, (xl - xr)**2 + (yl - yr)**2 - self.L * self.L)]


PROBLEM = BariProblem(
    "CARAXIS", "Car axis", CarAxis, 3.0,
    {"xl": 0.493455784275402809122e-1, "yl": 0.496989460230171153861,
     "xr": 0.104174252488542151681e1, "yr": 0.373911027265361256927,
     "ul": -0.770583684040972357970e-1, "vl": 0.744686658723778553466e-2,
     "ur": 0.175568157537232222276e-1, "vr": 0.770341043779251976443,
     "lam1": -0.473688659084893324729e-2, "lam2": -0.110468033125734368808e-2},
    index=3,
    rtol=1e-10, min_scd=5.0)
