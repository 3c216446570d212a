"""Partial models of gas components, and the gas laws they share.

A ``GasPort`` carries the pressure p [Pa] (across) and the mass flow m_flow [kg/s]
(through, positive into the component).  The gas in a volume follows a polytrope through
a reference state (p_0, rho_0):

    p / rho^n = p_0 / rho_0^n,    rho = rho_0 (p / p_0)^(1/n)

with n = 1 for an isothermal gas (rho = p/(R T), p_0/rho_0 = R T) and n = kappa for an
isentropic one (Egeland & Gravdahl (14.98): p = p_0 (rho/rho_0)^kappa).
"""
from acausal._sympy import sympy as sp

import acausal as ac
from acausal.ports import GasPort

__all__ = ["PartialOnePort", "PartialTwoPort", "polytropic_density", "signed_sqrt"]


class PartialOnePort(ac.Component):
    """One gas port, named port."""

    port = GasPort()


class PartialTwoPort(ac.Component):
    """A restriction between port_a and port_b (throttle, valve):

        dp = port_a.p - port_b.p,   m_flow = port_a.m_flow,   0 = port_a.m_flow + port_b.m_flow

    m_flow flows from port_a to port_b through the element: a restriction stores no mass.
    """

    port_a = GasPort()
    port_b = GasPort()
    dp = ac.Variable(start=0.0, unit="Pa", nominal=1e5, description="pressure drop a -> b")
    m_flow = ac.Variable(start=0.0, unit="kg/s", nominal=1e-2, description="mass flow a -> b")

    def equations(self):
        return [ac.Eq(self.dp, self.port_a.p - self.port_b.p),
                ac.Eq(self.m_flow, self.port_a.m_flow),
                ac.Eq(0, self.port_a.m_flow + self.port_b.m_flow)]


def polytropic_density(p, n, p_0, rho_0):
    """rho = rho_0 (p/p_0)^(1/n): the density on the polytrope through (p_0, rho_0)."""
    return rho_0 * (p / p_0)**(1 / n)


def signed_sqrt(x, x_reg):
    """sign(x) sqrt(|x|), written x (x^2 + x_reg^2)^(-1/4): odd, smooth, with a finite
    slope 1/sqrt(x_reg) at x = 0; its relative error is below x_reg^2/(4 x^2), so choose
    x_reg far below the values of x that matter.  (No sp.Abs: it would be differentiated
    into re()/im().)"""
    return x * (x**2 + x_reg**2)**sp.Rational(-1, 4)
