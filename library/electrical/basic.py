"""Basic electrical components (Modelica.Electrical.Analog.Basic)."""
import acausal as ac
from acausal.ports import BooleanInput, HeatPort, Pin, RealInput

from .interfaces import OnePort, TwoPort

__all__ = ["Ground", "Resistor", "Conductor", "Capacitor", "Inductor", "HeatingResistor",
           "VariableResistor", "VariableConductor", "VariableCapacitor", "VariableInductor",
           "Potentiometer",
           "Transformer", "Gyrator", "IdealTransformer", "IdealOpAmp", "IdealClosingSwitch",
           "IdealOpeningSwitch"]


class Ground(ac.Component):
    """Reference potential:  p.v = 0."""

    p = Pin()

    energy_role = "lossless"  # v = 0: takes no power

    def equations(self):
        return [ac.Eq(self.p.v, 0)]


class Resistor(OnePort):
    """Ideal linear resistor, Ohm's law:  v = R i."""

    R = ac.Parameter(1.0, unit="Ohm", min=0, description="resistance")

    def loss_power(self):
        """P_loss = R i^2 (to the environment; the audit checks it against v i)."""
        return self.R * self.i**2

    def equations(self):
        return [ac.Eq(self.v, self.R * self.i)]


class Conductor(OnePort):
    """Ideal linear conductor (MSL Analog.Basic.Conductor):  i = G v."""

    G = ac.Parameter(1.0, unit="S", min=0, description="conductance")

    def loss_power(self):
        """P_loss = G v^2 (the audit checks it against v i)."""
        return self.G * self.v**2

    def equations(self):
        return [ac.Eq(self.i, self.G * self.v)]


class Capacitor(OnePort):
    """Ideal capacitor:  C dv/dt = i."""

    C = ac.Parameter(1.0, unit="F", min=0, description="capacitance")
    v = ac.Variable(start=0.0, unit="V", description="voltage drop p.v - n.v")

    def stored_energy(self):
        """W = C v^2 / 2."""
        return self.C * self.v**2 / 2

    def equations(self):
        return [ac.Eq(self.C * ac.der(self.v), self.i)]


class Inductor(OnePort):
    """Ideal inductor:  L di/dt = v."""

    L = ac.Parameter(1.0, unit="H", min=0, description="inductance")
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

    R_ref = ac.Parameter(1.0, unit="Ohm", min=0, description="resistance at T_ref")
    T_ref = ac.Parameter(300.15, unit="K", description="reference temperature")
    alpha = ac.Parameter(0.0, unit="1/K", description="temperature coefficient of R")
    heatPort = HeatPort()
    R = ac.Variable(unit="Ohm", description="resistance at the port temperature")

    energy_role = "lossless"  # v i leaves as heat through heatPort

    def equations(self):
        return [ac.Eq(self.R, self.R_ref * (1 + self.alpha * (self.heatPort.T - self.T_ref))),
                ac.Eq(self.v, self.R * self.i),
                ac.Eq(self.heatPort.Q_flow, -self.v * self.i)]


class VariableResistor(OnePort):
    """Resistor whose resistance is a signal (MSL Analog.Basic.VariableResistor):

        v = R i          (R >= 0 for a passive resistor)
    """

    R = RealInput()

    def loss_power(self):
        """P_loss = R i^2 (negative if the signal R is)."""
        return self.R * self.i**2

    def equations(self):
        return [ac.Eq(self.v, self.R * self.i)]


class VariableConductor(OnePort):
    """Conductor whose conductance is a signal (MSL Analog.Basic.VariableConductor):

        i = G v          (G >= 0 for a passive conductor)
    """

    G = RealInput()

    def loss_power(self):
        """P_loss = G v^2."""
        return self.G * self.v**2

    def equations(self):
        return [ac.Eq(self.i, self.G * self.v)]


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
    Lmin = ac.Parameter(1e-15, unit="H", min=0, description="lower bound of L")
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
    input ``r`` (a structural choice, as the MSL's useRinput).
    """

    R = ac.Parameter(1.0, unit="Ohm", min=0, description="total resistance")
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

    L1 = ac.Parameter(1.0, unit="H", min=0, description="primary inductance")
    L2 = ac.Parameter(1.0, unit="H", min=0, description="secondary inductance")
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


class IdealTransformer(TwoPort):
    """Ideal transformer with turns ratio n = N1/N2:

        v1 = n v2,   i2 = -n i1   (so v1 i1 + v2 i2 = 0: lossless)
    """

    n = ac.Parameter(1.0, description="turns ratio N1/N2")

    energy_role = "lossless"  # v1 i1 + v2 i2 = 0

    def equations(self):
        return [ac.Eq(self.v1, self.n * self.v2),
                ac.Eq(self.i2, -self.n * self.i1)]


class IdealOpAmp(ac.Component):
    """Ideal operational amplifier as a nullor (Modelica IdealOpAmp3Pin):

        in_p.v = in_n.v,   in_p.i = 0,   in_n.i = 0

    The output current out.i is whatever the circuit demands (a norator); the output
    voltage is set by the feedback network, which must exist for the model to be regular.
    """

    in_p = Pin()
    in_n = Pin()
    out = Pin()

    energy_role = "source"  # the output stage is fed by a supply outside the model

    def equations(self):
        return [ac.Eq(self.in_p.v, self.in_n.v), ac.Eq(self.in_p.i, 0), ac.Eq(self.in_n.i, 0)]


class _IdealSwitch(OnePort):
    """A switch as a piecewise-linear one-port in the curve parameter s (MSL Ideal):

        v = s (Ron if closed else 1),   i = s (1 if closed else Goff)

    ``control`` is a signal; the switch changes state when it crosses 0.5 (an event).
    With ``booleanControl=True`` it is a ``BooleanInput`` (the MSL's Ideal switches):
    true closes an IdealClosingSwitch and opens an IdealOpeningSwitch.
    """

    Ron = ac.Parameter(1e-5, unit="Ohm", min=0, description="resistance when closed")
    Goff = ac.Parameter(1e-5, unit="S", min=0, description="conductance when open")
    booleanControl = ac.Parameter(False, structural=True,
                                  description="control is a BooleanInput (else a Real signal)")
    control = RealInput()
    s = ac.Variable(start=0.0, description="curve parameter (i when closed, v when open)")

    def loss_power(self):
        """P_loss = v i = s^2 Ron (closed), s^2 Goff (open)."""
        return self.v * self.i

    def build(self):
        if self.booleanControl:
            self.control = BooleanInput()

    def on(self):
        """The control's condition: true, or a Real signal above 0.5."""
        return self.control if self.booleanControl else self.control.signal > 0.5

    def closed(self):
        raise NotImplementedError

    def equations(self):
        closed = self.closed()
        return [ac.Eq(self.v, self.s * ac.if_else(closed, self.Ron, 1)),
                ac.Eq(self.i, self.s * ac.if_else(closed, 1, self.Goff))]


class IdealClosingSwitch(_IdealSwitch):
    """Ideal switch, closed while control > 0.5 (or true)."""

    def closed(self):
        return self.on()


class IdealOpeningSwitch(_IdealSwitch):
    """Ideal switch, open while control > 0.5 (or true)."""

    def closed(self):
        return ~self.on()
