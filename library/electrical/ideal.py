"""Ideal elements (Modelica.Electrical.Analog.Ideal, MSL v4.0.0): the ideal diode, the
ideal transformer, ideal switches, short and idle branches.  The ideal operational
amplifiers are in :mod:`.opamps`.

The switching elements are piecewise linear in a curve parameter s, as in the MSL: the
switch is an event on s or on the control, and the number of states stays the same.
The switches here are the MSL's *controlled* switches, closed or opened by the
potential of a control pin against ``level``.  ``IdealClosingSwitch`` and
``IdealOpeningSwitch`` take a Real ``control`` signal, closed (opened) above 0.5 (the
MSL's take a Boolean).
"""
import acausal as ac
from acausal.ports import BooleanInput, NegativePin, Pin, PositivePin, RealInput

from .interfaces import ConditionalHeatPort, OnePort, TwoPort

__all__ = ["IdealDiode", "IdealTransformer", "IdealClosingSwitch", "IdealOpeningSwitch",
           "ControlledIdealClosingSwitch", "ControlledIdealOpeningSwitch",
           "ControlledIdealTwoWaySwitch", "ControlledIdealIntermediateSwitch", "Short",
           "Idle"]


class IdealDiode(OnePort, ConditionalHeatPort):
    """Ideal diode (Modelica.Electrical.Analog.Ideal.IdealDiode, MSL v4.0.0) as a
    piecewise-linear characteristic in the curve parameter s (the MSL's
    IdealSemiconductor):

        off = s < 0
        v = s (1 if off else Ron) + Vknee,   i = s (Goff if off else 1) + Goff Vknee

    Conducting (s >= 0) it is a resistance Ron, blocking a conductance Goff; the switch
    is an event on s, so the number of states does not change.  LossPower = v i.  Note:
    a circuit where s is exactly 0 at the start time and rising (a sine source with zero
    phase) does not start; give the source a phase or a start time.
    """

    Ron = ac.Parameter(1e-5, unit="Ohm", min=0,
                       description="forward state-on differential resistance")
    Goff = ac.Parameter(1e-5, unit="S", min=0, description="backward state-off conductance")
    Vknee = ac.Parameter(0.0, unit="V", min=0, description="forward threshold voltage")
    s = ac.Variable(start=0.0, description="curve parameter (i when on, v when off)")

    def loss_power(self):
        """P_loss = v i >= 0 (the characteristic lies in the first and third quadrants)."""
        return self.v * self.i

    def equations(self):
        off = self.s < 0
        return [ac.Eq(self.v, self.s * ac.if_else(off, 1, self.Ron) + self.Vknee),
                ac.Eq(self.i, self.s * ac.if_else(off, self.Goff, 1) + self.Goff * self.Vknee),
                ac.Eq(self.LossPower, self.v * self.i)]


class IdealTransformer(TwoPort):
    """Ideal transformer core with or without magnetization (Modelica.Electrical.Analog.
    Ideal.IdealTransformer, MSL v4.0.0), turns ratio n = v1/v2:

        v1 = n v2,   im1 = i1 + i2/n
        im1 = 0                              (considerMagnetization = False: lossless)
        psim1 = Lm1 im1,   v1 = der(psim1)   (considerMagnetization = True)

    ``considerMagnetization`` is structural (it adds a state).
    """

    n = ac.Parameter(1.0, description="turns ratio primary:secondary voltage")
    considerMagnetization = ac.Parameter(False, structural=True,
                                         description="choice of considering magnetization")
    Lm1 = ac.Parameter(1.0, unit="H", description="magnetization inductance w.r.t. primary side")
    im1 = ac.Variable(unit="A", description="magnetization current w.r.t. primary side")

    def stored_energy(self):
        """W = Lm1 im1^2 / 2 (0 without magnetization: lossless)."""
        return self.Lm1 * self.im1**2 / 2 if self.considerMagnetization else 0

    def equations(self):
        if not self.considerMagnetization:
            magnetization = [ac.Eq(self.im1, 0)]
        else:
            magnetization = [ac.Eq(self.v1, self.Lm1 * ac.der(self.im1))]
        return [ac.Eq(self.im1, self.i1 + self.i2 / self.n), *magnetization,
                ac.Eq(self.v1, self.n * self.v2)]


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


class _ControlledIdealSwitch(OnePort, ConditionalHeatPort):
    """The MSL's Interfaces.IdealSwitch with a control pin (no current into it):

        v = s (1 if off else Ron),   i = s (Goff if off else 1),   LossPower = v i
    """

    level = ac.Parameter(0.5, unit="V", description="switch level")
    Ron = ac.Parameter(1e-5, unit="Ohm", min=0, description="closed switch resistance")
    Goff = ac.Parameter(1e-5, unit="S", min=0, description="opened switch conductance")
    control = Pin()
    s = ac.Variable(start=0.0, description="curve parameter (i when closed, v when open)")

    def off(self):
        raise NotImplementedError

    def equations(self):
        off = self.off()
        return [ac.Eq(self.control.i, 0),
                ac.Eq(self.v, self.s * ac.if_else(off, 1, self.Ron)),
                ac.Eq(self.i, self.s * ac.if_else(off, self.Goff, 1)),
                ac.Eq(self.LossPower, self.v * self.i)]


class ControlledIdealClosingSwitch(_ControlledIdealSwitch):
    """Controlled ideal closer (Modelica.Electrical.Analog.Ideal.
    ControlledIdealClosingSwitch, MSL v4.0.0): off = control.v < level."""

    def off(self):
        return self.control.v < self.level


