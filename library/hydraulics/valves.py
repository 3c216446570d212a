"""Valves (Egeland & Gravdahl 4.2.4-4.2.9): four-way spool valves, a pressure-compensated
flow-control valve and a balance valve, all with the regularized orifice law (4.13)."""
import acausal as ac
from acausal.ports import FluidPort, RealInput

from .interfaces import PartialTwoPort, orifice_flow

__all__ = ["FourWayValve", "CriticalCentreValve", "OpenCentreValve",
           "PressureCompensatedValve", "BalanceValve"]


def _positive(x):
    return ac.if_else(x > 0, x, 0)


class _OrificeData(ac.Component):
    """Fluid and orifice data of the regularized law (4.13): the book's oil by default."""

    C_d = ac.Parameter(0.6, min=0, description="discharge coefficient")
    rho = ac.Parameter(900.0, unit="kg/m3", min=0, description="oil density")
    nu = ac.Parameter(30e-6, unit="m2/s", min=0, description="kinematic viscosity")
    Re_tr = ac.Parameter(1000.0, min=0, description="transition Reynolds number")

    def _orifice(self, A, dp):
        return orifice_flow(A, dp, self.C_d, self.rho, self.nu, self.Re_tr)


class FourWayValve(_OrificeData):
    """Four-way valve, general (Egeland & Gravdahl 4.2.4, (4.15)-(4.17)), the orifices
    with the regularized law (4.13):

        q_a = q(A_a, p_s - p_1),  q_b = q(A_b, p_s - p_2)     (supply -> 1, supply -> 2)
        q_c = q(A_c, p_1 - p_r),  q_d = q(A_d, p_2 - p_r)     (1 -> return, 2 -> return)
        q_s = q_a + q_b,  q_r = q_c + q_d,  q_1 = q_a - q_c,  q_2 = q_d - q_b   (4.16)-(4.17)

    q_s enters at port_s, q_r leaves at port_r, q_1 leaves at port_1 towards the load
    and q_2 comes back from it at port_2.  Subclasses give the opening areas A_a..A_d
    as functions of the spool position x_v (``areas``).
    """

    port_s = FluidPort()
    port_r = FluidPort()
    port_1 = FluidPort()
    port_2 = FluidPort()
    x_v = RealInput()
    q_1 = ac.Variable(start=0.0, unit="m3/s", nominal=1e-4, description="flow out to the load")
    q_2 = ac.Variable(start=0.0, unit="m3/s", nominal=1e-4,
                      description="flow back from the load")

    def loss_power(self):
        """sum of p q over the four ports: the orifices only throttle."""
        return sum(port.p * port.q for port in (self.port_s, self.port_r, self.port_1,
                                                 self.port_2))

    def areas(self):
        raise NotImplementedError

    def equations(self):
        A_a, A_b, A_c, A_d = self.areas()
        ps, pr, p1, p2 = self.port_s.p, self.port_r.p, self.port_1.p, self.port_2.p
        q_a, q_b = self._orifice(A_a, ps - p1), self._orifice(A_b, ps - p2)
        q_c, q_d = self._orifice(A_c, p1 - pr), self._orifice(A_d, p2 - pr)
        return [ac.Eq(self.q_1, q_a - q_c), ac.Eq(self.q_2, q_d - q_b),
                ac.Eq(self.port_1.q, -self.q_1), ac.Eq(self.port_2.q, self.q_2),
                ac.Eq(self.port_s.q, q_a + q_b), ac.Eq(self.port_r.q, -(q_c + q_d))]


class CriticalCentreValve(FourWayValve):
    """Matched, symmetric four-way valve with critical spool (Egeland & Gravdahl
    (4.18)-(4.20)), rectangular ports of width b:

        A_a = A_d = b max(x_v, 0) + A_leak,   A_b = A_c = b max(-x_v, 0) + A_leak
    """

    b = ac.Parameter(0.01, unit="m", min=0, description="area gradient (port width)")
    A_leak = ac.Parameter(0.0, unit="m2", min=0, description="leakage area of a closed orifice")

    def areas(self):
        open_1 = self.b * _positive(self.x_v) + self.A_leak
        open_2 = self.b * _positive(-self.x_v) + self.A_leak
        return open_1, open_2, open_2, open_1


class OpenCentreValve(FourWayValve):
    """Matched, symmetric four-way valve with open (underlapped) spool, underlap U
    (Egeland & Gravdahl (4.21)-(4.22)):

        A_a = A_d = b max(U + x_v, 0),   A_b = A_c = b max(U - x_v, 0)
    """

    b = ac.Parameter(0.01, unit="m", min=0, description="area gradient (port width)")
    U = ac.Parameter(1e-4, unit="m", min=0, description="underlap")

    def areas(self):
        open_1 = self.b * _positive(self.U + self.x_v)
        open_2 = self.b * _positive(self.U - self.x_v)
        return open_1, open_2, open_2, open_1


