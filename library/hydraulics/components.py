"""Hydraulic components (Egeland & Gravdahl ch. 4): volumes, orifices, motors, pumps,
cylinders.  Valves are in ``valves``, transmission lines in ``lines``."""

import acausal as ac
from acausal.ports import FluidPort, RealInput, RotationalFlange, TranslationalFlange

from .interfaces import PartialOnePort, PartialTwoPort, orifice_flow

__all__ = ["Volume", "PistonVolume", "LaminarOrifice", "TurbulentOrifice", "VariableOrifice",
           "ReliefValve",
           "HydraulicMotor", "Pump", "VariablePump", "Cylinder", "SingleActingCylinder"]

_BETA = 7e8   # bulk modulus of oil, Egeland & Gravdahl 4.3.1


class Volume(PartialOnePort):
    """Hydraulic capacitance, a fixed volume of compressible oil (Egeland & Gravdahl
    4.3.1, (4.64) with dV/dt = 0):

        (V / beta) der(p) = port.q

    port.q is the net flow into the volume (q_in - q_out of all that is connected).
    Stored energy W_p = V p^2 / (2 beta)  (4.66).
    """

    V = ac.Parameter(1e-3, unit="m3", min=0, description="volume")
    beta = ac.Parameter(_BETA, unit="Pa", min=0, description="bulk modulus")
    p = ac.Variable(start=0.0, unit="Pa", nominal=1e6, state_select="prefer",
                    description="pressure in the volume")

    def stored_energy(self):
        """W_p = V p^2 / (2 beta)  (Egeland & Gravdahl (4.66))."""
        return self.V * self.p**2 / (2 * self.beta)

    def equations(self):
        return [ac.Eq(self.p, self.port.p),
                ac.Eq(self.V / self.beta * ac.der(self.p), self.port.q)]


class PistonVolume(PartialOnePort):
    """Volume with a moving boundary: a piston of area A at flange.s
    (Egeland & Gravdahl (4.64)):

        V = V0 + A flange.s,   (V / beta) der(p) + der(V) = port.q,   flange.f = -A p

    The pressure pushes the piston in +s (the flange is driven like by a force source).
    """

    flange = TranslationalFlange()
    V0 = ac.Parameter(1e-3, unit="m3", min=0, description="volume at flange.s = 0")
    A = ac.Parameter(1e-3, unit="m2", min=0, description="piston area")
    beta = ac.Parameter(_BETA, unit="Pa", min=0, description="bulk modulus")
    p = ac.Variable(start=0.0, unit="Pa", nominal=1e6, state_select="prefer",
                    description="pressure in the volume")
    V = ac.Variable(unit="m3", description="current volume")

    def stored_energy(self):
        """V p^2 / (2 beta)  (Egeland & Gravdahl (4.66) at the current volume)."""
        return self.V * self.p**2 / (2 * self.beta)

    def created_power(self):
        """p^2 der(V) / (2 beta): the constant-beta chamber with a moving boundary,
        (V/beta) der(p) = q - der(V), has no exact energy function: with
        W = V p^2/(2 beta), dW/dt exceeds the power into its ports by this much (a
        fraction p/(2 beta) of the piston power)."""
        return self.p**2 * ac.der(self.V) / (2 * self.beta)

    def equations(self):
        return [ac.Eq(self.p, self.port.p),
                ac.Eq(self.V, self.V0 + self.A * self.flange.s),
                ac.Eq(ac.der(self.p), self.beta / self.V * (self.port.q - ac.der(self.V))),
                ac.Eq(self.flange.f, -self.A * self.p)]


class LaminarOrifice(PartialTwoPort):
    """Laminar restriction (Egeland & Gravdahl (4.3)):  q = C_l dp."""

    C_l = ac.Parameter(1e-11, unit="m3/(s.Pa)", min=0, description="laminar flow coefficient")

    def loss_power(self):
        """dp q >= 0: a restriction only throttles."""
        return self.dp * self.q

    def equations(self):
        return [ac.Eq(self.q, self.C_l * self.dp)]


