"""The Boolean and Integer blocks (library/blocks: logical, math_boolean, math_integer,
boolean_sources, integer_sources, conversions) against their truth tables and closed
forms."""
import math

import numpy as np
import pytest

import acausal as ac
from acausal.library.blocks import logical as lg
from acausal.library.blocks import math_boolean as mb
from acausal.library.blocks import math_integer as mi
from acausal.library.blocks.boolean_sources import (BooleanConstant, BooleanPulse,
                                                    BooleanStep, BooleanTable, SampleTrigger)
from acausal.library.blocks.conversions import (BooleanToInteger, BooleanToReal,
                                                IntegerToBoolean, IntegerToReal,
                                                RealToBoolean, RealToInteger)
from acausal.library.blocks.integer_sources import IntegerConstant, IntegerStep, IntegerTable
from acausal.library.blocks.sources import Ramp, Sine

# u1 toggles at 1, 2, 3 s, u2 at 2 s: the four input pairs on [0,1), [1,2), [2,3), [3,4)
T = np.array([0.5, 1.5, 2.5, 3.5])
U1 = np.array([False, True, False, True])
U2 = np.array([False, False, True, True])


def _two_input(block):
    class TwoInputs(ac.Component):
        a = BooleanTable(table=(1.0, 2.0, 3.0))
        b = BooleanTable(table=(2.0,))
        g = block

        def equations(self):
            return [ac.connect(self.a.y, self.g.u1), ac.connect(self.b.y, self.g.u2)]
    return TwoInputs()


@pytest.mark.parametrize("block, table", [
    (lg.And, U1 & U2), (lg.Or, U1 | U2), (lg.Xor, U1 ^ U2), (lg.Nand, ~(U1 & U2)),
    (lg.Nor, ~(U1 | U2))])
def test_two_input_gates_follow_their_truth_tables(block, table):
    res = ac.simulate(_two_input(block()), t_end=4.0, t_eval=T)
    assert list(res["g.y"]) == list(table)


@pytest.mark.parametrize("block, table", [
    (mb.And, U1 & U2), (mb.Or, U1 | U2), (mb.Xor, U1 ^ U2), (mb.Nand, ~(U1 & U2)),
    (mb.Nor, ~(U1 | U2))])
def test_vector_gates_follow_their_truth_tables(block, table):
    class Vector(ac.Component):
        a = BooleanTable(table=(1.0, 2.0, 3.0))
        b = BooleanTable(table=(2.0,))
        g = block(nu=2)

        def equations(self):
            return [ac.connect(self.a.y, self.g.u[0]), ac.connect(self.b.y, self.g.u[1])]
    res = ac.simulate(Vector(), t_end=4.0, t_eval=T)
    assert list(res["g.y"]) == list(table)


def test_xor_of_three_is_true_for_exactly_one():
    class Three(ac.Component):
        a = BooleanTable(table=(1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0))
        b = BooleanTable(table=(2.0, 4.0, 6.0))
        c = BooleanTable(table=(4.0,))
        g = mb.Xor(nu=3)

        def equations(self):
            return [ac.connect(self.a.y, self.g.u[0]), ac.connect(self.b.y, self.g.u[1]),
                    ac.connect(self.c.y, self.g.u[2])]
    t = np.arange(0.5, 8.0, 1.0)
    res = ac.simulate(Three(), t_end=8.0, t_eval=t)
    k = np.arange(8)
    ones = (k & 1) + ((k >> 1) & 1) + ((k >> 2) & 1)
    assert list(res["g.y"]) == list(ones == 1)


def test_sources_switch_at_their_times():
    class Sources(ac.Component):
        step = BooleanStep(startTime=1.2)
        inverse = BooleanStep(startTime=1.2, startValue=True)
        const = BooleanConstant(k=False)
        pulse = BooleanPulse(width=30.0, period=1.0, startTime=0.25)
        tick = SampleTrigger(period=0.5)
        istep = IntegerStep(height=3, offset=-1, startTime=2.0)
        iconst = IntegerConstant(k=7)
        itab = IntegerTable(table=((0, 1), (1.5, 4), (2.5, -2)))
    t = np.linspace(0.0, 3.0, 61)
    res = ac.simulate(Sources(), t_end=3.0, t_eval=t)
    assert list(res["step.y"]) == list(t >= 1.2)
    assert list(res["inverse.y"]) == list(t < 1.2)
    assert not res["const.y"].any() and not res["tick.y"].any()
    phase = (t - 0.25) % 1.0
    pulse = (t >= 0.25) & (phase < 0.3 - 1e-12)
    assert list(res["pulse.y"]) == list(pulse)
    assert list(res["istep.y"]) == list(np.where(t < 2.0, -1, 2))
    assert list(res["iconst.y"]) == [7] * len(t)
    assert list(res["itab.y"]) == list(np.where(t < 1.5, 1, np.where(t < 2.5, 4, -2)))


