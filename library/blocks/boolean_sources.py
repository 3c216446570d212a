"""Sources of Boolean signals (Modelica.Blocks.Sources, MSL v4.0.0: BooleanConstant,
BooleanStep, BooleanPulse, SampleTrigger, BooleanTable, BooleanExpression,
RadioButtonSource).

Their switching times are exact time events: the relations of time and parameters (or
held values) in their equations are linear in time between events.
"""
import acausal as ac
from acausal.ports import BooleanInput, BooleanOutput

from .boolean_interfaces import BooleanSource
from .conversions import RealToBoolean
from .tables import CombiTimeTable

__all__ = ["BooleanConstant", "BooleanStep", "BooleanPulse", "SampleTrigger",
           "BooleanTable", "BooleanExpression", "RadioButtonSource"]


class BooleanConstant(BooleanSource):
    """y = k   (Modelica.Blocks.Sources.BooleanConstant)."""

    k = ac.Parameter(True, description="constant output value")

    def equations(self):
        return [ac.Eq(self.y, self.k)]


class BooleanStep(BooleanSource):
    """y = if time >= startTime then not startValue else startValue
    (Modelica.Blocks.Sources.BooleanStep)."""

    startTime = ac.Parameter(0.0, unit="s", description="time instant of step start")
    startValue = ac.Parameter(False, description="output before startTime")

    def equations(self):
        return [ac.Eq(self.y, (ac.time >= self.startTime) ^ self.startValue)]


class BooleanPulse(BooleanSource):
    """Boolean pulse train (Modelica.Blocks.Sources.BooleanPulse): true for width % of
    each period, from startTime:

        when sample(startTime, period):  pulseStart = time,
        y = time >= pulseStart and time < pulseStart + Twidth,   Twidth = period width/100
    """

    width = ac.Parameter(50.0, min=0, max=100, description="width of pulse in % of period")
    period = ac.Parameter(1.0, unit="s", min=0, description="time for one period")
    startTime = ac.Parameter(0.0, unit="s", description="time instant of first pulse")
    Twidth = ac.Parameter(lambda c: c.period * c.width / 100, unit="s",
                          description="width of one pulse")
    pulseStart = ac.Variable(discrete=True, start=0.0, unit="s",
                             description="start time of pulse")

    def __init__(self, **mods):
        mods.setdefault("pulseStart", mods.get("startTime", 0.0))
        super().__init__(**mods)

    def equations(self):
        t = ac.time
        return [ac.when(ac.sample(self.startTime, self.period),
                        ac.assign(self.pulseStart, t)),
                ac.Eq(self.y, (t >= self.pulseStart) & (t < self.pulseStart + self.Twidth))]


class SampleTrigger(BooleanSource):
    """y = sample(startTime, period): true at each tick startTime + k period, false in
    between (Modelica.Blocks.Sources.SampleTrigger)."""

    period = ac.Parameter(0.01, unit="s", min=0, description="sample period")
    startTime = ac.Parameter(0.0, unit="s", description="time instant of first sample trigger")

    def equations(self):
        return [ac.Eq(self.y, ac.sample(self.startTime, self.period))]


class BooleanTable(BooleanSource):
    """Boolean signal that changes at each time of ``table`` (Modelica.Blocks.Sources.
    BooleanTable): ``startValue`` before table[1], then its opposite until table[2], and
    so on, as the MSL builds it, a constant-segment ``CombiTimeTable`` of the values
    0/1 behind a ``RealToBoolean``.  ``table`` (strictly increasing times) and
    ``startValue`` are fixed when the block is made."""

    table = ac.Parameter((0.0, 1.0), structural=True,
                         description="time points; at each the output changes")
    startValue = ac.Parameter(False, structural=True, description="start value of y")
    shiftTime = ac.Parameter(0.0, unit="s", description="shift time of table")
    realToBoolean = RealToBoolean()

    def build(self):
        times = [float(t) for t in self.table]
        if any(b <= a for a, b in zip(times, times[1:])):
            raise ac.InvalidValue(f"BooleanTable: the times of table {times} are not "
                                  "strictly increasing")
        first = 1.0 if self.startValue else 0.0
        if times:
            rows = [(times[0], first)] + [(t, (first + i + 1) % 2) for i, t in
                                          enumerate(times)]
        else:
            rows = [(0.0, first)]
        rows.append((rows[-1][0] + 1.0, rows[-1][1]))     # held beyond the last time
        self.combiTimeTable = CombiTimeTable(table=rows, columns=[2],
                                             smoothness="constant", extrapolation="hold",
                                             startTime=float("-inf"),
                                             shiftTime=ac.ref("shiftTime"))

    def equations(self):
        return [ac.connect(self.combiTimeTable.y[0], self.realToBoolean.u),
                ac.connect(self.realToBoolean.y, self.y)]


class BooleanExpression(BooleanSource):
    """A Boolean output given by an equation of the enclosing model,
    ``ac.Eq(self.booleanExpression.y, self.pulse.y & self.step.y)``
    (Modelica.Blocks.Sources.BooleanExpression, whose ``y`` is bound to the expression)."""


class RadioButtonSource(ac.Component):
    """Boolean output that a button turns on at the times of ``buttonTimeTable`` and any of
    the ``reset`` inputs turns off, one event later (Modelica.Blocks.Sources.
    RadioButtonSource):

        pre_reset = pre(reset),   when pre_reset: on = false,
        when change(table.y): on = true   (the later assignment wins at one instant)

    ``nReset`` reset inputs (the MSL binds ``reset={other.on}``: connect them).
    """

    buttonTimeTable = ac.Parameter((0.0, 1.0), structural=True,
                                   description="time instants where button is pressed")
    nReset = ac.Parameter(1, structural=True, min=0, description="number of reset inputs")
    on = BooleanOutput()

    def build(self):
        self.table = BooleanTable(table=tuple(self.buttonTimeTable))
        self.reset = [BooleanInput() for _ in range(int(self.nReset))]
        self.pre_reset = [_Flag() for _ in self.reset]

    def equations(self):
        pressed = ac.change(self.table.y)
        return [*(ac.Eq(flag.b, ac.pre(port)) for flag, port in
                  zip(self.pre_reset, self.reset)),
                ac.when([*(flag.b for flag in self.pre_reset), pressed],
                        ac.assign(self.on, ac.if_else(pressed, True, False)))]


class _Flag(ac.Component):
    """One Boolean of a block's vector (``pre_reset[i]``)."""

    b = ac.Variable(type=bool, description="value")
