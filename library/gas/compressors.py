"""The Moore-Greitzer compression system (Egeland & Gravdahl 14.1.2, (14.1)-(14.4);
Moore & Greitzer 1986), in its normalized variables: an axial compressor with its duct,
a plenum, and a throttle for the turbine.

A ``NormalizedGasPort`` carries the pressure coefficient psi (a pressure rise over the
inlet's, divided by rho U^2) and the flow coefficient phi (axial velocity over the rotor
speed U).  Time is the normalized time of the model, U t / R (R the mean rotor radius),
which the book's equations are written in.  With the inlet at psi = 0 (``Ambient``), the
three components connected as ambient -> compressor -> plenum -> throttle -> ambient give
(14.1)-(14.3) with Psi the plenum's psi and Phi the compressor's phi.
"""
import acausal as ac
from acausal.ports import NormalizedGasPort

from .interfaces import signed_sqrt

__all__ = ["MooreGreitzerCompressor", "Plenum", "CompressorThrottle", "Ambient"]

_PSI_REG = 1e-6   # of the throttle's square root; Psi > 0.15 in the book's runs


class MooreGreitzerCompressor(ac.Component):
    """Axial compressor with its inlet and exit ducts, the cubic characteristic and the
    rotating-stall amplitude J (Egeland & Gravdahl (14.2)-(14.3)):

        phi = port_a.phi,   0 = port_a.phi + port_b.phi
        psi_c(phi, J) = psi_c0 + H [1 + (3/2)(phi/W - 1)(1 - J/2) - (1/2)(phi/W - 1)^3]
        l_c der(phi) = psi_c(phi, J) - (port_b.psi - port_a.psi)
        der(J) = sigma J [1 - (phi/W - 1)^2 - J/4]

    phi flows from port_a (inlet) to port_b (delivery).  J is the squared amplitude of
    the rotating stall cell; with J = 0 psi_c is the axisymmetric cubic characteristic,
    psi_c(0) = psi_c0 at shut-off and its peak psi_c0 + 2 H is at phi = 2 W.  J = 0 is kept by
    the equations (an invariant): start J > 0 to let stall grow.
    """

    port_a = NormalizedGasPort()
    port_b = NormalizedGasPort()
    H = ac.Parameter(0.18, min=0, description="semi-height of the cubic characteristic")
    W = ac.Parameter(0.25, min=0, description="semi-width of the cubic characteristic")
    psi_c0 = ac.Parameter(0.30, description="shut-off value of the characteristic")
    sigma = ac.Parameter(0.38, min=0, description="stall growth coefficient")
    l_c = ac.Parameter(2.0, min=0,
                       description="effective length of compressor and ducts (over R)")
    phi = ac.Variable(start=0.6, state_select="prefer",
                      description="flow coefficient through the compressor")
    J = ac.Variable(start=0.1, min=0, state_select="prefer",
                    description="squared rotating stall amplitude")
    psi_c = ac.Variable(start=0.6, description="pressure rise of the compressor")

    def characteristic(self, phi, J):
        """psi_c(phi, J) of (14.2)."""
        m = phi / self.W - 1
        return self.psi_c0 + self.H * (1 + _flow_terms(m, J))

    def equations(self):
        m = self.phi / self.W - 1
        return [ac.Eq(self.phi, self.port_a.phi),
                ac.Eq(0, self.port_a.phi + self.port_b.phi),
                ac.Eq(self.psi_c, self.characteristic(self.phi, self.J)),
                ac.Eq(self.l_c * ac.der(self.phi),
                      self.psi_c - (self.port_b.psi - self.port_a.psi)),
                ac.Eq(ac.der(self.J), self.sigma * self.J * (1 - m**2 - self.J / 4))]


def _flow_terms(m, J):
    """(3/2) m (1 - J/2) - (1/2) m^3, the flow-dependent part of psi_c / H."""
    return 3 * m * (1 - J / 2) / 2 - m**3 / 2


class Plenum(ac.Component):
    """Plenum (the combustion chamber of a jet engine), a gas volume in normalized
    variables (Egeland & Gravdahl (14.1)):

        psi = port.psi,   4 B^2 l_c der(psi) = port.phi

    port.phi is the net flow into the plenum.  B = (U/(2c)) sqrt(V_p/(A_c L_c)) (14.4) is
    Greitzer's parameter.  The product 4 B^2 l_c = (U/c)^2 V_p/(A_c R) belongs to the
    plenum alone, but the book gives B, which is defined with the compressor's duct
    length: give the plenum the compressor's l_c.  B = 0 is the limit of a plenum
    without storage (flow in = flow out).
    """

    port = NormalizedGasPort()
    B = ac.Parameter(1.0, min=0, description="Greitzer's B parameter (14.4)")
    l_c = ac.Parameter(2.0, min=0,
                       description="effective length of compressor and ducts (over R)")
    psi = ac.Variable(start=0.6, state_select="prefer",
                      description="plenum pressure coefficient")

    def equations(self):
        return [ac.Eq(self.psi, self.port.psi),
                ac.Eq(4 * self.B**2 * self.l_c * ac.der(self.psi), self.port.phi)]


class CompressorThrottle(ac.Component):
    """Throttle (the turbine of the jet engine) between port_a and port_b
    (Egeland & Gravdahl (14.1)):

        phi = port_a.phi = -port_b.phi = gamma_T sqrt(port_a.psi - port_b.psi)

    written gamma_T dpsi (dpsi^2 + 1e-12)^(-1/4): odd in dpsi (reverse flow through the
    throttle is not meant, the law only stays finite there), relative error
    1e-12/(4 dpsi^2), below 1.2e-11 at the pressure rises of the book's runs (dpsi > 0.15).
    """

    port_a = NormalizedGasPort()
    port_b = NormalizedGasPort()
    gamma_T = ac.Parameter(0.5, min=0, description="throttle coefficient (opening)")
    phi = ac.Variable(start=0.0, description="flow coefficient through the throttle")
    dpsi = ac.Variable(start=0.0, description="pressure drop a -> b")

    def equations(self):
        return [ac.Eq(self.dpsi, self.port_a.psi - self.port_b.psi),
                ac.Eq(self.phi, self.port_a.phi),
                ac.Eq(0, self.port_a.phi + self.port_b.phi),
                ac.Eq(self.phi, self.gamma_T * signed_sqrt(self.dpsi, _PSI_REG))]


class Ambient(ac.Component):
    """The surroundings, the reference of the pressure coefficient:  port.psi = psi."""

    port = NormalizedGasPort()
    psi = ac.Parameter(0.0, description="pressure coefficient of the surroundings")

    energy_role = "source"  # the atmosphere outside the model

    def equations(self):
        return [ac.Eq(self.port.psi, self.psi)]