def test_conversions_between_the_three_types():
    class Conversions(ac.Component):
        ramp = Ramp(height=4.0, duration=4.0, offset=-2.0)
        toInt = RealToInteger()
        toBool = RealToBoolean(threshold=0.5)
        intToBool = IntegerToBoolean(threshold=1)
        boolToReal = BooleanToReal(realTrue=3.0, realFalse=-1.0)
        boolToInt = BooleanToInteger(integerTrue=5, integerFalse=2)
        intToReal = IntegerToReal()

        def equations(self):
            c = ac.connect
            return [c(self.ramp.y, self.toInt.u), c(self.ramp.y, self.toBool.u),
                    c(self.toInt.y, self.intToBool.u), c(self.toBool.y, self.boolToReal.u),
                    c(self.toBool.y, self.boolToInt.u), c(self.toInt.y, self.intToReal.u)]
    t = np.linspace(0.05, 3.95, 40)
    res = ac.simulate(Conversions(), t_end=4.0, t_eval=t)
    u = t - 2.0
    rounded = np.where(u > 0, np.floor(u + 0.5), np.ceil(u - 0.5)).astype(int)
    assert list(res["toInt.y"]) == list(rounded)
    assert list(res["toBool.y"]) == list(u >= 0.5)
    assert list(res["intToBool.y"]) == list(rounded >= 1)
    assert np.array_equal(res["boolToReal.y"], np.where(u >= 0.5, 3.0, -1.0))
    assert list(res["boolToInt.y"]) == list(np.where(u >= 0.5, 5, 2))
    assert np.array_equal(res["intToReal.y"], rounded.astype(float))
    assert res["intToReal.y"].dtype == float


class Timed(ac.Component):
    """u true on [1, 2) and [3, 4.5)."""

    u = BooleanTable(table=(1.0, 2.0, 3.0, 4.5))
    timer = lg.Timer()
    trapezoid = lg.TriggeredTrapezoid(amplitude=2.0, rising=0.5, falling=0.25, offset=1.0)
    delay = mb.OnDelay(delayTime=0.4)
    edge = lg.Edge()
    falling = lg.FallingEdge()
    count = mi.TriggeredAdd()
    one = IntegerConstant(k=1)
    x = ac.Variable(start=0.0, fixed=True)

    def equations(self):
        c = ac.connect
        return [c(self.u.y, self.timer.u), c(self.u.y, self.trapezoid.u),
                c(self.u.y, self.delay.u), c(self.u.y, self.edge.u),
                c(self.u.y, self.falling.u), c(self.u.y, self.count.trigger),
                c(self.one.y, self.count.u), ac.Eq(ac.der(self.x), 1.0)]


def test_timer_trapezoid_on_delay_and_counter_against_their_closed_forms():
    t = np.linspace(0.0, 5.0, 101)
    res = ac.simulate(Timed(), t_end=5.0, t_eval=t, rtol=1e-9)
    on = ((t >= 1) & (t < 2)) | ((t >= 3) & (t < 4.5))
    entry = np.where(t >= 3, 3.0, 1.0)
    assert np.allclose(res["timer.y"], np.where(on, t - entry, 0.0), atol=1e-12)
    # ramps of slope 2/0.5 up from each rising edge, 2/0.25 down from each falling edge
    up = lambda t0: np.clip(1.0 + 4.0 * (t - t0), 1.0, 3.0)
    down = lambda t0: np.clip(3.0 - 8.0 * (t - t0), 1.0, 3.0)
    trap = np.where(t < 1, 1.0, np.where(t < 2, up(1.0), np.where(t < 3, down(2.0),
                    np.where(t < 4.5, up(3.0), down(4.5)))))
    assert np.max(np.abs(res["trapezoid.y"] - trap)) < 1e-9
    delayed = ((t >= 1.4) & (t < 2)) | ((t >= 3.4) & (t < 4.5))
    assert list(res["delay.y"]) == list(delayed)
    # edges are true only at their instants
    assert not res["edge.y"].any() and not res["falling.y"].any()
    assert list(res["count.y"]) == list(np.where(t < 1, 0, np.where(t < 3, 1, 2)))


