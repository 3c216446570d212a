"""Logical blocks (Modelica.Blocks.Logical, MSL v4.0.0).

Boolean outputs are given by one equation each, evaluated at every event; ``pre(x)`` is
the value before the event, and Modelica's event iteration repeats the evaluation until
no ``pre`` differs from its variable (``Pre`` breaks an algebraic loop of Booleans that
way).  A block that starts from a chosen ``pre`` value of its input (``pre_u_start``)
keeps its own copy of the input, ``u_`` (start ``pre_u_start``), whose ``pre`` it reads.
"""
import acausal as ac
from acausal.ports import BooleanInput, BooleanOutput, RealInput, RealOutput

from .boolean_interfaces import (BooleanComparison, BooleanSI2SO, BooleanSISO, BooleanSI3SO,
                                 BooleanThresholdComparison, output_start)

__all__ = ["And", "Or", "Xor", "Nor", "Nand", "Not", "Pre", "Edge", "FallingEdge", "Change",
           "GreaterThreshold", "GreaterEqualThreshold", "LessThreshold",
           "LessEqualThreshold", "Greater", "GreaterEqual", "Less", "LessEqual",
           "ZeroCrossing", "LogicalSwitch", "Switch", "Hysteresis", "OnOffController",
           "TriggeredTrapezoid", "Timer", "RSFlipFlop"]


class And(BooleanSI2SO):
    """y = u1 and u2   (Modelica.Blocks.Logical.And)."""

    def equations(self):
        return [ac.Eq(self.y, self.u1 & self.u2)]


class Or(BooleanSI2SO):
    """y = u1 or u2   (Modelica.Blocks.Logical.Or)."""

    def equations(self):
        return [ac.Eq(self.y, self.u1 | self.u2)]


class Xor(BooleanSI2SO):
    """y = not ((u1 and u2) or (not u1 and not u2))   (Modelica.Blocks.Logical.Xor)."""

    def equations(self):
        return [ac.Eq(self.y, ~((self.u1 & self.u2) | (~self.u1 & ~self.u2)))]


class Nor(BooleanSI2SO):
    """y = not (u1 or u2)   (Modelica.Blocks.Logical.Nor)."""

    def equations(self):
        return [ac.Eq(self.y, ~(self.u1 | self.u2))]


class Nand(BooleanSI2SO):
    """y = not (u1 and u2)   (Modelica.Blocks.Logical.Nand)."""

    def equations(self):
        return [ac.Eq(self.y, ~(self.u1 & self.u2))]


class Not(BooleanSISO):
    """y = not u   (Modelica.Blocks.Logical.Not)."""

    def equations(self):
        return [ac.Eq(self.y, ~self.u)]


class _PreOfInput(BooleanSISO):
    """The input's value with its own pre value at the start:  u_ = u, pre(u_) =
    pre_u_start before the first event iteration (the MSL's ``pre(u) = pre_u_start``)."""

    pre_u_start = ac.Parameter(False, description="start value of pre(u) at initial time")
    u_ = ac.Variable(type=bool, description="the input, with pre(u_) = pre_u_start at t0")

    def __init__(self, **mods):
        mods.setdefault("u_", {"start": mods.get("pre_u_start", False)})
        super().__init__(**mods)

    def equations(self):
        return [ac.Eq(self.u_, self.u)]


class Pre(_PreOfInput):
    """y = pre(u): the input's value before the event, so event iteration continues until
    u = pre(u) (Modelica.Blocks.Logical.Pre; it breaks algebraic loops of Booleans)."""

    def equations(self):
        return [ac.Eq(self.y, ac.pre(self.u_))]


class Edge(_PreOfInput):
    """y = edge(u) = u and not pre(u): true at the event where u becomes true
    (Modelica.Blocks.Logical.Edge)."""

    def equations(self):
        return [ac.Eq(self.y, ac.edge(self.u_))]


class FallingEdge(_PreOfInput):
    """y = edge(not u): true at the event where u becomes false
    (Modelica.Blocks.Logical.FallingEdge)."""

    def equations(self):
        return [ac.Eq(self.y, ~self.u_ & ac.pre(self.u_))]


class Change(_PreOfInput):
    """y = change(u) = u <> pre(u): true at the event where u changes
    (Modelica.Blocks.Logical.Change)."""

    def equations(self):
        return [ac.Eq(self.y, ac.change(self.u_))]


class GreaterThreshold(BooleanThresholdComparison):
    """y = u > threshold   (Modelica.Blocks.Logical.GreaterThreshold)."""

    def equations(self):
        return [ac.Eq(self.y, self.u > self.threshold)]


