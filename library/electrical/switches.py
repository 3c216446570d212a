"""Ideal switches (Modelica.Electrical.Analog.Ideal, MSL v4.0.0): the switches with a
Boolean control (``IdealClosingSwitch``, ``IdealOpeningSwitch``, ``IdealTwoWaySwitch``,
``IdealIntermediateSwitch``), those controlled by the potential of a control pin
against ``level`` (``Controlled...``), and the switches with a simple arc model
(``CloserWithArc``, ``OpenerWithArc``, ``ControlledCloserWithArc``,
``ControlledOpenerWithArc``).

The switches are piecewise linear in a curve parameter s (one per branch), as in the
MSL: closed a resistance Ron, open a conductance Goff; the control's change is an event
and the number of states stays the same.
"""
import acausal as ac
from acausal.ports import BooleanInput, NegativePin, Pin, PositivePin, RealInput

from .interfaces import ConditionalHeatPort, IdealSwitch, IdealSwitchWithArc

__all__ = ["IdealClosingSwitch", "IdealOpeningSwitch", "IdealTwoWaySwitch",
           "IdealIntermediateSwitch", "ControlledIdealClosingSwitch",
           "ControlledIdealOpeningSwitch", "ControlledIdealTwoWaySwitch",
           "ControlledIdealIntermediateSwitch", "CloserWithArc", "OpenerWithArc",
           "ControlledCloserWithArc", "ControlledOpenerWithArc"]


class _BooleanControl(ac.Component):
    """The MSL's ``BooleanInput control``; ``booleanControl=False`` (not the MSL's) makes
    it a ``RealInput`` read as true above 0.5."""

    booleanControl = ac.Parameter(True, structural=True,
                                  description="control is a BooleanInput (else a Real "
                                              "signal, true above 0.5)")
    control = BooleanInput()

    def build(self):
        if not self.booleanControl:
            self.control = RealInput()

    def on(self):
        """The control's value as a condition."""
        return self.control if self.booleanControl else self.control.signal > 0.5


class _PinControl(ac.Component):
    """A control pin that takes no current, true while its potential exceeds ``level``."""

    level = ac.Parameter(0.5, unit="V", description="switch level")
    control = Pin()

    def on(self):
        return self.control.v > self.level

    def equations(self):
        return [ac.Eq(self.control.i, 0)]


class IdealClosingSwitch(IdealSwitch, _BooleanControl):
    """Ideal electrical closer (Modelica.Electrical.Analog.Ideal.IdealClosingSwitch, MSL
    v4.0.0):  off = not control   (true: p--n connected)."""

    def equations(self):
        return [ac.Eq(self.off, ~self.on())]


class IdealOpeningSwitch(IdealSwitch, _BooleanControl):
    """Ideal electrical opener (Modelica.Electrical.Analog.Ideal.IdealOpeningSwitch, MSL
    v4.0.0):  off = control   (true: switch open)."""

    def equations(self):
        return [ac.Eq(self.off, self.on())]


class ControlledIdealClosingSwitch(IdealSwitch, _PinControl):
    """Controlled ideal closer (Modelica.Electrical.Analog.Ideal.
    ControlledIdealClosingSwitch, MSL v4.0.0):  off = control.v < level,  control.i = 0."""

    def equations(self):
        return [ac.Eq(self.off, self.control.v < self.level)]


class ControlledIdealOpeningSwitch(IdealSwitch, _PinControl):
    """Controlled ideal opener (Modelica.Electrical.Analog.Ideal.
    ControlledIdealOpeningSwitch, MSL v4.0.0):  off = control.v > level,  control.i = 0."""

    def equations(self):
        return [ac.Eq(self.off, self.control.v > self.level)]


class _TwoWaySwitch(ConditionalHeatPort):
    """p connected to n2 while on, to n1 otherwise (Ron closed, Goff open), one curve
    parameter per branch:

        p.v - n1.v = s1 (1 if on else Ron),   n1.i = -s1 (Goff if on else 1)
        p.v - n2.v = s2 (Ron if on else 1),   n2.i = -s2 (1 if on else Goff)
        0 = p.i + n1.i + n2.i,   LossPower = p.i p.v + n1.i n1.v + n2.i n2.v
    """

    Ron = ac.Parameter(1e-5, unit="Ohm", min=0, description="closed switch resistance")
    Goff = ac.Parameter(1e-5, unit="S", min=0, description="opened switch conductance")
    p = PositivePin()
    n2 = NegativePin()
    n1 = NegativePin()
    s1 = ac.Variable(start=0.0, description="curve parameter of branch p-n1")
    s2 = ac.Variable(start=0.0, description="curve parameter of branch p-n2")

    def equations(self):
        on = self.on()
        return [ac.Eq(0, self.p.i + self.n2.i + self.n1.i),
                ac.Eq(self.p.v - self.n1.v, self.s1 * ac.if_else(on, 1, self.Ron)),
                ac.Eq(self.n1.i, -self.s1 * ac.if_else(on, self.Goff, 1)),
                ac.Eq(self.p.v - self.n2.v, self.s2 * ac.if_else(on, self.Ron, 1)),
                ac.Eq(self.n2.i, -self.s2 * ac.if_else(on, 1, self.Goff)),
                ac.Eq(self.LossPower, self.p.i * self.p.v + self.n1.i * self.n1.v
                      + self.n2.i * self.n2.v)]


