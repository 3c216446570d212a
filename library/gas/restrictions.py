"""Gas restrictions: an orifice at small pressure drops, a compressible (choking) one,
and a laminar restriction."""
import acausal as ac

from .interfaces import PartialTwoPort, signed_sqrt

__all__ = ["Throttle", "CompressibleThrottle", "LaminarThrottle"]

_DP_REG = 1.0    # Pa: the regularization of the square root, below any pressure drop meant
_X_REG = 1e-9    # of 1 - r^((kappa-1)/kappa): a pressure drop of ~1e-4 Pa at 1 bar


class Throttle(PartialTwoPort):
    """Orifice of area A with the turbulent (Bernoulli) law for a gas at pressure drops
    small against the pressure, the gas density rho taken as constant (Egeland &
    Gravdahl (4.1) in mass flow):

        m_flow = C_d A sqrt(2 rho |dp|) sign(dp)

    written as C_d A sqrt(2 rho) dp (dp^2 + dp_r^2)^(-1/4) with dp_r = 1 Pa, so the slope
    at dp = 0 is finite (relative error below dp_r^2/(4 dp^2)).  It does not choke: at
    pressure ratios below about 0.53 the real mass flow no longer grows with dp.
    """

    A = ac.Parameter(1e-5, unit="m2", min=0, description="orifice area")
    C_d = ac.Parameter(0.6, min=0, description="discharge coefficient")
    rho = ac.Parameter(1.2, unit="kg/m3", min=0, description="gas density in the orifice")

    def equations(self):
        return [ac.Eq(self.m_flow, self.C_d * self.A * (2 * self.rho)**0.5
                      * signed_sqrt(self.dp, _DP_REG))]


class CompressibleThrottle(PartialTwoPort):
    """Orifice of area A with isentropic flow of an ideal gas to the throat (the
    Saint-Venant-Wantzel law), choked below the critical pressure ratio:

        p_u, p_d = upstream and downstream pressure,  r = p_d / p_u
        r_c = (2/(kappa + 1))^(kappa/(kappa - 1))                 (0.528 for air)
        m_flow = C_d A p_u sqrt(2 kappa / ((kappa - 1) R T)) psi(max(r, r_c))
        psi(r) = r^(1/kappa) sqrt(1 - r^((kappa-1)/kappa))

    signed by the direction of the flow (port_a -> port_b for p_a > p_b).  psi is
    largest at r_c, so the mass flow is continuous with a continuous slope at the
    choking point, where it no longer depends on the downstream pressure.  The gas
    arrives at the temperature T (that of the supply, or of an isothermal chamber).
    The square root is regularized like ``signed_sqrt`` below 1 - r^(...) = 1e-9 (a
    pressure drop of about 1e-4 Pa at 1 bar), so the slope at dp = 0 is finite; for
    1 - r small the law tends to ``Throttle``'s C_d A sqrt(2 rho_u dp),
    rho_u = p_u/(R T).  The direction and the choking are events.
    """

    A = ac.Parameter(1e-6, unit="m2", min=0, description="orifice area")
    C_d = ac.Parameter(0.6, min=0, description="discharge coefficient")
    kappa = ac.Parameter(1.4, min=1, description="ratio of specific heats")
    R = ac.Parameter(287.0, unit="J/(kg.K)", min=0, description="specific gas constant")
    T = ac.Parameter(293.15, unit="K", min=0, description="temperature of the gas arriving")

    def _psi(self, r):
        k = self.kappa
        return r**(1 / k) * signed_sqrt(1 - r**((k - 1) / k), _X_REG)

    def equations(self):
        k = self.kappa
        forward = self.dp >= 0
        p_u = ac.if_else(forward, self.port_a.p, self.port_b.p)
        p_d = ac.if_else(forward, self.port_b.p, self.port_a.p)
        r = p_d / p_u
        r_c = (2 / (k + 1))**(k / (k - 1))
        psi = ac.if_else(r > r_c, self._psi(r), self._psi(r_c))
        m_flow = (self.C_d * self.A * p_u * (2 * k / ((k - 1) * self.R * self.T))**0.5 * psi)
        return [ac.Eq(self.m_flow, ac.if_else(forward, m_flow, -m_flow))]


class LaminarThrottle(PartialTwoPort):
    """Laminar restriction (a capillary, a porous plug):  m_flow = G dp."""

    G = ac.Parameter(1e-7, unit="kg/(s.Pa)", min=0, description="mass flow conductance")

    def equations(self):
        return [ac.Eq(self.m_flow, self.G * self.dp)]
