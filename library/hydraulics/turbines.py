"""Hydropower: a penstock (rigid water column) and an impulse turbine with its nozzle
(Egeland & Gravdahl 11.2.9, (11.101)-(11.114))."""
from acausal._sympy import sympy as sp

import acausal as ac
from acausal.ports import RealInput, RotationalFlange

from .interfaces import PartialTwoPort

__all__ = ["Penstock", "PeltonTurbine"]

_G = 9.81
_Q_REG = 1e-9    # m3/s: q |q| as q sqrt(q^2 + q_r^2), far below any flow meant


class Penstock(PartialTwoPort):
    """Pipe of length L and cross-section A_p falling by h from port_a to port_b, the
    water incompressible (Egeland & Gravdahl (11.110)):

        (rho L / A_p) der(q) = port_a.p - port_b.p + rho g h

    the momentum balance of the column, L rho der(q) = A_p (rho g h + p_a - p_b).  The
    book prints the gravity term as "m g h"; the force along the pipe is m g h / L =
    rho A_p g h.  Linearized, H_pq(s) = -dp_p/dq = rho L s / A_p (11.111).
    """

    L = ac.Parameter(300.0, unit="m", min=0, description="pipe length")
    A_p = ac.Parameter(1.0, unit="m2", min=0, description="pipe cross-section")
    h = ac.Parameter(100.0, unit="m", description="drop from port_a to port_b")
    rho = ac.Parameter(1000.0, unit="kg/m3", min=0, description="water density")
    g = ac.Parameter(_G, unit="m/s2", min=0, description="gravity")

    def stored_energy(self):
        """Kinetic energy of the column, (rho L / A_p) q^2 / 2."""
        return self.rho * self.L / self.A_p * self.q**2 / 2

    def equations(self):
        return [ac.Eq(self.rho * self.L / self.A_p * ac.der(self.q),
                      self.dp + self.rho * self.g * self.h)]


class PeltonTurbine(PartialTwoPort):
    """Nozzle of outlet area A (the control input) after a pipe of section A_p, and a
    Pelton wheel of radius r_t on flange (Egeland & Gravdahl (11.103), (11.106)):

        port_a.p - port_b.p = (rho/2) q |q| (1/A^2 - 1/A_p^2)     (Bernoulli, nozzle)
        T_t = 2 r_t rho q (q/A - r_t w),   w = der(flange.phi),   flange.tau = -T_t

    port_a is the nozzle's inlet, port_b the tailwater the jet discharges to (p = 0 in
    the book).  The gate A must stay above zero: a closed nozzle would stop a rigid
    column at once (use a ``LumpedLine`` and a ``VariableOrifice`` for a closure, as in
    the water hammer example).  (11.103) prints q_0^2/A_p^2 for the inlet velocity head; the
    linearization that follows it, with alpha = 1 - A_0^2/A_p^2, is that of q^2/A_p^2,
    as here.  Linearized at (A_0, q_0, w_0) with the pipe H_pq(s):

        dT_t/dA = (2 r_t rho q_0^2 / (gamma A_0^2))
                  (1 - gamma (A_0^2/(alpha rho q_0)) H_pq) / (1 + (A_0^2/(alpha rho q_0)) H_pq)
        beta = 2 - r_t w_0 A_0 / q_0,   gamma = 1 / (beta/alpha - 1)          (11.109)

    the zero in the right half-plane for a ``Penstock`` (11.113)-(11.114).  The bucket
    speed r_t w is half the jet speed at the most power: beta = 1.5, gamma = 2 for
    alpha = 1.
    """

    flange = RotationalFlange()
    A = RealInput()
    r_t = ac.Parameter(1.0, unit="m", min=0, description="wheel radius")
    A_p = ac.Parameter(1.0, unit="m2", min=0, description="nozzle inlet (pipe) section")
    rho = ac.Parameter(1000.0, unit="kg/m3", min=0, description="water density")
    w = ac.Variable(start=0.0, unit="rad/s", description="shaft speed")
    T_t = ac.Variable(start=0.0, unit="N.m", description="torque of the jet on the wheel")

    def equations(self):
        q = self.q
        q_abs_q = q * (q**2 + _Q_REG**2)**sp.Rational(1, 2)
        return [ac.Eq(self.dp, self.rho / 2 * q_abs_q * (1 / self.A**2 - 1 / self.A_p**2)),
                ac.Eq(self.w, ac.der(self.flange.phi)),
                ac.Eq(self.T_t, 2 * self.r_t * self.rho * q * (q / self.A - self.r_t * self.w)),
                ac.Eq(self.flange.tau, -self.T_t)]
