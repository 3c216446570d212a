"""The delay of a breakaway that KarnoppFriction's documentation states.

A block of mass m stuck by Karnopp friction (static level F_s, band |v| < dv) is pulled
through a spring whose end moves at speed V (the stick-slip example): the spring force
k V t reaches F_s at t_1 = F_s / (k V), and from then on the net force on the block
grows as F' (t - t_1), F' = k V (the block has not moved: x stays ~0), so
m der(v) = F' (t - t_1) and v reaches dv, where the band ends, at

    t_1 + sqrt(2 m dv / F')

(the documented delay; the block's creep x ~ dv (t - t_1) / 3 changes the spring force
by k x, a few 1e-3 of the net force there).
"""
import math

import acausal as ac
from acausal.library.friction.examples.stick_slip import StickSlip


def test_a_breakaway_leaves_the_band_sqrt_2_m_dv_over_the_force_rate_late():
    m, k, V, F_s, dv = 1.0, 97.0, 0.113, 1.5, 1e-3
    res = ac.simulate(StickSlip(friction={"dv": dv}), t_end=0.2, rtol=1e-10, atol=1e-12)
    assert res.success
    rate = k * V
    t1 = F_s / rate
    expected = t1 + math.sqrt(2 * m * dv / rate)
    assert expected < 0.2
    # the event where the band is left: the first one after t_1 at which |v| = dv
    later = [float(e) for e in res.events if float(e) > t1 + 1e-9]
    assert later, res.events
    delay = later[0] - t1
    assert abs(delay - math.sqrt(2 * m * dv / rate)) <= 0.02 * math.sqrt(2 * m * dv / rate)
    assert abs(later[0] - expected) <= 0.02 * (expected - t1)
    # there the block's speed is the band's edge
    just_before = [v for t, v in zip(res.t, res["block.v"]) if t <= later[0]][-1]
    assert abs(just_before - dv) <= 1e-6 * dv


# A block on a belt moving at V, held back by a spring to the ground, Karnopp friction
# between belt and block: it rides with the belt (stuck) until the spring force c s reaches
# F_s, slides back, and sticks again when its speed is the belt's.  The band dv of a
# few 1e-13 m/s, far below the tolerance of v, must neither stop the run (a restart at
# each stick and breakaway) nor change the motion.
import numpy as np
import pytest
from scipy.integrate import solve_ivp

from acausal.library import translational as tr
from acausal.library.friction.translational import KarnoppFriction

M, C, V, F_C, F_S, V_S, F_V = 1.0, 10.0, 0.1, 1.0, 1.5, 0.01, 0.2
T_END = 5.0


class BlockOnBelt(ac.Component):
    belt = tr.ConstantSpeed(v_fixed=V, s={"start": 0.0, "fixed": True})
    friction = KarnoppFriction(F_c=F_C, F_s=F_S, v_s=V_S, F_v=F_V)
    block = tr.Mass(m=M, s={"start": 0.0, "fixed": True}, v={"start": 0.0, "fixed": True})
    spring = tr.Spring(c=C)
    ground = tr.Fixed()

    def equations(self):
        return [ac.connect(self.belt.flange, self.friction.flange_a),
                ac.connect(self.friction.flange_b, self.block.flange_a),
                ac.connect(self.block.flange_b, self.spring.flange_a),
                ac.connect(self.spring.flange_b, self.ground.flange)]


def _belt_reference(times):
    """Mode by mode (scipy, rtol 1e-12): starting at rest on the moving belt the block
    slides until its speed is the belt's, rides along while c |s| <= F_s, slides back."""
    def slide(t, z):
        s, v = z
        w = v - V                                   # the block's speed on the belt
        f = -np.sign(w) * (F_C + (F_S - F_C) * np.exp(-(w / V_S) ** 2)) - F_V * w
        return [v, (f - C * s) / M]

    def caught_up(t, z):
        return z[1] - V
    caught_up.terminal = True
    caught_up.direction = 1       # from below: leaving the belt speed is not it

    s_of_t, t0, z = [], 0.0, [0.0, 0.0]
    while t0 < T_END:
        sol = solve_ivp(slide, (t0, T_END), z, events=caught_up, rtol=1e-12, atol=1e-15,
                        dense_output=True, first_step=1e-9)
        s_of_t.append((t0, sol.t[-1], sol.sol))
        t0, z = sol.t[-1], sol.y[:, -1]
        if t0 >= T_END:
            break
        # stuck: s = s0 + V (t - t0) until c s = F_s (the spring pulls it off the belt)
        s0 = z[0]
        t1 = min(t0 + (F_S / C - s0) / V, T_END)
        s_of_t.append((t0, t1, lambda t, s0=s0, t0=t0: np.array([s0 + V * (t - t0), V])))
        t0, z = t1, [s0 + V * (t1 - t0), V]
    out = np.empty(len(times))
    for k, t in enumerate(times):
        for a, b, f in s_of_t:
            if a <= t <= b:
                out[k] = np.asarray(f(t))[0]
                break
    return out


@pytest.mark.parametrize("dv", [1e-12, 1e-13])
@pytest.mark.parametrize("rtol", [1e-8, 1e-10])
def test_a_block_on_a_belt_runs_with_a_band_of_1e_13(dv, rtol):
    t = np.linspace(0.0, T_END, 501)
    res = ac.simulate(BlockOnBelt(friction={"dv": dv}), t_end=T_END, rtol=rtol, t_eval=t)
    assert res.success, res.message
    want = _belt_reference(t)
    err = np.max(np.abs(res["block.s"] - want)) / np.max(np.abs(want))
    assert err < 1e-6, err     # a band of 1e-4 m/s is off by 1.6e-6 here