class PressureCompensatedValve(_OrificeData, PartialTwoPort):
    """Pressure-compensated flow-control valve (Egeland & Gravdahl 4.2.8), with the
    compensation spool in static equilibrium (its chambers at p_3 = p_c, p_4 = p_2):

        q = q(b_c x_c + A_leak, p_1 - p_c)                    (4.45)
          = q(b max(x_v, 0) + A_leak, p_c - p_2)              (4.46)
        K_c x_c = A_c (p_2 - p_c) + F_c0,   0 <= x_c <= x_c_max  (4.47), static

    The spool holds p_c - p_2 near F_c0/A_c, so q ~ C_d sqrt(2 F_c0/(rho A_c)) b x_v
    whatever p_1 - p_2 is (4.57).  The spool mass and the chamber dynamics (4.48)-(4.55)
    are not modelled.

    The main spool's opening is b max(x_v, 0): a negative command holds it closed.  A
    closed main spool with a closed compensator (x_v <= 0 and p_1 - p_2 > F_c0/A_c)
    traps the pressure p_c between them, which a static model cannot determine; a
    leakage area A_leak > 0 of both metering edges makes it the pressure between two
    equal leaks.
    """

    x_v = RealInput()
    b = ac.Parameter(0.01, unit="m", min=0, description="main spool area gradient")
    b_c = ac.Parameter(0.01, unit="m", min=0, description="compensator area gradient")
    A_c = ac.Parameter(1e-4, unit="m2", min=0, description="compensator spool area")
    K_c = ac.Parameter(1e3, unit="N/m", min=0, description="compensator spring stiffness")
    F_c0 = ac.Parameter(50.0, unit="N", description="spring preload")
    x_c_max = ac.Parameter(5e-3, unit="m", min=0, description="compensator stroke")
    A_leak = ac.Parameter(0.0, unit="m2", min=0,
                          description="leakage area of each closed metering edge")
    p_c = ac.Variable(start=0.0, unit="Pa", nominal=1e6, description="pressure between spools")
    x_c = ac.Variable(start=1e-3, unit="m", nominal=1e-3, description="compensator opening")

    def loss_power(self):
        """dp q: the two orifices in series only throttle."""
        return self.dp * self.q

    def equations(self):
        free = (self.F_c0 - self.A_c * (self.p_c - self.port_b.p)) / self.K_c
        clipped = ac.if_else(free < 0, 0, ac.if_else(free > self.x_c_max, self.x_c_max, free))
        return [ac.Eq(self.q, self._orifice(self.b_c * self.x_c + self.A_leak,
                                            self.dp + self.port_b.p - self.p_c)),
                ac.Eq(self.q, self._orifice(self.b * _positive(self.x_v) + self.A_leak,
                                            self.p_c - self.port_b.p)),
                ac.Eq(self.x_c, clipped)]


class BalanceValve(_OrificeData, PartialTwoPort):
    """Balance (counterbalance) valve, spool in static equilibrium (Egeland & Gravdahl
    4.2.9, (4.58)-(4.60)); port_a = 1 (load side), port_b = 2, pilot port port_p:

        x_v = (A_r/K) [p_1 - p_0 + R p_p - p_2 (R + 1)] - F_0/K,  0 <= x_v <= x_v_max
        q = q(b x_v, p_1 - p_2)   for p_1 > p_2   (pilot-opened flow 1 -> 2)
        q = q(A_ch, p_1 - p_2)    for p_1 < p_2   (check valve, free flow 2 -> 1)

    with A_r = A - A_p, R = A_p/A_r (4.58) and the regularized orifice (4.13).  The
    spring preload F_0 (0 in (4.59)) sets the load pressure the valve holds.
    """

    port_p = FluidPort()
    A = ac.Parameter(2e-4, unit="m2", min=0, description="spool area on the p_2 side")
    A_p = ac.Parameter(1.5e-4, unit="m2", min=0, description="pilot area")
    K = ac.Parameter(1e5, unit="N/m", min=0, description="spring stiffness")
    F_0 = ac.Parameter(0.0, unit="N", min=0, description="spring preload")
    p_0 = ac.Parameter(0.0, unit="Pa", description="spring chamber pressure")
    x_v_max = ac.Parameter(2e-3, unit="m", min=0, description="spool stroke")
    b = ac.Parameter(0.01, unit="m", min=0, description="area gradient")
    A_ch = ac.Parameter(1e-4, unit="m2", min=0, description="check valve area")
    x_v = ac.Variable(start=0.0, unit="m", nominal=1e-3, description="spool opening")

    def loss_power(self):
        """dp q (the pilot port takes no flow)."""
        return self.dp * self.q + self.port_p.p * self.port_p.q

    def equations(self):
        A_r = self.A - self.A_p
        R = self.A_p / A_r
        p1, p2 = self.port_a.p, self.port_b.p
        free = (A_r * (p1 - self.p_0 + R * self.port_p.p - p2 * (R + 1)) - self.F_0) / self.K
        clipped = ac.if_else(free < 0, 0, ac.if_else(free > self.x_v_max, self.x_v_max, free))
        law = ac.if_else(self.dp > 0, self._orifice(self.b * self.x_v, self.dp),
                         self._orifice(self.A_ch, self.dp))
        return [ac.Eq(self.port_p.q, 0), ac.Eq(self.x_v, clipped),
                ac.Eq(self.q, law)]
