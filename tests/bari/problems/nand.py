"""NAND: a NAND gate, an implicit ODE (index 0) of dimension 14.

Test Set for IVP Solvers (Mazzia & Magherini, Bari, release 2.4), problem "nand"
(``Ex_nand.f``; Günther & Rentrop): the network equation of a NAND gate of two
n-channel MOSFETs (the Shichman-Hodges model with bulk diodes) and a depletion-type
load, in charge-conserving form with voltage-dependent capacitances,

    C(U) U' = f(U, t),

U the 14 node potentials, C(U) the capacitance matrix ``CAP`` assembles (junction
capacitances C_BD(V) = C_BD / sqrt(1 - V/phi_B) for V <= 0, C_BD (1 + V/(2 phi_B))
above), f the static currents ``nandfunc`` assembles, driven by two trapezoidal pulse
inputs V1 (period 20) and V2 (period 40), on [0, 80].  The drain current, the bulk
currents and the capacitances are the test set's piecewise functions, written with
``if_else`` as the Fortran's IF statements (their relations are events).  The test
set's scd uses node 5 only (its output).  All fourteen potentials start at the test
set's values, fixed.
"""
import acausal as ac

from ..testset import BariProblem

__all__ = ["Nand", "PROBLEM"]

VBB = -2.5
U0 = [5.0, 5.0, VBB, VBB, 5.0, 3.62385, 5.0, VBB, VBB, 3.62385, 0.0, 3.62385, VBB, VBB]


def pulse(t, low, high, delay, t1, t2, t3, period):
    """``nandPULSE``: the trapezoidal input and its derivative at time t."""
    time = t % period
    vin = ac.if_else(time > delay + t1 + t2 + t3, low,
                     ac.if_else(time > delay + t1 + t2,
                                (high - low) / t3 * (delay + t1 + t2 + t3 - time) + low,
                                ac.if_else(time > delay + t1, high,
                                           ac.if_else(time > delay,
                                                      (high - low) / t1 * (time - delay) + low,
                                                      low))))
    vind = ac.if_else(time > delay + t1 + t2 + t3, 0,
                      ac.if_else(time > delay + t1 + t2, -(high - low) / t3,
                                 ac.if_else(time > delay + t1, 0,
                                            ac.if_else(time > delay, (high - low) / t1, 0))))
    return vin, vind


def _zero(entry) -> bool:
    """An entry CAP leaves at its initial 0 (a structural zero of C(U))."""
    return isinstance(entry, int) and entry == 0


