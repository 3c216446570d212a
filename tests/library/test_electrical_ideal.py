"""Ideal elements and operational amplifiers of Modelica.Electrical.Analog (MSL v4.0.0)
against closed forms: the controlled switches' Ron/Goff lines, the ideal transformer's
ratio and magnetizing current, the op-amps' gains and limits, the detailed op-amp's
slew rate."""
import math

import numpy as np
import pytest

import acausal as ac
from acausal.library import electrical as el
from acausal.library.blocks import Sine


class SwitchBench(ac.Component):
    """A 10 V source through 1 Ohm into a controlled switch; the control pin follows a
    1 V, 1 Hz sine (closed while above the level 0.5 V)."""

    def __init__(self, switch, **mods):
        super().__init__(**mods)
        self.src = el.ConstantVoltage(V=10.0)
        self.R = el.Resistor(R=1.0)
        self.sw = switch
        self.ctl = el.SineVoltage(V=1.0, f=1.0)
        self.gnd = el.Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.R.p), ac.connect(self.R.n, self.sw.p),
                ac.connect(self.ctl.p, self.sw.control),
                ac.connect(self.sw.n, self.src.n, self.ctl.n, self.gnd.p)]


@pytest.mark.parametrize("cls, closed_above", [(el.ControlledIdealClosingSwitch, True),
                                               (el.ControlledIdealOpeningSwitch, False)])
def test_controlled_switch_lies_on_its_ron_and_goff_lines(cls, closed_above):
    Ron, Goff = 1e-3, 1e-4
    t = np.linspace(0.01, 0.99, 99)
    res = ac.simulate(SwitchBench(cls(Ron=Ron, Goff=Goff)), t_end=1.0, rtol=1e-9, t_eval=t)
    ctl, v, i = res["ctl.v"], res["sw.v"], res["sw.i"]
    closed = (ctl > 0.5) == closed_above
    away = np.abs(ctl - 0.5) > 1e-3                     # not at the switching instants
    assert np.allclose(v[closed & away], Ron * i[closed & away], rtol=1e-9)
    assert np.allclose(i[~closed & away], Goff * v[~closed & away], rtol=1e-9)
    # closed: 10 V over 1 + Ron Ohm; open: 10 V over 1 + 1/Goff
    assert np.allclose(i[closed & away], 10.0 / (1.0 + Ron), rtol=1e-9)
    assert np.allclose(i[~closed & away], 10.0 / (1.0 + 1.0 / Goff), rtol=1e-9)
    assert np.max(np.abs(res["sw.control.i"])) == 0.0
    assert np.allclose(res["sw.LossPower"], v * i, rtol=1e-12)


class TwoWayBench(ac.Component):
    """p fed from 10 V through 1 Ohm; n1 and n2 to ground through 1 Ohm and 2 Ohm."""

    src = el.ConstantVoltage(V=10.0)
    R = el.Resistor(R=1.0)
    sw = el.ControlledIdealTwoWaySwitch(Ron=1e-6, Goff=1e-7)
    R1 = el.Resistor(R=1.0)
    R2 = el.Resistor(R=2.0)
    ctl = el.SineVoltage(V=1.0, f=1.0)
    gnd = el.Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.R.p), ac.connect(self.R.n, self.sw.p),
                ac.connect(self.sw.n1, self.R1.p), ac.connect(self.sw.n2, self.R2.p),
                ac.connect(self.ctl.p, self.sw.control),
                ac.connect(self.R1.n, self.R2.n, self.src.n, self.ctl.n, self.gnd.p)]


def test_two_way_switch_routes_p_to_n2_above_the_level():
    t = np.array([0.02, 0.25, 0.6, 0.8])           # control 0.13, 1.0, -0.59, -0.95 V
    res = ac.simulate(TwoWayBench(), t_end=1.0, rtol=1e-9, t_eval=t)
    on = res["ctl.v"] > 0.5
    assert list(on) == [False, True, False, False]
    assert np.allclose(res["R2.i"][on], 10.0 / 3.0, rtol=1e-5)
    assert np.allclose(res["R1.i"][~on], 10.0 / 2.0, rtol=1e-5)
    assert np.max(np.abs(res["R1.i"][on])) < 1e-5 and np.max(np.abs(res["R2.i"][~on])) < 1e-5


