"""Sampled blocks (library/blocks/discrete.py) against hand-computed sequences and
scipy.signal.dlsim.

The blocks here are driven by signal sources only, so the models have no continuous
states and run from tick to tick: every value is a difference equation evaluated in
floating point, and the bounds are rounding-level (1e-12 of the signal).
"""
import numpy as np
import pytest
import scipy.signal as sig

import acausal as ac
from acausal.library.blocks import Constant, Ramp, Step
from acausal.library.blocks.discrete import (PI, PID, Sampler, TransferFunction, UnitDelay,
                                             ZeroOrderHold)

H, T0 = 0.1, 0.05          # sample period and first tick of the chains below
BACKENDS = ["numpy", "c"]


def _ticks(n, h=H, t0=T0):
    return t0 + h * np.arange(n)


def _close(a, b, rel=1e-12):
    a, b = np.asarray(a, float), np.asarray(b, float)
    return np.max(np.abs(a - b)) <= rel * max(1.0, np.max(np.abs(b)))


class HoldChain(ac.Component):
    """u = 1 + 2 t sampled, held and delayed; the hold and the delay are declared before
    the sampler, so only the data-flow order makes them read this tick's sample."""

    hold = ZeroOrderHold(samplePeriod=H, startTime=T0)
    delay = UnitDelay(samplePeriod=H, startTime=T0, y_start=-1.0)
    slow = ZeroOrderHold(samplePeriod=2 * H, startTime=T0)
    src = Ramp(height=20.0, duration=10.0, offset=1.0)
    smp = Sampler(samplePeriod=H, startTime=T0)

    def equations(self):
        return [ac.connect(self.src.y, self.smp.u),
                ac.connect(self.smp.y, self.hold.u, self.delay.u, self.slow.u)]


@pytest.mark.parametrize("backend", BACKENDS)
def test_sampler_hold_and_unit_delay_sequences(backend):
    n = 12
    ticks = _ticks(n)
    mid = ticks + H / 2                    # between ticks: the held values
    t_eval = np.concatenate([[0.0, 0.02], np.sort(np.concatenate([ticks, mid]))])
    res = ac.simulate(HoldChain(), t_end=float(mid[-1]), t_eval=t_eval, backend=backend)
    assert res.success, res.message
    # the k-th tick's sample, in force on [t_k, t_k+1) (results are right-continuous)
    k = np.floor((t_eval - T0) / H + 1e-9)
    sample = np.where(k >= 0, 1.0 + 2.0 * (T0 + H * k), 0.0)     # start value 0 before
    delayed = np.where(k >= 1, 1.0 + 2.0 * (T0 + H * (k - 1)), -1.0)
    k2 = np.floor((t_eval - T0) / (2 * H) + 1e-9)
    slow = np.where(k2 >= 0, 1.0 + 2.0 * (T0 + 2 * H * k2), 0.0)
    assert _close(res["smp.y.signal"], sample)
    assert _close(res["hold.y.signal"], sample)        # this tick's sample, not the last
    assert _close(res["delay.y.signal"], delayed)
    assert _close(res["slow.y.signal"], slow)
    ev = [e for e in res.events if e.kind == "when"]
    assert _close([float(e) for e in ev], ticks[:len(ev)]) and len(ev) == n


def test_a_clock_at_the_start_time_fires_at_initialization():
    """A tick at t0 fires once the initial values are found (the MSL's
    when {sample(...), initial()}): the output holds u(t0) from t0 on."""

    class AtStart(ac.Component):
        src = Ramp(height=2.0, duration=1.0, offset=3.0)
        smp = Sampler(samplePeriod=0.25)

        def equations(self):
            return [ac.connect(self.src.y, self.smp.u)]

    t = np.array([0.0, 0.1, 0.25, 0.3, 0.6])
    res = ac.simulate(AtStart(), t_end=0.6, t_eval=t)
    assert _close(res["smp.y.signal"], 3.0 + 2.0 * np.floor(t / 0.25) * 0.25)


@pytest.mark.parametrize("b, a", [([0.2, 0.1], [1.0, -1.2, 0.5]),
                                  ([1.0, -0.5, 0.25], [2.0, -0.4]),
                                  ([0.3], [1.0])])
def test_discrete_transfer_function_step_response_matches_dlsim(b, a):
    class StepTF(ac.Component):
        u = Step(height=1.5, startTime=0.0)
        tf = TransferFunction(b=b, a=a, samplePeriod=H)

        def equations(self):
            return [ac.connect(self.u.y, self.tf.u)]

    n = 15
    ticks = H * np.arange(n)
    res = ac.simulate(StepTF(), t_end=float(ticks[-1]), t_eval=ticks)
    m = max(len(a), len(b))      # coefficients of z^0, z^-1, ...: pad both to one length
    num, den = np.pad(b, (0, m - len(b))), np.pad(a, (0, m - len(a)))
    _, y = sig.dlsim((num, den, H), 1.5 * np.ones(n))
    assert _close(res["tf.y.signal"], y[:, 0])