class Nand(ac.Component):
    """The NAND gate (module docstring)."""

    RGS = ac.Parameter(4.0)
    RGD = ac.Parameter(4.0)
    RBS = ac.Parameter(10.0)
    RBD = ac.Parameter(10.0)
    CGS = ac.Parameter(0.6e-4)
    CGD = ac.Parameter(0.6e-4)
    CBD = ac.Parameter(2.4e-5)
    CBS = ac.Parameter(2.4e-5)
    C9 = ac.Parameter(0.5e-4)
    DELTA = ac.Parameter(0.2e-1)
    CURIS = ac.Parameter(1.e-14)
    VTH = ac.Parameter(25.85)
    VDD = ac.Parameter(5.0)
    VBB = ac.Parameter(VBB)
    U = ac.Variable(shape=14, start=U0, fixed=True)

    # -- the device models of Ex_nand.f ---------------------------------------------------
    def ids(self, ned, vds, vgs, vbs, vgd, vbd):
        """``nandIDS``: the drain current (GDSP for VDS > 0, GDSM for VDS < 0)."""
        return ac.if_else(vds > 0, self.gdsp(ned, vds, vgs, vbs),
                          ac.if_else(vds < 0, self.gdsm(ned, vds, vgd, vbd), 0))

    @staticmethod
    def _mos(ned, forward):
        if ned == 1:        # depletion type
            return -2.43, .2, 1.28, 5.35e-4
        # enhancement type: GDSM has BETA = 1.748e-4, GDSP 1.748e-3, as the test set
        return .2, 0.035, 1.01, (1.748e-3 if forward else 1.748e-4)

    def gdsp(self, ned, vds, vgs, vbs):
        vt0, cgamma, phi, beta = self._mos(ned, True)
        vte = vt0 + cgamma * (ac.sqrt(phi - vbs) - ac.sqrt(phi))
        return ac.if_else(
            vgs - vte <= 0, 0,
            ac.if_else(vgs - vte <= vds,
                       -beta * (vgs - vte)**2 * (1 + self.DELTA * vds),
                       -beta * vds * (2 * (vgs - vte) - vds) * (1 + self.DELTA * vds)))

    def gdsm(self, ned, vds, vgd, vbd):
        vt0, cgamma, phi, beta = self._mos(ned, False)
        vte = vt0 + cgamma * (ac.sqrt(phi - vbd) - ac.sqrt(phi))
        return ac.if_else(
            vgd - vte <= 0, 0,
            ac.if_else(vgd - vte <= -vds,
                       beta * (vgd - vte)**2 * (1 - self.DELTA * vds),
                       -beta * vds * (2 * (vgd - vte) + vds) * (1 - self.DELTA * vds)))

    def ibs(self, vbs):
        """``nandIBS`` (and ``nandIBD``, the same function): the bulk diode current."""
        return ac.if_else(vbs <= 0, -self.CURIS * (ac.exp(vbs / self.VTH) - 1), 0)

    ibd = ibs

    def cbdbs(self, v):
        """``nandCBDBS``: the junction capacitance."""
        phib = 0.87
        return ac.if_else(v <= 0, self.CBD / ac.sqrt(1 - v / phib),
                          self.CBD * (1 + v / (2 * phib)))

    def capacitance(self):
        """``CAP``: the capacitance matrix C(U), entry by entry."""
        Y, am = self.U, [[0] * 14 for _ in range(14)]
        am[0][0], am[0][4] = self.CGS, -self.CGS
        am[1][1], am[1][4] = self.CGD, -self.CGD
        am[2][2] = self.cbdbs(Y[2] - Y[4])
        am[2][4] = -self.cbdbs(Y[2] - Y[4])
        am[3][3] = self.cbdbs(Y[3] - self.VDD)
        am[4][0], am[4][1] = -self.CGS, -self.CGD
        am[4][2] = -self.cbdbs(Y[2] - Y[4])
        am[4][4] = self.CGS + self.CGD - am[4][2] + self.cbdbs(Y[8] - Y[4]) + self.C9
        am[4][8] = -self.cbdbs(Y[8] - Y[4])
        am[5][5] = self.CGS
        am[6][6] = self.CGD
        am[7][7] = self.cbdbs(Y[7] - Y[9])
        am[7][9] = -self.cbdbs(Y[7] - Y[9])
        am[8][4] = -self.cbdbs(Y[8] - Y[4])
        am[8][8] = self.cbdbs(Y[8] - Y[4])
        am[9][7] = -self.cbdbs(Y[7] - Y[9])
        am[9][9] = -am[7][9] + self.cbdbs(Y[13] - Y[9]) + self.C9
        am[9][13] = -self.cbdbs(Y[13] - Y[9])
        am[10][10] = self.CGS
        am[11][11] = self.CGD
        am[12][12] = self.cbdbs(Y[12])
        am[13][9] = -self.cbdbs(Y[13] - Y[9])
        am[13][13] = self.cbdbs(Y[13] - Y[9])
        return am

    def currents(self):
        """``nandfunc``: the static currents f(U, t)."""
        Y, t = self.U, ac.time
        V1, V1D = pulse(t, 0.0, 5.0, 5.0, 5.0, 5.0, 5.0, 20.0)
        V2, V2D = pulse(t, 0.0, 5.0, 15.0, 5.0, 15.0, 5.0, 40.0)
        RGS, RGD, RBS, RBD = self.RGS, self.RGD, self.RBS, self.RBD
        VDD, VBB = self.VDD, self.VBB
        ids1 = self.ids(1, Y[1] - Y[0], Y[4] - Y[0], Y[2] - Y[4], Y[4] - Y[1], Y[3] - VDD)
        ids2 = self.ids(2, Y[6] - Y[5], V1 - Y[5], Y[7] - Y[9], V1 - Y[6], Y[8] - Y[4])
        ids3 = self.ids(2, Y[11] - Y[10], V2 - Y[10], Y[12], V2 - Y[11], Y[13] - Y[9])
        return [
            -(Y[0] - Y[4]) / RGS - ids1,
            -(Y[1] - VDD) / RGD + ids1,
            -(Y[2] - VBB) / RBS + self.ibs(Y[2] - Y[4]),
            -(Y[3] - VBB) / RBD + self.ibd(Y[3] - VDD),
            -(Y[4] - Y[0]) / RGS - self.ibs(Y[2] - Y[4]) - (Y[4] - Y[6]) / RGD
            - self.ibd(Y[8] - Y[4]),
            self.CGS * V1D - (Y[5] - Y[9]) / RGS - ids2,
            self.CGD * V1D - (Y[6] - Y[4]) / RGD + ids2,
            -(Y[7] - VBB) / RBS + self.ibs(Y[7] - Y[9]),
            -(Y[8] - VBB) / RBD + self.ibd(Y[8] - Y[4]),
            -(Y[9] - Y[5]) / RGS - self.ibs(Y[7] - Y[9]) - (Y[9] - Y[11]) / RGD
            - self.ibd(Y[13] - Y[9]),
            self.CGS * V2D - Y[10] / RGS - ids3,
            self.CGD * V2D - (Y[11] - Y[9]) / RGD + ids3,
            -(Y[12] - VBB) / RBS + self.ibs(Y[12]),
            -(Y[13] - VBB) / RBD + self.ibd(Y[13] - Y[9])]

    def equations(self):
        am, f = self.capacitance(), self.currents()
        d = [ac.der(u) for u in self.U]
        return [ac.Eq(sum(am[i][j] * d[j] for j in range(14) if not _zero(am[i][j])), f[i])
                for i in range(14)]


_REF = [0.4971088699385777e+1, 0.4999752103929311e+1, -0.2499998781491227e+1,
        -0.2499999999999975e+1, 0.4970837023296724e+1, -0.2091214032073855e+0,
        0.4970593243278363e+1, -0.2500077409198803e+1, -0.2499998781491227e+1,
        -0.2090289583878100e+0, -0.2399999999966269e-3, -0.2091214032073855e+0,
        -0.2499999999999991e+1, -0.2500077409198803e+1]

PROBLEM = BariProblem(
    "NAND", "NAND gate", Nand, 80.0, {f"U[{i}]": v for i, v in enumerate(_REF)},
    index=0, scd_names=["U[4]"],
    rtol=1e-8, min_scd=5.0)