class IntermediateBench(ac.Component):
    """p1 at 10 V and p2 at 4 V through 1 Ohm each; n1 and n2 to ground through 1 Ohm
    and 2 Ohm: crossed above the level."""

    s1 = el.ConstantVoltage(V=10.0)
    s2 = el.ConstantVoltage(V=4.0)
    Ra = el.Resistor(R=1.0)
    Rb = el.Resistor(R=1.0)
    sw = el.ControlledIdealIntermediateSwitch(Ron=1e-6, Goff=1e-7)
    R1 = el.Resistor(R=1.0)
    R2 = el.Resistor(R=2.0)
    ctl = el.SineVoltage(V=1.0, f=1.0)
    gnd = el.Ground()

    def equations(self):
        return [ac.connect(self.s1.p, self.Ra.p), ac.connect(self.Ra.n, self.sw.p1),
                ac.connect(self.s2.p, self.Rb.p), ac.connect(self.Rb.n, self.sw.p2),
                ac.connect(self.sw.n1, self.R1.p), ac.connect(self.sw.n2, self.R2.p),
                ac.connect(self.ctl.p, self.sw.control),
                ac.connect(self.R1.n, self.R2.n, self.s1.n, self.s2.n, self.ctl.n,
                           self.gnd.p)]


def test_intermediate_switch_crosses_above_the_level():
    res = ac.simulate(IntermediateBench(), t_end=1.0, rtol=1e-9, t_eval=[0.02, 0.25])
    straight, crossed = 0, 1
    # straight: 10 V -> R1 (2 Ohm in all), 4 V -> R2 (3 Ohm); crossed: 10 V -> R2, 4 V -> R1
    assert res["R1.i"][straight] == pytest.approx(5.0, rel=1e-5)
    assert res["R2.i"][straight] == pytest.approx(4.0 / 3.0, rel=1e-5)
    assert res["R1.i"][crossed] == pytest.approx(2.0, rel=1e-5)
    assert res["R2.i"][crossed] == pytest.approx(10.0 / 3.0, rel=1e-5)


class MagnetizedTransformer(ac.Component):
    """A 10 V, 50 Hz cosine on the primary of an ideal transformer (n = 4) with
    magnetization, its secondary loaded by 2 Ohm."""

    src = el.CosineVoltage(V=10.0, f=50.0)
    tr = el.IdealTransformer(n=4.0, considerMagnetization=True, Lm1=0.1,
                             im1={"start": 0.0, "fixed": True})
    load = el.Resistor(R=2.0)
    g1 = el.Ground()
    g2 = el.Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.tr.p1), ac.connect(self.src.n, self.tr.n1, self.g1.p),
                ac.connect(self.tr.p2, self.load.p), ac.connect(self.tr.n2, self.load.n, self.g2.p)]


class PlainTransformer(MagnetizedTransformer):
    """The same without magnetization."""

    tr = el.IdealTransformer(n=4.0)


def test_ideal_transformer_ratio_and_magnetizing_current():
    t = np.linspace(0, 0.04, 81)
    res = ac.simulate(MagnetizedTransformer(), t_end=0.04, rtol=1e-10, t_eval=t)
    w = 2 * math.pi * 50.0
    v1 = 10.0 * np.cos(w * t)
    assert np.allclose(res["tr.v2"], v1 / 4.0, atol=1e-9)             # v1 = n v2
    im1 = 10.0 * np.sin(w * t) / (w * 0.1)                           # v1 = Lm1 der(im1)
    # an integral over two periods: its error grows with the run (1e-7, 1e3 rtol)
    assert np.max(np.abs(res["tr.im1"] - im1)) < 1e-7 * np.max(np.abs(im1))
    # i1 = im1 - i2/n, i2 = -v2/R (the load current leaves p2)
    assert np.max(np.abs(res["tr.i1"] - (im1 + v1 / 4.0 / 2.0 / 4.0))) < 1e-8
    plain = ac.simulate(PlainTransformer(), t_end=0.04, rtol=1e-10, t_eval=t)
    assert np.allclose(plain["tr.v1"] * plain["tr.i1"] + plain["tr.v2"] * plain["tr.i2"],
                       0.0, atol=1e-9)                                # lossless


