"""TUBE: the water tube system, an index-2 DAE of dimension 49.

Test Set for IVP Solvers (Mazzia & Magherini, Bari, release 2.4), problem "water"
(``Ex_tube.f``; C. Lubich's model of a water network): 13 nodes joined by 18 tubes of
length 1000 m and diameter 1 m; in tube (i, j) the flow phi_ij and the friction
factor lam_ij, at node i the pressure p_i; nodes 5 and 8 are buffers (pressure
equations with compliance c = b / (rho g)), water flows in at nodes 1 and 13 and out at
node 10.  With A = pi d^2/4, v = rho L / A, Reynolds number R = |phi d / (nu A)|,

    v phi_ij' = p_i - p_j - lam_ij rho L phi_ij^2 / (A^2 d)     (R > Rcrit)
              = p_i - p_j - 32 nu rho L phi_ij / (A d^2)        (laminar)
    0 = 1/sqrt(lam_ij) - 1.74 + 2 log10(2k/d + 18.7/(max(R, Rcrit) sqrt(lam_ij)))
    c p_i' = e_in,i - e_out,i + sum_k phi_ki - sum_k phi_ik     (i = 5, 8)
    0      = e_in,i - e_out,i + sum_k phi_ki - sum_k phi_ik     (the other nodes)

e_in,1 = (1 - cos(exp(-t/3600) - 1))/200, e_in,13 = (1 - cos(exp(-t/3600) - 1))/80,
e_out,10 = (t/3600)^2 (3 (t/3600)^2 - 92 t/3600 + 720) / 1e6, on [0, 17 h].  The
switch between the turbulent and the laminar law at Rcrit is an event.  The test set
starts at rest (phi = 0, p = 109800 Pa, lam = 0.0475...); the flows and the two buffer
pressures are fixed as given (eleven flow conditions are redundant with the node
balances).  The reference is the test set's (RADAU5).
"""
import numpy as np

import acausal as ac

from ..testset import BariProblem

__all__ = ["Tube", "PROBLEM"]

# the tubes (from node, to node), in the test set's order of phi and lambda
TUBES = [(1, 2), (2, 3), (2, 6), (3, 4), (3, 5), (4, 5), (5, 10), (6, 5), (7, 4), (7, 8),
         (8, 5), (8, 10), (9, 8), (11, 9), (11, 12), (12, 7), (12, 8), (13, 11)]
NODES = 13
BUFFERS = (5, 8)
LAM0 = 0.47519404529185289807e-1
P0 = 109800.0


class Tube(ac.Component):
    """The water tube network (module docstring)."""

    nu = ac.Parameter(1.31e-6)
    g = ac.Parameter(9.8)
    rho = ac.Parameter(1.0e3)
    rcrit = ac.Parameter(2.3e3)
    length = ac.Parameter(1.0e3)
    k = ac.Parameter(2.0e-4)
    d = ac.Parameter(1.0)
    b = ac.Parameter(2.0e2)
    phi = ac.Variable(shape=len(TUBES), start=0.0, fixed=True)
    lam = ac.Variable(shape=len(TUBES), start=LAM0)
    p = ac.Variable(shape=NODES, start=P0, description="p[i-1]: pressure at node i",
                    fixed=[i + 1 in BUFFERS for i in range(NODES)])

    def equations(self):
        a = np.pi * self.d**2 / 4
        mu = self.nu * self.rho
        v = self.rho * self.length / a
        c = self.b / (self.rho * self.g)
        that = ac.time / 3600
        e_in = {1: (1 - ac.cos(ac.exp(-that) - 1)) / 200,
                13: (1 - ac.cos(ac.exp(-that) - 1)) / 80}
        e_out = {10: that**2 * (3 * that**2 - 92 * that + 720) / 1e6}
        eqs = []
        for n, (i, j) in enumerate(TUBES):
            phi, lam = self.phi[n], self.lam[n]
            r = abs(phi * self.d / (self.nu * a))
            turbulent = r > self.rcrit
            eqs.append(ac.Eq(v * ac.der(phi), ac.if_else(
                turbulent,
                self.p[i - 1] - self.p[j - 1] - lam * self.rho * self.length * phi**2
                / (a**2 * self.d),
                self.p[i - 1] - self.p[j - 1] - 32 * mu * self.length * phi / (a * self.d**2))))
            eqs.append(ac.Eq(0, ac.if_else(
                turbulent,
                1 / ac.sqrt(lam) - 1.74
                + 2 * ac.log(2 * self.k / self.d + 18.7 / (r * ac.sqrt(lam))) / np.log(10),
                1 / ac.sqrt(lam) - 1.74
                + 2 * ac.log(2 * self.k / self.d + 18.7 / (self.rcrit * ac.sqrt(lam)))
                / np.log(10))))
        for node in range(1, NODES + 1):
            net = e_in.get(node, 0) - e_out.get(node, 0)
            net = net + sum(self.phi[n] for n, (i, j) in enumerate(TUBES) if j == node)
            net = net - sum(self.phi[n] for n, (i, j) in enumerate(TUBES) if i == node)
            if node in BUFFERS:
                eqs.append(ac.Eq(c * ac.der(self.p[node - 1]), net))
            else:
                eqs.append(ac.Eq(0, net))
        return eqs


_PHI = [0.2298488296477430e-2, 0.1188984650746585e-2, 0.1109503645730845e-2,
        0.1589620100314825e-3, 0.1030022640715102e-2, 0.8710606306836165e-3,
        0.3243571480903489e-2, 0.1109503645730845e-2, 0.7120986206521341e-3,
        0.6414613963833099e-3, 0.9416978549524347e-3, 0.3403428519096511e-2,
        0.2397639310739395e-2, 0.2397639310739395e-2, 0.3348581430454180e-2,
        0.1353560017035444e-2, 0.1995021413418736e-2, 0.5746220741193575e-2]
_LAM = [0.4751940452918529e-1] * 6 + [0.4311196778792902e-1] + [0.4751940452918529e-1] * 4 \
    + [0.4249217433601160e-1, 0.4732336439609648e-1, 0.4732336439609648e-1,
       0.4270002118868241e-1, 0.4751940452918529e-1, 0.4751940452918529e-1,
       0.3651427026675656e-1]
# y37.. y49: p5, p8, then p1, p2, p3, p4, p6, p7, p9, ..., p13
_P = {5: 0.1111268591478108e+6, 8: 0.1111270045592387e+6, 1: 0.1111271078730254e+6,
      2: 0.1111269851929858e+6, 3: 0.1111269255355337e+6, 4: 0.1111269322658045e+6,
      6: 0.1111269221703983e+6, 7: 0.1111270121140691e+6, 9: 0.1111274419515807e+6,
      10: 0.1111255158881087e+6, 11: 0.1111278793439227e+6, 12: 0.1111270995171642e+6,
      13: 0.1111298338971779e+6}
_REF = {f"phi[{n}]": v for n, v in enumerate(_PHI)}
_REF.update({f"lam[{n}]": v for n, v in enumerate(_LAM)})
_REF.update({f"p[{i - 1}]": _P[i] for i in (5, 8, 1, 2, 3, 4, 6, 7, 9, 10, 11, 12, 13)})

PROBLEM = BariProblem("TUBE", "Water tube system", Tube, 17 * 3600.0, _REF, index=2,
                      rtol=1e-12, min_scd=5.0)