class _RegularizedOrifice(PartialTwoPort):
    """Fluid data of the regularized orifice law (4.13): the book's oil by default."""

    C_d = ac.Parameter(0.6, min=0, description="discharge coefficient")
    rho = ac.Parameter(900.0, unit="kg/m3", min=0, description="oil density")
    nu = ac.Parameter(30e-6, unit="m2/s", min=0, description="kinematic viscosity")
    Re_tr = ac.Parameter(1000.0, min=0, description="transition Reynolds number")

    def loss_power(self):
        """dp q >= 0: a restriction only throttles."""
        return self.dp * self.q

    def _law(self, A):
        return orifice_flow(A, self.dp, self.C_d, self.rho, self.nu, self.Re_tr)


class TurbulentOrifice(_RegularizedOrifice):
    """Orifice of area A, turbulent flow (4.1) regularized to laminar flow at small
    Reynolds numbers (Egeland & Gravdahl 4.2.3, (4.13) with F_tr of (4.42)):

        q = C_d A sqrt(2 |dp| / rho) sign(dp)                for |A dp| >= F_tr
        q = (3 nu Re_tr/4) (sqrt(pi)/2) sqrt(A) x (3 - |x|),  x = A dp / F_tr, otherwise

    Defaults are the book's oil data: Re_tr = 1000, rho = 900 kg/m3, nu = 30 cSt,
    C_d = 0.6.
    """

    A = ac.Parameter(1e-5, unit="m2", min=0, description="orifice area")

    def equations(self):
        return [ac.Eq(self.q, self._law(self.A))]


class VariableOrifice(_RegularizedOrifice):
    """``TurbulentOrifice`` whose area is a signal, A = max(A_in, 0): a valve that opens
    and closes (e.g. the fast closure of Egeland & Gravdahl 11.2.10)."""

    A_in = RealInput()

    def equations(self):
        A = ac.if_else(self.A_in > 0, self.A_in, 0)
        return [ac.Eq(self.q, self._law(A))]


class ReliefValve(PartialTwoPort):
    """Direct pressure relief valve, static, with a linear opening characteristic:

        q = G_open (dp - p_crack) + G_closed dp   for dp > p_crack
        q = G_closed dp                            otherwise

    G_closed is the leakage of the closed valve.  The crack point is an event.
    """

    p_crack = ac.Parameter(1e7, unit="Pa", description="cracking pressure drop")
    G_open = ac.Parameter(1e-10, unit="m3/(s.Pa)", min=0,
                          description="flow gain above the cracking pressure")
    G_closed = ac.Parameter(1e-14, unit="m3/(s.Pa)", min=0, description="leakage when closed")

    def loss_power(self):
        """dp q >= 0: a restriction only throttles."""
        return self.dp * self.q

    def equations(self):
        opening = ac.if_else(self.dp > self.p_crack, self.G_open * (self.dp - self.p_crack), 0)
        return [ac.Eq(self.q, opening + self.G_closed * self.dp)]


class _DisplacementMachine(ac.Component):
    """Rotary displacement machine, motor or pump (Egeland & Gravdahl 4.3.2, (4.67)-(4.75)
    without the chamber volumes, which are separate ``Volume`` components):

        w = der(flange.phi)
        port_a.q = D w + C_i (p_a - p_b) + C_e p_a
        port_b.q = -D w - C_i (p_a - p_b) + C_e p_b
        flange.tau = -D (p_a - p_b)

    The fluid drives the shaft with T = D (p_a - p_b) (4.71); q_a - D w is the leakage,
    internal (C_i, a -> b) and external (C_e, to a drain at zero pressure).  A positive w
    moves D w from port_a to port_b: a motor for p_a > p_b, a pump for p_b > p_a.
    """

    port_a = FluidPort()
    port_b = FluidPort()
    flange = RotationalFlange()
    C_i = ac.Parameter(0.0, unit="m3/(s.Pa)", min=0, description="internal leakage coefficient")
    C_e = ac.Parameter(0.0, unit="m3/(s.Pa)", min=0, description="external leakage coefficient")
    w = ac.Variable(start=0.0, unit="rad/s", description="shaft speed")
    tau = ac.Variable(unit="N.m", description="torque from the fluid on the shaft")

    def loss_power(self):
        """The leakage, C_i (p_a - p_b)^2 + C_e (p_a^2 + p_b^2): the ideal machine
        converts D (p_a - p_b) w without loss."""
        pa, pb = self.port_a.p, self.port_b.p
        return self.C_i * (pa - pb)**2 + self.C_e * (pa**2 + pb**2)

    def displacement(self):
        raise NotImplementedError

    def equations(self):
        D, pa, pb = self.displacement(), self.port_a.p, self.port_b.p
        return [ac.Eq(self.w, ac.der(self.flange.phi)),
                ac.Eq(self.port_a.q, D * self.w + self.C_i * (pa - pb) + self.C_e * pa),
                ac.Eq(self.port_b.q, -D * self.w - self.C_i * (pa - pb) + self.C_e * pb),
                ac.Eq(self.tau, D * (pa - pb)),
                ac.Eq(self.flange.tau, -self.tau)]