class InvertingBench(ac.Component):
    """An inverting amplifier R2/R1 = 2 around ``amp`` (made in __init__), driven by a
    12 V, 2 Hz sine; +-15 V pins where the op-amp has them."""

    def __init__(self, amp, kind, **mods):
        super().__init__(**mods)
        self.amp, self.kind = amp, kind
        self.src = el.SineVoltage(V=12.0, f=2.0)
        self.R1 = el.Resistor(R=1e3)
        self.R2 = el.Resistor(R=2e3)
        self.gnd = el.Ground()
        if kind == "pins":
            self.vp = el.ConstantVoltage(V=15.0)
            self.vn = el.ConstantVoltage(V=-15.0)

    def equations(self):
        a = self.amp
        inp, inn, out = ((a.p1, a.n1, a.p2) if self.kind == "norator" else
                         (a.in_p, a.in_n, a.out))
        eqs = [ac.connect(self.src.p, self.R1.p), ac.connect(self.R1.n, self.R2.p, inn),
               ac.connect(self.R2.n, out),
               ac.connect(self.src.n, inp, self.gnd.p)]
        if self.kind == "norator":
            eqs.append(ac.connect(a.n2, self.gnd.p))
        if self.kind == "pins":
            eqs += [ac.connect(self.vp.p, a.VMax), ac.connect(self.vn.p, a.VMin),
                    ac.connect(self.vp.n, self.vn.n, self.gnd.p)]
        return eqs


T_AMP = np.linspace(0.0, 0.5, 101)
V_IN = 12.0 * np.sin(2 * math.pi * 2.0 * T_AMP)


def test_ideal_op_amp_norator_nullator_gain():
    res = ac.simulate(InvertingBench(el.IdealOpAmp(), "norator"), t_end=0.5, rtol=1e-10,
                      t_eval=T_AMP)
    assert np.max(np.abs(res["amp.p2.v"] + 2 * V_IN)) < 1e-8 * 24
    assert np.max(np.abs(res["amp.v1"])) < 1e-9


def test_ideal_op_amp_limited_clips_at_its_supply_pins():
    res = ac.simulate(InvertingBench(el.IdealOpAmpLimited(), "pins"), t_end=0.5, rtol=1e-10,
                      t_eval=T_AMP)
    out = res["amp.out.v"]
    assert np.max(np.abs(out - np.clip(-2 * V_IN, -15.0, 15.0))) < 1e-6 * 15
    assert np.max(np.abs(res["amp.VMax.i"])) == 0.0


def test_idealized_op_amp_limited_finite_gain_and_supply_power():
    """Between the limits out = -2 vin (1 + 3/V0)^-1 (finite gain V0); clipped at
    +-15 V; with useSupply the supply pins carry i_s = p_s/(vps - vns)."""
    V0 = 15000.0
    res = ac.simulate(SuppliedIdealized(), t_end=0.5, rtol=1e-10, t_eval=T_AMP)
    out = res["amp.out.v"]
    linear = -2 * V_IN / (1 + 3 / V0)
    assert np.max(np.abs(out - np.clip(linear, -15.0, 15.0))) < 1e-6 * 15
    # the supply pins take what the output delivers (p_in = 0): s_p.i v_p + s_n.i v_n =
    # -p_out, so the whole power balance of the op-amp is zero
    balance = (res["amp.s_p.i"] * 15.0 + res["amp.s_n.i"] * (-15.0)
               + res["amp.out.v"] * res["amp.out.i"])
    assert np.max(np.abs(balance)) < 1e-9 * np.max(np.abs(res["amp.p_out"]))


