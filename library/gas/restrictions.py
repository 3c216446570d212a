"""Gas restrictions: a throttle (orifice) and a laminar restriction."""
import acausal as ac

from .interfaces import PartialTwoPort, signed_sqrt

__all__ = ["Throttle", "LaminarThrottle"]

_DP_REG = 1.0    # Pa: the regularization of the square root, below any pressure drop meant


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
        return [*super().equations(),
                ac.Eq(self.m_flow, self.C_d * self.A * (2 * self.rho)**0.5
                      * signed_sqrt(self.dp, _DP_REG))]


class LaminarThrottle(PartialTwoPort):
    """Laminar restriction (a capillary, a porous plug):  m_flow = G dp."""

    G = ac.Parameter(1e-7, unit="kg/(s.Pa)", min=0, description="mass flow conductance")

    def equations(self):
        return [*super().equations(), ac.Eq(self.m_flow, self.G * self.dp)]
