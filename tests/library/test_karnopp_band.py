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
