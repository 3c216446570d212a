"""Modelica.Blocks.Examples.BooleanNetwork1 and IntegerNetwork1 (MSL v4.0.0): the blocks
of MathBoolean and MathInteger in small networks.

The MSL's vector inputs ``u[1] ... u[nu]`` are ``u[0] ... u[nu-1]`` here (``MSLNames``
maps the reference's names).
"""
import acausal as ac
from acausal.library.blocks import math_boolean as mb
from acausal.library.blocks import math_integer as mi
from acausal.library.blocks.boolean_sources import BooleanPulse, BooleanStep, BooleanTable, \
    SampleTrigger
from acausal.library.blocks.conversions import RealToInteger
from acausal.library.blocks.integer_sources import IntegerConstant, IntegerStep
from acausal.library.blocks.interaction import BooleanValue, IntegerValue
from acausal.library.blocks.logical import RSFlipFlop
from acausal.library.blocks.sources import Sine

from . import MSLNames

__all__ = ["BooleanNetwork1", "IntegerNetwork1"]


class BooleanNetwork1(ac.Component):
    """Pulses and a step through And, Or, Xor, Nand, Nor, Not; edges, an on-delay, a
    multi-switch, a triggered counter and an RS flip-flop set and reset by triggers."""

    msl_name = "Modelica.Blocks.Examples.BooleanNetwork1"
    stop_time = 10.0
    tolerance = 1e-6
    msl_signals = MSLNames()

    showValue = BooleanValue()
    and1 = mb.And(nu=3)
    booleanPulse1 = BooleanPulse(width=20.0, period=1.0)
    booleanPulse2 = BooleanPulse(period=1.0, width=80.0)
    booleanStep = BooleanStep(startTime=1.5)
    or1 = mb.Or(nu=2)
    xor1 = mb.Xor(nu=2)
    showValue2 = BooleanValue()
    showValue3 = BooleanValue()
    nand1 = mb.Nand(nu=2)
    or2 = mb.Nor(nu=2)
    showValue4 = BooleanValue()
    nor1 = mb.Not()
    onDelay = mb.OnDelay(delayTime=1.0)
    rising = mb.RisingEdge()
    set1 = mb.MultiSwitch(nu=2, expr=(False, True))
    falling = mb.FallingEdge()
    booleanTable = BooleanTable(table=(2.0, 4.0, 6.0, 6.5, 7.0, 9.0, 11.0))
    changing = mb.ChangingEdge()
    triggeredAdd = mi.TriggeredAdd()
    integerConstant = IntegerConstant(k=2)
    showValue1 = IntegerValue()
    showValue5 = BooleanValue()
    showValue6 = BooleanValue()
    rSFlipFlop = RSFlipFlop()
    sampleTriggerSet = SampleTrigger(period=0.5, startTime=0.0)
    sampleTriggerReset = SampleTrigger(period=0.5, startTime=0.3)

    def equations(self):
        c = ac.connect
        return [c(self.booleanPulse1.y, self.and1.u[0]),
                c(self.booleanStep.y, self.and1.u[1]),
                c(self.booleanPulse2.y, self.and1.u[2]),
                c(self.and1.y, self.or1.u[0]),
                c(self.booleanPulse2.y, self.or1.u[1]),
                c(self.or1.y, self.xor1.u[0]),
                c(self.booleanPulse2.y, self.xor1.u[1]),
                c(self.and1.y, self.showValue.activePort),
                c(self.or1.y, self.showValue2.activePort),
                c(self.xor1.y, self.showValue3.activePort),
                c(self.xor1.y, self.nand1.u[0]),
                c(self.booleanPulse2.y, self.nand1.u[1]),
                c(self.nand1.y, self.or2.u[0]),
                c(self.booleanPulse2.y, self.or2.u[1]),
                c(self.or2.y, self.nor1.u),
                c(self.nor1.y, self.showValue4.activePort),
                c(self.booleanPulse2.y, self.rising.u),
                c(self.rising.y, self.set1.u[0]),
                c(self.falling.y, self.set1.u[1]),
                c(self.booleanPulse2.y, self.falling.u),
                c(self.booleanTable.y, self.onDelay.u),
                c(self.booleanPulse2.y, self.changing.u),
                c(self.integerConstant.y, self.triggeredAdd.u),
                c(self.changing.y, self.triggeredAdd.trigger),
                c(self.triggeredAdd.y, self.showValue1.numberPort),
                c(self.set1.y, self.showValue5.activePort),
                c(self.onDelay.y, self.showValue6.activePort),
                c(self.sampleTriggerSet.y, self.rSFlipFlop.S),
                c(self.sampleTriggerReset.y, self.rSFlipFlop.R)]


class IntegerNetwork1(ac.Component):
    """A rounded sine, a step and a constant summed and multiplied; a triggered counter
    and a multi-switch driven by Boolean pulses."""

    msl_name = "Modelica.Blocks.Examples.IntegerNetwork1"
    stop_time = 10.0
    tolerance = 1e-6

    sum = mi.Sum(nu=3)
    sine = Sine(amplitude=3.0, f=0.1)
    realToInteger = RealToInteger()
    integerStep = IntegerStep(height=3, startTime=2.0)
    integerConstant = IntegerConstant(k=1)
    showValue = IntegerValue()
    product = mi.Product(nu=2)
    showValue1 = IntegerValue()
    triggeredAdd = mi.TriggeredAdd(use_reset=False, use_set=False)
    booleanPulse1 = BooleanPulse(period=1.0)
    showValue2 = IntegerValue()
    multiSwitch1 = mi.MultiSwitch(nu=2, expr=(4, 6), y_default=2, use_pre_as_default=False)
    booleanPulse2 = BooleanPulse(period=2.0, width=80.0)
    showValue3 = IntegerValue()

    def equations(self):
        c = ac.connect
        return [c(self.sine.y, self.realToInteger.u),
                c(self.realToInteger.y, self.sum.u[0]),
                c(self.integerStep.y, self.sum.u[1]),
                c(self.integerConstant.y, self.sum.u[2]),
                c(self.sum.y, self.showValue.numberPort),
                c(self.sum.y, self.product.u[0]),
                c(self.integerStep.y, self.product.u[1]),
                c(self.product.y, self.showValue1.numberPort),
                c(self.integerConstant.y, self.triggeredAdd.u),
                c(self.booleanPulse1.y, self.triggeredAdd.trigger),
                c(self.triggeredAdd.y, self.showValue2.numberPort),
                c(self.booleanPulse1.y, self.multiSwitch1.u[0]),
                c(self.booleanPulse2.y, self.multiSwitch1.u[1]),
                c(self.multiSwitch1.y, self.showValue3.numberPort)]
