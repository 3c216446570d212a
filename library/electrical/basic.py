"""Basic electrical components (Modelica.Electrical.Analog.Basic)."""
from acausal._sympy import sympy as sp

import acausal as ac
from acausal.ports import HeatPort, Pin, RealInput

from .interfaces import ConditionalHeatPort, OnePort, TwoPort

__all__ = ["Ground", "Resistor", "Conductor", "Capacitor", "Inductor", "HeatingResistor",
           "VariableResistor", "VariableConductor", "VariableCapacitor", "VariableInductor",
           "Potentiometer", "Transformer", "Gyrator", "SaturatingInductor"]


class Ground(ac.Component):
    """Reference potential:  p.v = 0."""

    p = Pin()

    energy_role = "lossless"  # v = 0: takes no power

    def equations(self):
        return [ac.Eq(self.p.v, 0)]


class Resistor(OnePort):
    """Ideal linear resistor (Modelica.Electrical.Analog.Basic.Resistor, MSL v4.0.0),
    Ohm's law with a linear temperature coefficient:

        R_actual = R (1 + alpha (T_heatPort - T_ref)),   v = R_actual i

    Without the MSL's heat port (useHeatPort, not here yet) the device is at its
    reference temperature (the MSL's T = T_ref), so R_actual = R; T_ref and alpha act
    once the port is there.  The loss is declared by ``loss_power``.
    """

    R = ac.Parameter(1.0, unit="Ohm", description="resistance")
    T_ref = ac.Parameter(300.15, unit="K", min=0, description="reference temperature")
    alpha = ac.Parameter(0.0, unit="1/K",
                         description="temperature coefficient of resistance (R_actual = "
                                     "R (1 + alpha (T_heatPort - T_ref)))")

    def loss_power(self):
        """P_loss = R i^2 (to the environment; the audit checks it against v i)."""
        return self.R * self.i**2

    def equations(self):
        return [ac.Eq(self.v, self.R * self.i)]


class Conductor(OnePort):
    """Ideal linear conductor (Modelica.Electrical.Analog.Basic.Conductor, MSL v4.0.0)
    with a linear temperature coefficient:

        G_actual = G / (1 + alpha (T_heatPort - T_ref)),   i = G_actual v

    (at its reference temperature without the MSL's heat port, as :class:`Resistor`:
    G_actual = G).
    """

    G = ac.Parameter(1.0, unit="S", description="conductance at temperature T_ref")
    T_ref = ac.Parameter(300.15, unit="K", min=0, description="reference temperature")
    alpha = ac.Parameter(0.0, unit="1/K",
                         description="temperature coefficient of resistance (G_actual = "
                                     "G/(1 + alpha (T_heatPort - T_ref)))")

    def loss_power(self):
        """P_loss = G v^2 (the audit checks it against v i)."""
        return self.G * self.v**2

    def equations(self):
        return [ac.Eq(self.i, self.G * self.v)]


class Capacitor(OnePort):
    """Ideal linear capacitor (Modelica.Electrical.Analog.Basic.Capacitor):  i = C dv/dt."""

    C = ac.Parameter(1.0, unit="F", min=0, description="capacitance")
    v = ac.Variable(start=0.0, unit="V", description="voltage drop p.v - n.v")

    def stored_energy(self):
        """W = C v^2 / 2."""
        return self.C * self.v**2 / 2

    def equations(self):
        return [ac.Eq(self.C * ac.der(self.v), self.i)]


class Inductor(OnePort):
    """Ideal linear inductor (Modelica.Electrical.Analog.Basic.Inductor):  L di/dt = v."""

    L = ac.Parameter(1.0, unit="H", description="inductance")
    i = ac.Variable(start=0.0, unit="A", description="current from p to n")

    def stored_energy(self):
        """W = L i^2 / 2."""
        return self.L * self.i**2 / 2

    def equations(self):
        return [ac.Eq(self.L * ac.der(self.i), self.v)]