class IdealTwoWaySwitch(_TwoWaySwitch, _BooleanControl):
    """Ideal two-way switch (Modelica.Electrical.Analog.Ideal.IdealTwoWaySwitch, MSL
    v4.0.0; the MSL 3's IdealCommutingSwitch): control true connects p--n2, false
    p--n1 (the branch equations of ``_TwoWaySwitch`` with on = control)."""


class ControlledIdealTwoWaySwitch(_TwoWaySwitch, _PinControl):
    """Controlled ideal two-way switch (Modelica.Electrical.Analog.Ideal.
    ControlledIdealTwoWaySwitch, MSL v4.0.0): p--n2 while control.v > level, p--n1
    otherwise; control.i = 0."""


class _IntermediateSwitch(ConditionalHeatPort):
    """p1--n2 and p2--n1 connected while on, p1--n1 and p2--n2 otherwise, one curve
    parameter per branch:

        p1.v - n1.v = s1 (1 if on else Ron),   p2.v - n2.v = s2 (1 if on else Ron)
        p1.v - n2.v = s3 (Ron if on else 1),   p2.v - n1.v = s4 (Ron if on else 1)
        p1.i = s1 Goff + s3 (on),  s1 + s3 Goff (off),  and so on for p2, n1, n2
        LossPower = p1.i p1.v + p2.i p2.v + n1.i n1.v + n2.i n2.v
    """

    Ron = ac.Parameter(1e-5, unit="Ohm", min=0, description="closed switch resistance")
    Goff = ac.Parameter(1e-5, unit="S", min=0, description="opened switch conductance")
    p1 = PositivePin()
    p2 = PositivePin()
    n1 = NegativePin()
    n2 = NegativePin()
    s1 = ac.Variable(start=0.0, description="curve parameter of branch p1-n1")
    s2 = ac.Variable(start=0.0, description="curve parameter of branch p2-n2")
    s3 = ac.Variable(start=0.0, description="curve parameter of branch p1-n2")
    s4 = ac.Variable(start=0.0, description="curve parameter of branch p2-n1")

    def equations(self):
        on = self.on()
        s1, s2, s3, s4, G = self.s1, self.s2, self.s3, self.s4, self.Goff
        return [ac.Eq(self.p1.v - self.n1.v, s1 * ac.if_else(on, 1, self.Ron)),
                ac.Eq(self.p2.v - self.n2.v, s2 * ac.if_else(on, 1, self.Ron)),
                ac.Eq(self.p1.v - self.n2.v, s3 * ac.if_else(on, self.Ron, 1)),
                ac.Eq(self.p2.v - self.n1.v, s4 * ac.if_else(on, self.Ron, 1)),
                ac.Eq(self.p1.i, ac.if_else(on, s1 * G + s3, s1 + s3 * G)),
                ac.Eq(self.p2.i, ac.if_else(on, s2 * G + s4, s2 + s4 * G)),
                ac.Eq(self.n1.i, ac.if_else(on, -s1 * G - s4, -s1 - s4 * G)),
                ac.Eq(self.n2.i, ac.if_else(on, -s2 * G - s3, -s2 - s3 * G)),
                ac.Eq(self.LossPower, self.p1.i * self.p1.v + self.p2.i * self.p2.v
                      + self.n1.i * self.n1.v + self.n2.i * self.n2.v)]


class IdealIntermediateSwitch(_IntermediateSwitch, _BooleanControl):
    """Ideal intermediate switch (Modelica.Electrical.Analog.Ideal.
    IdealIntermediateSwitch, MSL v4.0.0): control true connects p1--n2 and p2--n1,
    false p1--n1 and p2--n2."""


class ControlledIdealIntermediateSwitch(_IntermediateSwitch, _PinControl):
    """Controlled ideal intermediate switch (Modelica.Electrical.Analog.Ideal.
    ControlledIdealIntermediateSwitch, MSL v4.0.0): p1--n2 and p2--n1 while
    control.v > level, p1--n1 and p2--n2 otherwise; control.i = 0."""


class CloserWithArc(IdealSwitchWithArc, _BooleanControl):
    """Ideal closing switch with a simple arc model (Modelica.Electrical.Analog.Ideal.
    CloserWithArc, MSL v4.0.0):  off = not control   (true: p--n connected), the arc of
    :class:`~.interfaces.IdealSwitchWithArc` when it opens."""

    def equations(self):
        return [ac.Eq(self.off, ~self.on())]


class OpenerWithArc(IdealSwitchWithArc, _BooleanControl):
    """Ideal opening switch with a simple arc model (Modelica.Electrical.Analog.Ideal.
    OpenerWithArc, MSL v4.0.0):  off = control   (true: switch open)."""

    def equations(self):
        return [ac.Eq(self.off, self.on())]


class ControlledCloserWithArc(IdealSwitchWithArc, _PinControl):
    """Controlled ideal closer with a simple arc model (Modelica.Electrical.Analog.Ideal.
    ControlledCloserWithArc, MSL v4.0.0):  off = control.v < level,  control.i = 0."""

    def equations(self):
        return [ac.Eq(self.off, self.control.v < self.level)]


class ControlledOpenerWithArc(IdealSwitchWithArc, _PinControl):
    """Controlled ideal opener with a simple arc model (Modelica.Electrical.Analog.Ideal.
    ControlledOpenerWithArc, MSL v4.0.0):  off = control.v > level,  control.i = 0."""

    def equations(self):
        return [ac.Eq(self.off, self.control.v > self.level)]