class GreaterEqualThreshold(BooleanThresholdComparison):
    """y = u >= threshold   (Modelica.Blocks.Logical.GreaterEqualThreshold)."""

    def equations(self):
        return [ac.Eq(self.y, self.u >= self.threshold)]


class LessThreshold(BooleanThresholdComparison):
    """y = u < threshold   (Modelica.Blocks.Logical.LessThreshold)."""

    def equations(self):
        return [ac.Eq(self.y, self.u < self.threshold)]


class LessEqualThreshold(BooleanThresholdComparison):
    """y = u <= threshold   (Modelica.Blocks.Logical.LessEqualThreshold)."""

    def equations(self):
        return [ac.Eq(self.y, self.u <= self.threshold)]


class Greater(BooleanComparison):
    """y = u1 > u2   (Modelica.Blocks.Logical.Greater)."""

    def equations(self):
        return [ac.Eq(self.y, self.u1 > self.u2)]


class GreaterEqual(BooleanComparison):
    """y = u1 >= u2   (Modelica.Blocks.Logical.GreaterEqual)."""

    def equations(self):
        return [ac.Eq(self.y, self.u1 >= self.u2)]


class Less(BooleanComparison):
    """y = u1 < u2   (Modelica.Blocks.Logical.Less)."""

    def equations(self):
        return [ac.Eq(self.y, self.u1 < self.u2)]


class LessEqual(BooleanComparison):
    """y = u1 <= u2   (Modelica.Blocks.Logical.LessEqual)."""

    def equations(self):
        return [ac.Eq(self.y, self.u1 <= self.u2)]


class ZeroCrossing(ac.Component):
    """Trigger at a zero crossing of u while ``enable`` is true
    (Modelica.Blocks.Logical.ZeroCrossing):

        u_pos = enable and u >= 0,
        y = change(u_pos) and not edge(enable) and not edge(not enable)
    """

    u = RealInput()
    enable = BooleanInput()
    y = BooleanOutput()
    enable_ = ac.Variable(type=bool, description="the enable input (pre(enable) = false)")
    u_pos = ac.Variable(type=bool, description="enable and u >= 0")

    def equations(self):
        e = self.enable_
        return [ac.Eq(self.enable_, self.enable),
                ac.Eq(self.u_pos, self.enable & (self.u >= 0)),
                ac.Eq(self.y, ac.change(self.u_pos) & ~ac.edge(e) & ~(~e & ac.pre(e)))]


class LogicalSwitch(BooleanSI3SO):
    """y = if u2 then u1 else u3   (Modelica.Blocks.Logical.LogicalSwitch)."""

    def equations(self):
        return [ac.Eq(self.y, ac.if_else(self.u2, self.u1, self.u3))]


class Switch(ac.Component):
    """Switch between two Real signals:  y = if u2 then u1 else u3
    (Modelica.Blocks.Logical.Switch)."""

    u1 = RealInput()
    u2 = BooleanInput()
    u3 = RealInput()
    y = RealOutput()

    def equations(self):
        return [ac.Eq(self.y, ac.if_else(self.u2, self.u1, self.u3))]


class Hysteresis(ac.Component):
    """Real to Boolean with hysteresis (Modelica.Blocks.Logical.Hysteresis):

        y = not pre(y) and u > uHigh  or  pre(y) and u >= uLow,   pre(y) = pre_y_start at t0
    """

    u = RealInput()
    y = BooleanOutput()
    uLow = ac.Parameter(0.0, description="if y = true and u < uLow, switch to y = false")
    uHigh = ac.Parameter(1.0, description="if y = false and u > uHigh, switch to y = true")
    pre_y_start = ac.Parameter(False, description="value of pre(y) at initial time")

    def __init__(self, **mods):
        super().__init__(**output_start(mods, "pre_y_start", False))

    def equations(self):
        y0 = ac.pre(self.y)
        return [ac.Eq(self.y, (~y0 & (self.u > self.uHigh)) | (y0 & (self.u >= self.uLow)))]


class OnOffController(ac.Component):
    """On-off controller (Modelica.Blocks.Logical.OnOffController):

        y = pre(y) and u < reference + bandwidth/2  or  u < reference - bandwidth/2
    """

    reference = RealInput()
    u = RealInput()
    y = BooleanOutput()
    bandwidth = ac.Parameter(0.1, description="bandwidth around reference signal")
    pre_y_start = ac.Parameter(False, description="value of pre(y) at initial time")

    def __init__(self, **mods):
        super().__init__(**output_start(mods, "pre_y_start", False))

    def equations(self):
        half = self.bandwidth / 2
        return [ac.Eq(self.y, (ac.pre(self.y) & (self.u < self.reference + half))
                      | (self.u < self.reference - half))]