class HeatingResistor(OnePort):
    """Temperature-dependent resistor whose losses leave through a heat port:

        R = R_ref (1 + alpha (T - T_ref)),   v = R i,   heatPort.Q_flow = -v i

    (heatPort.Q_flow is positive into the resistor, so the dissipated power v i flows
    out into whatever the port is connected to; Modelica.Electrical.Analog.Basic.)
    """

    R_ref = ac.Parameter(1.0, unit="Ohm", description="resistance at T_ref")
    T_ref = ac.Parameter(300.15, unit="K", min=0, description="reference temperature")
    alpha = ac.Parameter(0.0, unit="1/K", description="temperature coefficient of R")
    heatPort = HeatPort()
    R = ac.Variable(unit="Ohm", description="resistance at the port temperature")

    energy_role = "lossless"  # v i leaves as heat through heatPort

    def equations(self):
        return [ac.Eq(self.R, self.R_ref * (1 + self.alpha * (self.heatPort.T - self.T_ref))),
                ac.Eq(self.v, self.R * self.i),
                ac.Eq(self.heatPort.Q_flow, -self.v * self.i)]


class VariableResistor(OnePort, ConditionalHeatPort):
    """Resistor whose resistance is a signal (Modelica.Electrical.Analog.Basic.
    VariableResistor, MSL v4.0.0), with a linear temperature coefficient:

        R_actual = R (1 + alpha (T_heatPort - T_ref)),   v = R_actual i,   LossPower = v i

    (R >= 0 for a passive resistor; T_heatPort is the fixed device temperature T, T_ref
    by default.)
    """

    T_ref = ac.Parameter(300.15, unit="K", min=0, description="reference temperature")
    alpha = ac.Parameter(0.0, unit="1/K",
                         description="temperature coefficient of resistance (R_actual = "
                                     "R (1 + alpha (T_heatPort - T_ref)))")
    T = ac.Parameter(lambda c: c.T_ref, unit="K", min=0,
                     description="fixed device temperature (no heat port)")
    R = RealInput()
    R_actual = ac.Variable(unit="Ohm",
                           description="actual resistance = R (1 + alpha (T_heatPort - T_ref))")

    def equations(self):
        return [ac.Eq(self.R_actual, self.R * (1 + self.alpha * (self.T_heatPort - self.T_ref))),
                ac.Eq(self.v, self.R_actual * self.i),
                ac.Eq(self.LossPower, self.v * self.i)]


class VariableConductor(OnePort, ConditionalHeatPort):
    """Conductor whose conductance is a signal (Modelica.Electrical.Analog.Basic.
    VariableConductor, MSL v4.0.0), with a linear temperature coefficient:

        G_actual = G / (1 + alpha (T_heatPort - T_ref)),   i = G_actual v,   LossPower = v i

    (G >= 0 for a passive conductor; T_heatPort is the fixed device temperature T.)
    """

    T_ref = ac.Parameter(300.15, unit="K", min=0, description="reference temperature")
    alpha = ac.Parameter(0.0, unit="1/K",
                         description="temperature coefficient of resistance (G_actual = "
                                     "G/(1 + alpha (T_heatPort - T_ref)))")
    T = ac.Parameter(lambda c: c.T_ref, unit="K", min=0,
                     description="fixed device temperature (no heat port)")
    G = RealInput()
    G_actual = ac.Variable(unit="S",
                           description="actual conductance = G/(1 + alpha (T_heatPort - T_ref))")

    def equations(self):
        return [ac.Eq(self.G_actual, self.G / (1 + self.alpha * (self.T_heatPort - self.T_ref))),
                ac.Eq(self.i, self.G_actual * self.v),
                ac.Eq(self.LossPower, self.v * self.i)]


class VariableCapacitor(OnePort):
    """Capacitor whose capacitance is a signal (MSL Analog.Basic.VariableCapacitor),
    charge balance form:

        Q = max(C, Cmin) v,   i = der(Q)

    The charge Q is the state, so a change of C at constant charge changes the voltage
    (a plate capacitor pulled apart).  Cmin keeps v = Q / C finite if C reaches 0.
    """

    C = RealInput()
    Cmin = ac.Parameter(1e-15, unit="F", min=0, description="lower bound of C")
    Q = ac.Variable(start=0.0, unit="C", description="charge on the p plate")

    def stored_energy(self):
        """W = Q v / 2 = Q^2 / (2 C)."""
        return self.Q * self.v / 2

    def created_power(self):
        """-v^2 der(C) / 2: the work of whatever changes C (dW/dt = v i - v^2 C'/2 at
        constant charge; the field pulls the plates together)."""
        return -self.v**2 * ac.der(self.C.signal) / 2

    def equations(self):
        return [ac.Eq(self.Q, ac.max(self.C.signal, self.Cmin) * self.v),
                ac.Eq(self.i, ac.der(self.Q))]