class HydraulicMotor(_DisplacementMachine):
    """Rotary hydraulic motor, displacement D_m (Egeland & Gravdahl 4.3.2):

        port_a.q = D_m w + C_im (p_a - p_b) + C_em p_a,   T = D_m (p_a - p_b)

    (see ``_DisplacementMachine``).  The rotor inertia J_t and viscous friction B_m of
    (4.75) are an ``Inertia`` and a ``Damper`` on the flange; the chamber volumes of
    (4.73)-(4.74) are ``Volume`` components on the ports.
    """

    D_m = ac.Parameter(1e-5, unit="m3/rad", min=0, description="motor displacement")

    def displacement(self):
        return self.D_m


class Pump(_DisplacementMachine):
    """Fixed-displacement pump driven by its flange; sucks from port_a, delivers at
    port_b:  port_b.q = -(D_p w - leakage),  the drive supplies D_p (p_b - p_a)."""

    D_p = ac.Parameter(1e-5, unit="m3/rad", min=0, description="pump displacement")

    def displacement(self):
        return self.D_p


class VariablePump(_DisplacementMachine):
    """Variable-displacement pump (Egeland & Gravdahl 4.4.5): D = phi_p D_max with the
    swash-plate signal phi_p in [-1, 1] (a negative phi_p reverses the flow)."""

    D_max = ac.Parameter(1e-5, unit="m3/rad", min=0, description="maximum displacement")
    phi_p = RealInput()

    def displacement(self):
        return self.phi_p * self.D_max


