"""Basic electrical components (Modelica.Electrical.Analog.Basic)."""
import acausal as ac
from acausal.ports import HeatPort, Pin, RealInput

from .interfaces import OnePort, TwoPort

__all__ = ["Ground", "Resistor", "Capacitor", "Inductor", "HeatingResistor",
           "IdealTransformer", "IdealOpAmp", "IdealClosingSwitch", "IdealOpeningSwitch"]


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
    """

    Ron = ac.Parameter(1e-5, unit="Ohm", min=0, description="resistance when closed")
    Goff = ac.Parameter(1e-5, unit="S", min=0, description="conductance when open")
    control = RealInput()
    s = ac.Variable(start=0.0, description="curve parameter (i when closed, v when open)")

    def loss_power(self):
        """P_loss = v i = s^2 Ron (closed), s^2 Goff (open)."""
        return self.v * self.i

    def closed(self):
        raise NotImplementedError

    def equations(self):
        closed = self.closed()
        return [ac.Eq(self.v, self.s * ac.if_else(closed, self.Ron, 1)),
                ac.Eq(self.i, self.s * ac.if_else(closed, 1, self.Goff))]


class IdealClosingSwitch(_IdealSwitch):
    """Ideal switch, closed while control > 0.5."""

    def closed(self):
        return self.control.signal > 0.5


class IdealOpeningSwitch(_IdealSwitch):
    """Ideal switch, open while control > 0.5."""

    def closed(self):
        return self.control.signal <= 0.5