class VariableInductor(OnePort):
    """Inductor whose inductance is a signal (MSL Analog.Basic.VariableInductor),
    flux form:

        Psi = max(L, Lmin) i,   v = der(Psi)
    """

    L = RealInput()
    Lmin = ac.Parameter(1e-15, unit="H", description="lower bound of L")
    Psi = ac.Variable(start=0.0, unit="Wb", description="flux linkage")

    def stored_energy(self):
        """W = Psi i / 2 = Psi^2 / (2 L)."""
        return self.Psi * self.i / 2

    def created_power(self):
        """-i^2 der(L) / 2: the work of whatever changes L at constant flux."""
        return -self.i**2 * ac.der(self.L.signal) / 2

    def equations(self):
        return [ac.Eq(self.Psi, ac.max(self.L.signal, self.Lmin) * self.i),
                ac.Eq(self.v, ac.der(self.Psi))]


class Potentiometer(ac.Component):
    """Adjustable resistor with a sliding contact (MSL Analog.Basic.Potentiometer), the
    contact at r between pin_n (r = 0) and pin_p (r = 1):

        Rp = R (1 - r_c),   Rn = R r_c,   r_c = min(1, max(0, r))
        pin_p.v - contact.v = Rp pin_p.i,   pin_n.v - contact.v = Rn pin_n.i
        pin_p.i + pin_n.i + contact.i = 0

    r is the parameter rConstant, or with ``Potentiometer(useRinput=True)`` the signal
    input ``r`` (a structural choice, as the MSL's useRinput).  Without the MSL's heat
    port the device is at T_ref, and R is not changed by alpha (as :class:`Resistor`).
    """

    R = ac.Parameter(1.0, unit="Ohm", description="resistance at temperature T_ref")
    T_ref = ac.Parameter(293.15, unit="K", min=0, description="reference temperature")
    alpha = ac.Parameter(0.0, unit="1/K",
                         description="temperature coefficient of resistance")
    rConstant = ac.Parameter(0.5, min=0, max=1,
                             description="contact position without the input r")
    pin_p = Pin()
    pin_n = Pin()
    contact = Pin()
    Rp = ac.Variable(unit="Ohm", description="resistance between pin_p and contact")
    Rn = ac.Variable(unit="Ohm", description="resistance between contact and pin_n")

    useRinput = ac.Parameter(False, structural=True,
                             description="the contact position is the input r")
    r = ac.Conditional(RealInput(), "useRinput")

    def loss_power(self):
        """Rp pin_p.i^2 + Rn pin_n.i^2."""
        return self.Rp * self.pin_p.i**2 + self.Rn * self.pin_n.i**2

    def equations(self):
        # the parameter is checked against [0, 1]; only the signal needs the clipping
        r_c = ac.min(1, ac.max(0, self.r.signal)) if self.useRinput else self.rConstant
        return [ac.Eq(0, self.pin_p.i + self.pin_n.i + self.contact.i),
                ac.Eq(self.Rp, self.R * (1 - r_c)),
                ac.Eq(self.Rn, self.R * r_c),
                ac.Eq(self.pin_p.v - self.contact.v, self.Rp * self.pin_p.i),
                ac.Eq(self.pin_n.v - self.contact.v, self.Rn * self.pin_n.i)]


class Transformer(TwoPort):
    """Two coupled inductors (MSL Analog.Basic.Transformer):

        v1 = L1 der(i1) + M der(i2),   v2 = M der(i1) + L2 der(i2)

    (M^2 <= L1 L2 for a physical transformer; equality is the ideal coupling, which
    makes the two currents dependent.)
    """

    L1 = ac.Parameter(1.0, unit="H", description="primary inductance")
    L2 = ac.Parameter(1.0, unit="H", description="secondary inductance")
    M = ac.Parameter(1.0, unit="H", description="coupling inductance")

    def stored_energy(self):
        """W = L1 i1^2 / 2 + M i1 i2 + L2 i2^2 / 2."""
        return self.L1 * self.i1**2 / 2 + self.M * self.i1 * self.i2 + self.L2 * self.i2**2 / 2

    def equations(self):
        di1, di2 = ac.der(self.i1), ac.der(self.i2)
        return [ac.Eq(self.v1, self.L1 * di1 + self.M * di2),
                ac.Eq(self.v2, self.M * di1 + self.L2 * di2)]