def _pi_by_hand(e, k, Ti, Tt, h, lo, hi, pid=None):
    """The controller's difference equations, iterated in numpy (docstring of PI/PID)."""
    I = D = u_prev = 0.0
    ys, Is = [], []
    for ek in e:
        if pid is not None:
            Td, N = pid
            ad = Td / (Td + N * h)
            D = ad * D + k * N * ad * (ek - u_prev)
            u_prev = ek
        v = k * ek + I + D
        y = min(max(v, lo), hi)
        I = I + k * h / Ti * ek + h / Tt * (y - v)
        ys.append(y)
        Is.append(I)
    return np.array(ys), np.array(Is)


class SaturatedPI(ac.Component):
    """A constant error of 1 until t = 2 s, then -1: the output saturates at yMax and
    the integral must come back when the error changes sign."""

    err = Step(height=-2.0, offset=1.0, startTime=2.0)
    pi = PI(k=0.5, Ti=0.2, Tt=0.4, yMax=0.8, yMin=-0.8, samplePeriod=H)

    def equations(self):
        return [ac.connect(self.err.y, self.pi.u)]


@pytest.mark.parametrize("backend", BACKENDS)
def test_saturated_pi_integral_stays_bounded_and_recovers(backend):
    n = 40
    ticks = H * np.arange(n)
    res = ac.simulate(SaturatedPI(), t_end=float(ticks[-1]), t_eval=ticks, backend=backend)
    e = np.where(ticks >= 2.0, -1.0, 1.0)
    k, Ti, Tt, lim = 0.5, 0.2, 0.4, 0.8
    y, I = _pi_by_hand(e, k, Ti, Tt, H, -lim, lim)
    assert _close(res["pi.y.signal"], y) and _close(res["pi.I"], I)
    # saturated with e = 1, I_k = (1 - h/Tt) I_k-1 + k h/Ti + (h/Tt)(yMax - k): it
    # contracts to I* = yMax - k + (Tt/Ti) k (closed form), never beyond it: bounded
    I_star = lim - k + Tt / Ti * k
    before = ticks < 2.0
    Ik = res["pi.I"]
    sat = np.flatnonzero(before & (res["pi.y.signal"] == lim))
    assert sat.size > 10 and np.all(Ik[before] <= I_star + 1e-12)
    j = np.arange(sat.size)
    assert _close(Ik[sat] - I_star, (1 - H / Tt) ** j * (Ik[sat[0]] - I_star), rel=1e-11)
    # without anti-windup the integral would have grown to k h/Ti * 20 = 5
    assert I_star < 0.3 * k * H / Ti * np.count_nonzero(before)
    # after the sign change the output leaves the upper limit at the first tick where
    # the hand iteration does, and ends at the lower one
    after = ~before
    assert np.array_equal(res["pi.y.signal"][after] < lim, y[after] < lim)
    assert abs(res["pi.y.signal"][-1] + lim) < 1e-12


def test_pid_unlimited_matches_its_difference_equations():
    class OpenPID(ac.Component):
        u = Ramp(height=3.0, duration=2.0, offset=-1.0, startTime=0.3)
        pid = PID(k=2.0, Ti=0.5, Td=0.2, Nd=5.0, samplePeriod=H)

        def equations(self):
            return [ac.connect(self.u.y, self.pid.u)]

    n = 25
    ticks = H * np.arange(n)
    res = ac.simulate(OpenPID(), t_end=float(ticks[-1]), t_eval=ticks)
    e = -1.0 + 3.0 * np.clip((ticks - 0.3) / 2.0, 0, 1)
    y, _ = _pi_by_hand(e, 2.0, 0.5, 0.5, H, -np.inf, np.inf, pid=(0.2, 5.0))
    assert _close(res["pid.y.signal"], y)


def test_constant_into_sampler_is_held_from_the_first_tick():
    class C(ac.Component):
        c = Constant(k=4.0)
        smp = Sampler(samplePeriod=0.5, startTime=0.2, y={"signal": {"discrete": True,
                                                                    "start": 7.0}})

        def equations(self):
            return [ac.connect(self.c.y, self.smp.u)]

    res = ac.simulate(C(), t_end=1.0, t_eval=[0.0, 0.1, 0.2, 0.9])
    assert list(res["smp.y.signal"]) == [7.0, 7.0, 4.0, 4.0]    # the start value before


def test_a_slow_hold_behind_a_fast_sampler_reads_the_shared_ticks_sample():
    """Ticks of 0.1 and 0.3 coincide every third fast tick, though 3 * 0.1 and 0.3
    differ in the last bit: both clauses fire at that instant, in data-flow order."""

    class TwoRates(ac.Component):
        slow = ZeroOrderHold(samplePeriod=0.3)
        src = Ramp(height=10.0, duration=10.0)
        fast = Sampler(samplePeriod=0.1)

        def equations(self):
            return [ac.connect(self.src.y, self.fast.u), ac.connect(self.fast.y, self.slow.u)]

    t = 0.025 + 0.05 * np.arange(40)
    res = ac.simulate(TwoRates(), t_end=2.0, t_eval=t)
    assert _close(res["slow.y.signal"], 0.3 * np.floor(t / 0.3))
    assert _close(res["fast.y.signal"], 0.1 * np.floor(t / 0.1))
