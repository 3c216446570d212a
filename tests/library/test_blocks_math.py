"""Math blocks and signal sources (Add3, Division, Abs, Sqrt, Min, Max, Cosine, ExpSine,
Trapezoid), evaluated against numpy on the same time grid."""
import numpy as np
import pytest

import acausal as ac
from acausal.library.blocks import (Abs, Add3, Cosine, Division, ExpSine, Max, Min, Ramp,
                                    Sine, Sqrt, Trapezoid)


class Signals(ac.Component):
    sine = Sine(amplitude=2.0, f=1.5, offset=0.5)
    cosine = Cosine(amplitude=1.5, f=0.7, phase=0.3, startTime=0.2)
    ramp = Ramp(height=3.0, duration=2.0, offset=1.0)
    exp_sine = ExpSine(amplitude=2.0, f=2.0, damping=1.5, phase=0.1, offset=-0.2,
                       startTime=0.4)
    add3 = Add3(k1=2.0, k2=-1.0, k3=0.5)
    div = Division()
    mag = Abs()
    root = Sqrt()
    low = Min()
    high = Max()

    def equations(self):
        return [ac.connect(self.sine.y, self.add3.u1, self.div.u1, self.mag.u, self.low.u1,
                           self.high.u1),
                ac.connect(self.cosine.y, self.add3.u2, self.low.u2, self.high.u2),
                ac.connect(self.ramp.y, self.add3.u3, self.div.u2, self.root.u)]


def test_math_blocks_and_sources_against_numpy():
    t = np.linspace(0, 2, 81)
    res = ac.simulate(Signals(), t_end=2.0, t_eval=t)
    sine = 0.5 + 2.0 * np.sin(2 * np.pi * 1.5 * t)
    cosine = np.where(t >= 0.2, 1.5 * np.cos(2 * np.pi * 0.7 * (t - 0.2) + 0.3), 0.0)
    ramp = 1.0 + 3.0 * np.minimum(t / 2.0, 1.0)
    tau = t - 0.4
    exp_sine = -0.2 + np.where(tau >= 0, 2.0 * np.exp(-1.5 * tau)
                               * np.sin(2 * np.pi * 2.0 * tau + 0.1), 0.0)
    expected = {"cosine.y": cosine, "exp_sine.y": exp_sine,
                "add3.y": 2.0 * sine - cosine + 0.5 * ramp, "div.y": sine / ramp,
                "mag.y": np.abs(sine), "root.y": np.sqrt(ramp),
                "low.y": np.minimum(sine, cosine), "high.y": np.maximum(sine, cosine)}
    for name, value in expected.items():
        got = res[f"{name}.signal"]
        assert np.max(np.abs(got - value)) < 1e-10 * (1 + np.max(np.abs(value))), name


class Trapezoids(ac.Component):
    wave = Trapezoid(amplitude=2.0, rising=0.1, width=0.25, falling=0.2, period=0.7,
                     offset=0.5, startTime=0.15)


def test_trapezoid_against_numpy():
    t = np.linspace(0, 3, 301)
    res = ac.simulate(Trapezoids(), t_end=3.0, t_eval=t)
    phase = np.mod(t - 0.15, 0.7)
    shape = np.select([phase < 0.1, phase < 0.35, phase < 0.55],
                      [2.0 * phase / 0.1, 2.0, 2.0 * (0.55 - phase) / 0.2], 0.0)
    expected = 0.5 + np.where(t >= 0.15, shape, 0.0)
    assert np.max(np.abs(res["wave.y.signal"] - expected)) < 1e-9 * 2.5
    with pytest.raises(ac.ModelError, match="rising must be > 0"):
        ac.compile(Trapezoids(wave={"rising": 0.0}))


def test_real_network_blocks_against_their_formulas():
    """RealNetwork1's Math blocks on its signals: sine 3 sin(0.2 pi t), a step of 3 at
    2 s, pulses of period 1 s (50 %) and 2 s (80 %) choosing 4, 6 or 2."""
    from acausal.library.blocks.examples.msl.networks import RealNetwork1

    t = np.linspace(0, 10, 1001)
    res = ac.simulate(RealNetwork1(), t_end=10, rtol=1e-9, t_eval=t)
    sine, step = 3 * np.sin(0.2 * np.pi * t), np.where(t >= 2, 3.0, 0.0)
    add, product = sine + step, step * 1.0
    assert np.max(np.abs(res["add.y"] - add)) < 1e-12
    assert np.max(np.abs(res["showValue1.showNumber"] - product)) == 0
    assert np.max(np.abs(res["linearDependency1.y"] - (1 + 2 * add + 3 * product))) < 1e-11
    assert np.max(np.abs(res["minMax.yMax"] - np.maximum(add, product))) < 1e-12
    assert np.max(np.abs(res["minMax.yMin"] - np.minimum(add, product))) < 1e-12
    # away from the pulses' edges: the first true input's value, else y_default
    p1, p2 = np.mod(t, 1.0) < 0.5, np.mod(t, 2.0) < 1.6
    edge = (np.abs(t - np.round(t * 2) / 2) < 1e-9) | (np.abs(t - np.round(t / 2) * 2 - 1.6)
                                                        < 1e-9)
    chosen = np.where(p1, 4.0, np.where(p2, 6.0, 2.0))
    assert np.array_equal(res["showValue3.showNumber"][~edge], chosen[~edge])
    with pytest.raises(ac.InvalidValue, match="expr has 1 values for nu = 2"):
        from acausal.library.blocks import MultiSwitch
        MultiSwitch(nu=2, expr=(1.0,))