class Cylinder(ac.Component):
    """Double-acting cylinder with its two chambers (Egeland & Gravdahl 4.3.4,
    (4.83)-(4.85) without the load mass, which is a ``Mass`` on the flange):

        x = flange.s
        ((V_a0 + A_a x)/beta) der(p_a) = port_a.q - A_a der(x) - C_i (p_a - p_b) - C_e p_a
        ((V_b0 - A_b x)/beta) der(p_b) = port_b.q + A_b der(x) + C_i (p_a - p_b) - C_e p_b
        flange.f = -(A_a p_a - A_b p_b)

    A symmetric cylinder has A_a = A_b = A_p - A_r (4.81), a single-rod one A_a = A_p,
    A_b = A_p - A_r (4.82).  The force A_a p_a - A_b p_b pushes the rod in +x.  The
    chamber equations are written solved for der(p): in the form above their
    coefficient V/beta (~1e-13) looks singular to the solver's pivot test.
    """

    port_a = FluidPort()
    port_b = FluidPort()
    flange = TranslationalFlange()
    A_a = ac.Parameter(1e-3, unit="m2", min=0, description="piston area, chamber a")
    A_b = ac.Parameter(1e-3, unit="m2", min=0, description="piston area, chamber b")
    V_a0 = ac.Parameter(1e-4, unit="m3", min=0, description="volume of chamber a at x = 0")
    V_b0 = ac.Parameter(1e-4, unit="m3", min=0, description="volume of chamber b at x = 0")
    beta = ac.Parameter(_BETA, unit="Pa", min=0, description="bulk modulus")
    C_i = ac.Parameter(0.0, unit="m3/(s.Pa)", min=0, description="internal leakage coefficient")
    C_e = ac.Parameter(0.0, unit="m3/(s.Pa)", min=0, description="external leakage coefficient")
    x = ac.Variable(start=0.0, unit="m", description="piston position")
    v = ac.Variable(start=0.0, unit="m/s", description="piston speed")
    p_a = ac.Variable(start=0.0, unit="Pa", nominal=1e6, state_select="prefer",
                      description="pressure in chamber a")
    p_b = ac.Variable(start=0.0, unit="Pa", nominal=1e6, state_select="prefer",
                      description="pressure in chamber b")

    def stored_energy(self):
        """(V_a p_a^2 + V_b p_b^2) / (2 beta) at the current chamber volumes."""
        Va, Vb = self.V_a0 + self.A_a * self.x, self.V_b0 - self.A_b * self.x
        return (Va * self.p_a**2 + Vb * self.p_b**2) / (2 * self.beta)

    def loss_power(self):
        """Leakage C_i (p_a - p_b)^2 + C_e (p_a^2 + p_b^2)."""
        pa, pb = self.p_a, self.p_b
        return self.C_i * (pa - pb)**2 + self.C_e * (pa**2 + pb**2)

    def created_power(self):
        """p^2 der(V)/(2 beta) of each chamber (see ``PistonVolume.created_power``)."""
        return (self.A_a * self.p_a**2 - self.A_b * self.p_b**2) * self.v / (2 * self.beta)

    def equations(self):
        pa, pb, leak = self.p_a, self.p_b, self.C_i * (self.p_a - self.p_b)
        return [ac.Eq(self.x, self.flange.s), ac.Eq(self.v, ac.der(self.x)),
                ac.Eq(pa, self.port_a.p), ac.Eq(pb, self.port_b.p),
                ac.Eq(ac.der(pa), self.beta / (self.V_a0 + self.A_a * self.x)
                      * (self.port_a.q - self.A_a * self.v - leak - self.C_e * pa)),
                ac.Eq(ac.der(pb), self.beta / (self.V_b0 - self.A_b * self.x)
                      * (self.port_b.q + self.A_b * self.v + leak - self.C_e * pb)),
                ac.Eq(self.flange.f, -(self.A_a * pa - self.A_b * pb))]


class SingleActingCylinder(ac.Component):
    """Single-acting cylinder, one chamber (Egeland & Gravdahl (4.83) with the rod side
    vented):

        ((V_0 + A x)/beta) der(p) = port.q - A der(x) - C_e p,   flange.f = -A p
    """

    port = FluidPort()
    flange = TranslationalFlange()
    A = ac.Parameter(1e-3, unit="m2", min=0, description="piston area")
    V_0 = ac.Parameter(1e-4, unit="m3", min=0, description="chamber volume at x = 0")
    beta = ac.Parameter(_BETA, unit="Pa", min=0, description="bulk modulus")
    C_e = ac.Parameter(0.0, unit="m3/(s.Pa)", min=0, description="leakage coefficient")
    x = ac.Variable(start=0.0, unit="m", description="piston position")
    v = ac.Variable(start=0.0, unit="m/s", description="piston speed")
    p = ac.Variable(start=0.0, unit="Pa", nominal=1e6, state_select="prefer",
                    description="chamber pressure")

    def stored_energy(self):
        """(V_0 + A x) p^2 / (2 beta)."""
        return (self.V_0 + self.A * self.x) * self.p**2 / (2 * self.beta)

    def loss_power(self):
        """Leakage C_e p^2."""
        return self.C_e * self.p**2

    def created_power(self):
        """p^2 der(V)/(2 beta) (see ``PistonVolume.created_power``)."""
        return self.A * self.p**2 * self.v / (2 * self.beta)

    def equations(self):
        return [ac.Eq(self.x, self.flange.s), ac.Eq(self.v, ac.der(self.x)),
                ac.Eq(self.p, self.port.p),
                ac.Eq(ac.der(self.p), self.beta / (self.V_0 + self.A * self.x)
                      * (self.port.q - self.A * self.v - self.C_e * self.p)),
                ac.Eq(self.flange.f, -self.A * self.p)]