class SuppliedIdealized(ac.Component):
    """The inverting amplifier around an IdealizedOpAmpLimited fed from +-15 V pins."""

    src = el.SineVoltage(V=12.0, f=2.0)
    R1 = el.Resistor(R=1e3)
    R2 = el.Resistor(R=2e3)
    amp = el.IdealizedOpAmpLimited(useSupply=True)
    vp = el.ConstantVoltage(V=15.0)
    vn = el.ConstantVoltage(V=-15.0)
    gnd = el.Ground()

    def equations(self):
        a = self.amp
        return [ac.connect(self.src.p, self.R1.p), ac.connect(self.R1.n, self.R2.p, a.in_n),
                ac.connect(self.R2.n, a.out), ac.connect(self.vp.p, a.s_p),
                ac.connect(self.vn.p, a.s_n),
                ac.connect(self.src.n, a.in_p, self.vp.n, self.vn.n, self.gnd.p)]


def test_simple_op_amp_saturates_smoothly():
    """out = (VMax + VMin)/2 + |Slope| vin/(1 + |Slope| |f vin|), f = 2/(VMax - VMin)."""
    res = ac.simulate(InvertingBench(el.OpAmp(Slope=1e4), "pins"), t_end=0.5, rtol=1e-10,
                      t_eval=T_AMP)
    vin, out = res["amp.vin"], res["amp.out.v"]
    law = 1e4 * vin / (1 + 1e4 * np.abs(vin / 15.0))
    assert np.max(np.abs(out - law)) < 1e-9 * 15
    assert out.max() > 14.9 and out.min() < -14.9 and np.abs(out).max() < 15


class DetailedFollower(ac.Component):
    """OpAmpDetailed as a voltage follower on +-15 V, stepped by 10 V at 10 us."""

    amp = el.OpAmpDetailed()
    step = el.StepVoltage(V=10.0, startTime=10e-6)
    vp = el.ConstantVoltage(V=15.0)
    vn = el.ConstantVoltage(V=-15.0)
    load = el.Resistor(R=1e4)
    gnd = el.Ground()

    def initial_equations(self):
        a = self.amp
        return [ac.Eq(a.q_fp1, 0), ac.Eq(a.q_fr1, 0), ac.Eq(a.q_fr2, 0), ac.Eq(a.q_fr3, 0),
                ac.Eq(a.v_in, 0)]

    def equations(self):
        a = self.amp
        return [ac.connect(self.step.p, a.p), ac.connect(a.outp, a.m, self.load.p),
                ac.connect(self.vp.p, a.p_supply), ac.connect(self.vn.p, a.m_supply),
                ac.connect(self.step.n, self.vp.n, self.vn.n, self.load.n, self.gnd.p)]


def test_detailed_op_amp_slews_at_its_slew_rate_and_settles():
    t = np.linspace(0.0, 60e-6, 601)
    res = ac.simulate(DetailedFollower(), t_end=60e-6, rtol=1e-8, t_eval=t)
    out, source = res["amp.v_out"], res["amp.v_source"]
    slope = np.diff(source) / np.diff(t)
    # the internal source rises at the slew rate sr_p = 0.5 V/us while the error is
    # large (the output follows it through Rout = 75 Ohm)
    slewing = (t[1:] > 12e-6) & (out[1:] < 8.0)
    assert np.allclose(slope[slewing], 0.5e6, rtol=1e-6)
    assert slope.max() < 0.5e6 * (1 + 1e-6)
    # settled: the follower's output is the input within the offset Vos = 1 mV
    # and the gain error 1/Avd0 (Avd0 = 106 dB)
    assert out[-1] == pytest.approx(10.0, abs=2e-3)
