"""Gas volumes: a fixed plenum and a pneumatic cylinder chamber (Egeland & Gravdahl
14.4.5, (14.97)-(14.99); the chamber equation is that of the hydraulic volume (4.64) with
the gas's bulk modulus n p)."""
import acausal as ac
from acausal.ports import TranslationalFlange

from .interfaces import PartialOnePort, polytropic_density

__all__ = ["GasVolume", "PneumaticCylinder"]

_KAPPA = 1.4   # ratio of specific heats of air, Egeland & Gravdahl 14.4.5


class _PolytropicGas(PartialOnePort):
    """The gas data of a chamber: the polytrope p/rho^n = p_0/rho_0^n."""

    n = ac.Parameter(_KAPPA, min=1, description="polytropic exponent: 1 isothermal, "
                                                "kappa adiabatic (isentropic)")
    p_0 = ac.Parameter(1e5, unit="Pa", min=0, description="reference pressure on the polytrope")
    rho_0 = ac.Parameter(1.2, unit="kg/m3", min=0,
                         description="gas density at the reference pressure")
    p = ac.Variable(start=1e5, unit="Pa", nominal=1e5, state_select="prefer",
                    description="pressure in the chamber")
    rho = ac.Variable(start=1.2, unit="kg/m3", description="gas density in the chamber")
    m = ac.Variable(unit="kg", nominal=1e-3, description="gas mass in the chamber")

    def _chamber(self, V, dV):
        """rho = rho_0 (p/p_0)^(1/n),  m = rho V,
        der(p) = (n p / (rho V)) (port.m_flow - rho der(V))."""
        return [ac.Eq(self.p, self.port.p),
                ac.Eq(self.rho, polytropic_density(self.p, self.n, self.p_0, self.rho_0)),
                ac.Eq(self.m, self.rho * V),
                ac.Eq(ac.der(self.p), self.n * self.p / (self.rho * V)
                      * (self.port.m_flow - self.rho * dV))]


class GasVolume(_PolytropicGas):
    """Fixed volume of gas, a plenum or a receiver (mass balance d(rho V)/dt = m_flow on
    the polytrope p/rho^n = const, (14.98)):

        (V / (n p)) der(p) = port.m_flow / rho,    rho = rho_0 (p/p_0)^(1/n)

    the hydraulic capacitance (4.64) with the bulk modulus of the gas, n p (kappa p
    adiabatic, p isothermal).  port.m_flow is the net mass flow into the volume.
    """

    V = ac.Parameter(1e-3, unit="m3", min=0, description="volume")

    def equations(self):
        return self._chamber(self.V, 0)


class PneumaticCylinder(_PolytropicGas):
    """Gas chamber closed by a piston of area A at flange.s, a pneumatic cylinder or
    spring (Egeland & Gravdahl 14.4.5, (14.97)-(14.99)):

        V = V_0 + A flange.s
        (V / (n p)) der(p) + der(V) = port.m_flow / rho,    rho = rho_0 (p/p_0)^(1/n)
        flange.f = -A p

    The pressure pushes the piston in +s with A p (p absolute, as in (14.99): put a
    ``ConstantForce`` on the flange for the ambient pressure on the other side).  With
    the port unconnected the gas mass is constant and p V^n = const, the isentropic
    spring p = p_0 (x_0/x)^kappa of (14.98) for V_0 = 0, n = kappa.
    """

    flange = TranslationalFlange()
    A = ac.Parameter(1e-2, unit="m2", min=0, description="piston area")
    V_0 = ac.Parameter(0.0, unit="m3", min=0, description="volume at flange.s = 0")
    V = ac.Variable(unit="m3", description="current volume")

    def equations(self):
        return [ac.Eq(self.V, self.V_0 + self.A * self.flange.s),
                # der(V) as A der(s): the piston position, not the volume, is the state
                *self._chamber(self.V, self.A * ac.der(self.flange.s)),
                ac.Eq(self.flange.f, -self.A * self.p)]