def test_hysteresis_and_on_off_controller_switch_at_their_thresholds():
    class Controllers(ac.Component):
        sine = Sine(amplitude=2.0, f=1 / (2 * math.pi))
        reference = Ramp(height=0.0, offset=0.5)
        hysteresis = lg.Hysteresis(uLow=-1.0, uHigh=1.0)
        onOff = lg.OnOffController(bandwidth=1.0)

        def equations(self):
            c = ac.connect
            return [c(self.sine.y, self.hysteresis.u), c(self.sine.y, self.onOff.u),
                    c(self.reference.y, self.onOff.reference)]
    t = np.linspace(0.0, 7.0, 141)
    res = ac.simulate(Controllers(), t_end=7.0, t_eval=t)
    s = 2 * np.sin(t)
    # hysteresis: true from 2 sin = 1 (t = pi/6) until 2 sin = -1 (t = pi + pi/6)
    hyst = ((t > math.pi / 6) & (t < 7 * math.pi / 6)) | (t > 2 * math.pi + math.pi / 6)
    assert list(res["hysteresis.y"]) == list(hyst)
    # on-off: on below 0.5 - 0.5 = 0, off above 0.5 + 0.5 = 1 (u < 0 from t = pi)
    on = ((t > math.pi) & (t < 2 * math.pi + math.pi / 6)) | (t < 0)
    assert list(res["onOff.y"]) == list(on)


def test_rs_flip_flop_sets_and_resets():
    class Flip(ac.Component):
        s = BooleanTable(table=(1.0, 1.5, 3.0, 3.5))
        r = BooleanTable(table=(2.0, 2.5))
        ff = lg.RSFlipFlop()

        def equations(self):
            return [ac.connect(self.s.y, self.ff.S), ac.connect(self.r.y, self.ff.R)]
    t = np.array([0.5, 1.2, 1.7, 2.2, 2.7, 3.2, 3.7])
    res = ac.simulate(Flip(), t_end=4.0, t_eval=t)
    q = np.array([False, True, True, False, False, True, True])
    assert list(res["ff.Q"]) == list(q)
    assert list(res["ff.QI"]) == list(~q)


def test_integer_sum_product_and_multiswitch():
    class Integers(ac.Component):
        a = IntegerStep(height=2, offset=1, startTime=1.0)
        b = IntegerConstant(k=-3)
        s = mi.Sum(nu=2, k=(2, 1))
        p = mi.Product(nu=2)
        u1 = BooleanTable(table=(1.0, 2.0))
        u2 = BooleanTable(table=(1.5, 3.0))
        sw = mi.MultiSwitch(nu=2, expr=(10, 20), y_default=-1, use_pre_as_default=False)
        hold = mi.MultiSwitch(nu=2, expr=(10, 20), y_default=-1)

        def equations(self):
            c = ac.connect
            return [c(self.a.y, self.s.u[0]), c(self.b.y, self.s.u[1]),
                    c(self.a.y, self.p.u[0]), c(self.b.y, self.p.u[1]),
                    c(self.u1.y, self.sw.u[0]), c(self.u2.y, self.sw.u[1]),
                    c(self.u1.y, self.hold.u[0]), c(self.u2.y, self.hold.u[1])]
    t = np.array([0.5, 1.2, 1.7, 2.5, 3.5])
    res = ac.simulate(Integers(), t_end=4.0, t_eval=t)
    a = np.where(t < 1, 1, 3)
    assert list(res["s.y"]) == list(2 * a - 3)
    assert list(res["p.y"]) == list(-3 * a)
    assert list(res["sw.y"]) == [-1, 10, 10, 20, -1]
    assert list(res["hold.y"]) == [-1, 10, 10, 20, 20]