class TriggeredTrapezoid(ac.Component):
    """Triggered trapezoid generator (Modelica.Blocks.Logical.TriggeredTrapezoid): at
    each edge of u the output ramps towards offset + amplitude (u true) or offset (u
    false) at the rate amplitude/rising or amplitude/falling:

        y = if time < T then endValue - (T - time) rate else endValue,
        when {initial(), u, not u}:  endValue = if u then offset + amplitude else offset,
            rate = amplitude/rising (u, rising > 0), -amplitude/falling (not u,
            falling > 0), else 0,
            T = time where the ramp is instantaneous or at initial(), else
            time + (endValue - pre(y))/rate
    """

    u = BooleanInput()
    y = RealOutput()
    amplitude = ac.Parameter(1.0, description="amplitude of trapezoid")
    rising = ac.Parameter(0.0, unit="s", min=0, description="rising duration of trapezoid")
    falling = ac.Parameter(lambda c: c.rising, unit="s", min=0,
                           description="falling duration of trapezoid")
    offset = ac.Parameter(0.0, description="offset of output signal")
    endValue = ac.Variable(discrete=True, start=0.0, description="value of y at time of recent edge")
    rate = ac.Variable(discrete=True, start=0.0, description="current rising/falling rate")
    T = ac.Variable(discrete=True, start=0.0, unit="s",
                    description="predicted time of output reaching endValue")

    def equations(self):
        u, t = self.u, ac.time
        end = ac.if_else(u, self.offset + self.amplitude, self.offset)
        rate = ac.if_else(u & (self.rising > 0), self.amplitude / self.rising,
                          ac.if_else(~u & (self.falling > 0), -self.amplitude / self.falling,
                                     0))
        instant = (u & ~(self.rising > 0)) | (~u & ~(self.falling > 0)) \
            | ~(ac.abs(self.amplitude) > 0) | ac.initial()
        # (endValue - pre(y))/rate, written with the durations (the rate is not 0 where
        # the ramp is not instantaneous); pre(y) is y of the values before the event
        pre_y = self._output(ac.pre(self.T), ac.pre(self.endValue), ac.pre(self.rate))
        duration = ac.if_else(u, self.rising, -self.falling) * (end - pre_y) / self.amplitude
        return [ac.Eq(self.y, self._output(self.T, self.endValue, self.rate)),
                ac.when([ac.initial(), u, ~u],
                        ac.assign(self.endValue, end), ac.assign(self.rate, rate),
                        ac.assign(self.T, ac.if_else(instant, t, t + duration)))]


    @staticmethod
    def _output(T, endValue, rate):
        return ac.if_else(ac.time < T, endValue - (T - ac.time) * rate, endValue)


class Timer(ac.Component):
    """Time since u became true (Modelica.Blocks.Logical.Timer):

        when u: entryTime = time,     y = if u then time - entryTime else 0
    """

    u = BooleanInput()
    y = RealOutput()
    entryTime = ac.Variable(discrete=True, start=0.0, unit="s",
                            description="time instant when u became true")

    def equations(self):
        return [ac.when(self.u, ac.assign(self.entryTime, ac.time)),
                ac.Eq(self.y, ac.if_else(self.u, ac.time - self.entryTime, 0.0))]


class RSFlipFlop(ac.Component):
    """A basic RS flip-flop of two Nor gates and a Pre (Modelica.Blocks.Logical.RSFlipFlop):
    S sets Q, R resets it, QI = not Q; ``Qini`` is Q at the start."""

    Qini = ac.Parameter(False, structural=True, description="start value of Q at initial time")
    S = BooleanInput()
    R = BooleanInput()
    Q = BooleanOutput()
    QI = BooleanOutput()
    nor = Nor()
    nor1 = Nor()

    def build(self):
        self.pre = Pre(pre_u_start=not self.Qini)

    def equations(self):
        return [ac.connect(self.nor1.y, self.nor.u2),
                ac.connect(self.nor1.y, self.Q),
                ac.connect(self.nor.y, self.pre.u),
                ac.connect(self.pre.y, self.nor1.u1),
                ac.connect(self.pre.y, self.QI),
                ac.connect(self.S, self.nor.u1),
                ac.connect(self.R, self.nor1.u2)]
