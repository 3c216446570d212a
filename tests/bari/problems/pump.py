"""PUMP: the charge pump, an index-2 DAE of dimension 9.

Test Set for IVP Solvers (Mazzia & Magherini, Bari, release 2.4), problem "pump"
(``pumpi.f`` of the MEBDFI drivers; Günther, Denk & Feldmann 1995): a MOS transistor
(charge model of Günther, Denk and Feldmann) between a source capacitor C_S and a drain
capacitor C_D, its gate driven by a pulse V_in(t) of period 120 ns, in charge-oriented
form: y1..y5 the charges of gate, source capacitor, source, drain capacitor and drain,
y6..y8 the voltages, y9 the gate current,

    y1' = -y9
    y2' + y3' = 0
    y4' + y5' = 0
    0 = -y6 + V_in(t)
    0 = y1 - q_G(y6, y6 - y7, y6 - y8)
    0 = y2 - C_S y7
    0 = y3 - q_S(y6, y6 - y7, y6 - y8)
    0 = y4 - C_D y8
    0 = y5 - q_D(y6, y6 - y7, y6 - y8),

q_G, q_S, q_D the test set's piecewise charge functions (written with ``if_else`` as
the Fortran's IF statements), on [0, 1200 ns].  The charges are of order 1e-12: the
test set's driver gives them an absolute tolerance 1e-6 of the others', which is their
nominal value here.  Started as ``init`` does (all voltages zero, the charges of the
transistor at zero voltages).  The test set's scd leaves out y9; its reference
(PSIDE at 2e-8) has y2..y8 exactly zero -- each charge returns: y2 + y3 and y4 + y5 are
conserved, zero at the start -- so its relative digits measure y1 alone.  Its drivers
judge y2..y8 by their absolute errors (mescd, ``benchmarks/bari.py``): acausal integrates
the states y2 and y4 from the derivatives of the transistor's charges y3 and y5 (dummy
derivatives), so the sums drift by the charges' error per step, and at the test set's
tolerance for charges (1e-14 at rtol 1e-8) y7 and y8 end at 0.099 and 0.397 V (y8
reaches 36 V in the run): mescd 0.40.  With atol 1e-20 on the charge states they end
within 6e-5 V (``test_bari``).
"""
import acausal as ac

from ..testset import BariProblem

__all__ = ["Pump", "PROBLEM"]

VT0, GAMMA, PHI, COX = 0.20, 0.350e-1, 1.010, 4.0e-12
CHARGE = 1e-6        # the nominal value of a charge (the test set's atol 1e-6 x)


class _Charges:
    """``qgate``, ``qsrc`` and ``qdrain`` of the test set (Günther, Denk & Feldmann)."""

    @staticmethod
    def _terminals(vgb, vgs, vgd):
        # the terminals of larger potential is the source
        swap = vgs - vgd <= 0
        ugs = ac.if_else(swap, vgd, vgs)
        ugd = ac.if_else(swap, vgs, vgd)
        ugb = vgb
        ubs = ugs - ugb
        vfb = VT0 - GAMMA * ac.sqrt(PHI) - PHI
        vte = VT0 + GAMMA * (ac.sqrt(PHI - ubs) - ac.sqrt(PHI))
        return ugs, ugd, ugb, ubs, vfb, vte

    @classmethod
    def gate(cls, vgb, vgs, vgd):
        ugs, ugd, ugb, ubs, vfb, vte = cls._terminals(vgb, vgs, vgd)
        ugst = ugs - vte
        ugdt = ac.if_else(ugd > vte, ugd - vte, 0)
        return ac.if_else(
            ugb <= vfb, COX * (ugb - vfb),
            ac.if_else(ugs <= vte,
                       COX * GAMMA * (ac.sqrt((GAMMA / 2)**2 + ugb - vfb) - GAMMA / 2),
                       COX * (2 / 3 * (ugdt + ugst - ugdt * ugst / (ugdt + ugst))
                              + GAMMA * ac.sqrt(PHI - ubs))))

    @classmethod
    def _channel(cls, vgb, vgs, vgd):
        """``qsrc`` and ``qdrain``: the same function."""
        ugs, ugd, ugb, ubs, vfb, vte = cls._terminals(vgb, vgs, vgd)
        ugst = ugs - vte
        ugdt = ac.if_else(ugd >= vte, ugd - vte, 0)
        return ac.if_else(
            ugb <= vfb, 0,
            ac.if_else(ugs <= vte, 0,
                       -COX / 3 * (ugdt + ugst - ugdt * ugst / (ugdt + ugst))))

    source = _channel
    drain = _channel


def vin(t):
    """The pulsed gate voltage: 0 for 50 ns, up to 20 V in 10 ns, 50 ns high, down in
    10 ns, period 120 ns."""
    vhigh, deltat, t1, t2, t3 = 20.0, 120.0e-9, 50.0e-9, 60.0e-9, 110.0e-9
    dummy = t % deltat
    return ac.if_else(dummy < t1, 0.0,
                      ac.if_else(dummy < t2, (dummy - t1) * 0.10e+9 * vhigh,
                                 ac.if_else(dummy < t3, vhigh,
                                            (deltat - dummy) * 0.10e+9 * vhigh)))


class Pump(ac.Component):
    """The charge pump (module docstring)."""

    capd = ac.Parameter(0.40e-12, description="drain capacitance C_D")
    caps = ac.Parameter(1.60e-12, description="source capacitance C_S")
    y1 = ac.Variable(start=_Charges.gate(0.0, 0.0, 0.0), fixed=True, nominal=CHARGE)
    y2 = ac.Variable(start=0.0, fixed=True, nominal=CHARGE)
    y3 = ac.Variable(start=_Charges.source(0.0, 0.0, 0.0), fixed=True, nominal=CHARGE)
    y4 = ac.Variable(start=0.0, fixed=True, nominal=CHARGE)
    y5 = ac.Variable(start=_Charges.drain(0.0, 0.0, 0.0), fixed=True, nominal=CHARGE)
    y6 = ac.Variable(start=0.0)
    y7 = ac.Variable(start=0.0)
    y8 = ac.Variable(start=0.0)
    y9 = ac.Variable(start=0.0)

    def equations(self):
        y6, y7, y8 = self.y6, self.y7, self.y8
        args = (y6, y6 - y7, y6 - y8)
        return [ac.Eq(ac.der(self.y1), -self.y9),
                ac.Eq(ac.der(self.y2) + ac.der(self.y3), 0),
                ac.Eq(ac.der(self.y4) + ac.der(self.y5), 0),
                ac.Eq(0, -y6 + vin(ac.time)),
                ac.Eq(0, self.y1 - _Charges.gate(*args)),
                ac.Eq(0, self.y2 - self.caps * y7),
                ac.Eq(0, self.y3 - _Charges.source(*args)),
                ac.Eq(0, self.y4 - self.capd * y8),
                ac.Eq(0, self.y5 - _Charges.drain(*args))]


PROBLEM = BariProblem(
    "PUMP", "Charge pump", Pump, 1200e-9,
    {"y1": 0.1262800429876759e-12, "y2": 0.0, "y3": 0.0, "y4": 0.0, "y5": 0.0,
     "y6": 0.0, "y7": 0.0, "y8": 0.0, "y9": 0.1522565920949845e-03},
    index=2, scd_names=[f"y{i}" for i in range(1, 9)],
    rtol=1e-8, min_scd=8.0)