class Gyrator(TwoPort):
    """Gyrator (MSL Analog.Basic.Gyrator):  i1 = G2 v2,   i2 = -G1 v1

    (lossless for G1 = G2: v1 i1 + v2 i2 = (G2 - G1) v1 v2).
    """

    G1 = ac.Parameter(1.0, unit="S", description="gyration conductance, port 1")
    G2 = ac.Parameter(1.0, unit="S", description="gyration conductance, port 2")

    energy_role = "source"  # lossless only when G1 = G2; any difference comes from outside

    def equations(self):
        return [ac.Eq(self.i1, self.G2 * self.v2),
                ac.Eq(self.i2, -self.G1 * self.v1)]


class SaturatingInductor(OnePort):
    """Inductor with saturation (Modelica.Electrical.Analog.Basic.SaturatingInductor,
    MSL v4.0.0): the flux follows an arc tangent between the inductance Lzer near
    i = 0 and Linf at large currents,

        Psi = Linf i + (Lzer - Linf) Ipar atan(i/Ipar),   v = der(Psi)
        Lact = Linf + (Lzer - Linf) atan(i/Ipar)/(i/Ipar)   (Lzer at i = 0)

    where Ipar makes the inductance Psi/i equal Lnom at the nominal current Inom:

        (Lnom - Linf)/(Lzer - Linf) = Ipar/Inom (pi/2 - atan(Ipar/Inom))

    (the MSL's parameter with fixed = false: here a variable that this equation
    determines, constant in time; Lzer > Lnom > Linf.)
    """

    Inom = ac.Parameter(1.0, unit="A", description="nominal current")
    Lnom = ac.Parameter(1.0, unit="H", description="nominal inductance at nominal current")
    Lzer = ac.Parameter(lambda c: 2 * c.Lnom, unit="H",
                        description="inductance near current = 0")
    Linf = ac.Parameter(lambda c: c.Lnom / 2, unit="H",
                        description="inductance at large currents")
    i = ac.Variable(start=0.0, unit="A", description="current from p to n")
    Lact = ac.Variable(unit="H", description="present inductance")
    Psi = ac.Variable(unit="Wb", description="present flux")
    Ipar = ac.Variable(start=0.1, unit="A", state_select="never",
                       description="current scale of the arc tangent")

    def stored_energy(self):
        """W = integral of i dPsi = Linf i^2/2 + (Lzer - Linf) Ipar (i atan(i/Ipar)
        - Ipar ln(1 + (i/Ipar)^2)/2)."""
        x = self.i / self.Ipar
        return (self.Linf * self.i**2 / 2 + (self.Lzer - self.Linf) * self.Ipar**2
                * (x * ac.atan(x) - ac.log(1 + x**2) / 2))

    def equations(self):
        self._check_order()
        x = self.i / self.Ipar
        # atan(x)/x -> 1 at x = 0 (the MSL's noEvent(abs(i)/Ipar < small))
        ratio = ac.no_event(ac.if_else(x**2 < 1e-120, 1, ac.atan(x) / x))
        return [ac.Eq((self.Lnom - self.Linf) / (self.Lzer - self.Linf),
                      self.Ipar / self.Inom * (sp.pi / 2 - ac.atan(self.Ipar / self.Inom))),
                ac.Eq(self.Lact, self.Linf + (self.Lzer - self.Linf) * ratio),
                ac.Eq(self.Psi, self.Linf * self.i + (self.Lzer - self.Linf) * self.Ipar
                      * ac.atan(x)),
                ac.Eq(self.v, ac.der(self.Psi))]

    def _check_order(self):
        """The MSL's asserts Lzer > Lnom (1 + eps) and Linf < Lnom (1 - eps), where the
        values are numbers when the model is made."""
        try:
            Lzer, Lnom, Linf = (float(self.parameter_value(n)) for n in ("Lzer", "Lnom", "Linf"))
        except TypeError:
            return                       # bound to other parameters: not known here
        eps = 2.220446049250313e-16
        if not Lzer > Lnom * (1 + eps) or not Linf < Lnom * (1 - eps):
            raise ac.InvalidValue(f"{self._describe()}: SaturatingInductor needs Lzer > Lnom > "
                                  f"Linf, not Lzer = {Lzer:g}, Lnom = {Lnom:g}, Linf = {Linf:g}")