class ControlledIdealOpeningSwitch(_ControlledIdealSwitch):
    """Controlled ideal opener (Modelica.Electrical.Analog.Ideal.
    ControlledIdealOpeningSwitch, MSL v4.0.0): off = control.v > level."""

    def off(self):
        return self.control.v > self.level


class ControlledIdealTwoWaySwitch(ConditionalHeatPort):
    """Controlled ideal two-way switch (Modelica.Electrical.Analog.Ideal.
    ControlledIdealTwoWaySwitch, MSL v4.0.0): p is connected to n2 while
    control.v > level, to n1 otherwise (Ron closed, Goff open), one curve parameter per
    branch:

        p.v - n1.v = s1 (1 if on else Ron),   n1.i = -s1 (Goff if on else 1)
        p.v - n2.v = s2 (Ron if on else 1),   n2.i = -s2 (1 if on else Goff)
        0 = p.i + n1.i + n2.i,   on = control.v > level
    """

    level = ac.Parameter(0.5, unit="V", description="switch level")
    Ron = ac.Parameter(1e-5, unit="Ohm", min=0, description="closed switch resistance")
    Goff = ac.Parameter(1e-5, unit="S", min=0, description="opened switch conductance")
    p = PositivePin()
    n1 = NegativePin()
    n2 = NegativePin()
    control = Pin()
    s1 = ac.Variable(start=0.0, description="curve parameter of branch p-n1")
    s2 = ac.Variable(start=0.0, description="curve parameter of branch p-n2")

    def equations(self):
        on = self.control.v > self.level
        return [ac.Eq(self.control.i, 0),
                ac.Eq(0, self.p.i + self.n2.i + self.n1.i),
                ac.Eq(self.p.v - self.n1.v, self.s1 * ac.if_else(on, 1, self.Ron)),
                ac.Eq(self.n1.i, -self.s1 * ac.if_else(on, self.Goff, 1)),
                ac.Eq(self.p.v - self.n2.v, self.s2 * ac.if_else(on, self.Ron, 1)),
                ac.Eq(self.n2.i, -self.s2 * ac.if_else(on, 1, self.Goff)),
                ac.Eq(self.LossPower, self.p.i * self.p.v + self.n1.i * self.n1.v
                      + self.n2.i * self.n2.v)]


class ControlledIdealIntermediateSwitch(ConditionalHeatPort):
    """Controlled ideal intermediate switch (Modelica.Electrical.Analog.Ideal.
    ControlledIdealIntermediateSwitch, MSL v4.0.0): p1-n2 and p2-n1 connected while
    control.v > level, p1-n1 and p2-n2 otherwise; one curve parameter per branch:

        p1.v - n1.v = s1 (1 if on else Ron),   p2.v - n2.v = s2 (1 if on else Ron)
        p1.v - n2.v = s3 (Ron if on else 1),   p2.v - n1.v = s4 (Ron if on else 1)
        p1.i = s1 Goff + s3 (on),   s1 + s3 Goff (off),   and so on for p2, n1, n2
    """

    level = ac.Parameter(0.5, unit="V", description="switch level")
    Ron = ac.Parameter(1e-5, unit="Ohm", min=0, description="closed switch resistance")
    Goff = ac.Parameter(1e-5, unit="S", min=0, description="opened switch conductance")
    p1 = PositivePin()
    p2 = PositivePin()
    n1 = NegativePin()
    n2 = NegativePin()
    control = Pin()
    s1 = ac.Variable(start=0.0, description="curve parameter of branch p1-n1")
    s2 = ac.Variable(start=0.0, description="curve parameter of branch p2-n2")
    s3 = ac.Variable(start=0.0, description="curve parameter of branch p1-n2")
    s4 = ac.Variable(start=0.0, description="curve parameter of branch p2-n1")

    def equations(self):
        on = self.control.v > self.level
        s1, s2, s3, s4, G = self.s1, self.s2, self.s3, self.s4, self.Goff
        return [ac.Eq(self.control.i, 0),
                ac.Eq(self.p1.v - self.n1.v, s1 * ac.if_else(on, 1, self.Ron)),
                ac.Eq(self.p2.v - self.n2.v, s2 * ac.if_else(on, 1, self.Ron)),
                ac.Eq(self.p1.v - self.n2.v, s3 * ac.if_else(on, self.Ron, 1)),
                ac.Eq(self.p2.v - self.n1.v, s4 * ac.if_else(on, self.Ron, 1)),
                ac.Eq(self.p1.i, ac.if_else(on, s1 * G + s3, s1 + s3 * G)),
                ac.Eq(self.p2.i, ac.if_else(on, s2 * G + s4, s2 + s4 * G)),
                ac.Eq(self.n1.i, ac.if_else(on, -s1 * G - s4, -s1 - s4 * G)),
                ac.Eq(self.n2.i, ac.if_else(on, -s2 * G - s3, -s2 - s3 * G)),
                ac.Eq(self.LossPower, self.p1.i * self.p1.v + self.p2.i * self.p2.v
                      + self.n1.i * self.n1.v + self.n2.i * self.n2.v)]


class Short(OnePort):
    """Short cut branch (Modelica.Electrical.Analog.Ideal.Short):  v = 0."""

    energy_role = "lossless"  # v = 0

    def equations(self):
        return [ac.Eq(self.v, 0)]


class Idle(OnePort):
    """Idle branch (Modelica.Electrical.Analog.Ideal.Idle):  i = 0."""

    energy_role = "lossless"  # i = 0

    def equations(self):
        return [ac.Eq(self.i, 0)]
