"""Badly scaled equations and weakly damped oscillatory modes."""
import numpy as np
import pytest

from acausal.solvers import integrate

from .problems import Chamber, OscillatorChain


def test_tiny_capacitance_is_not_a_singular_matrix():
    # (V/beta) p' = q with V/beta ~ 1e-13: a regular iteration matrix at every cj
    p = Chamber()
    out = integrate(p, (0.0, 1.0), [0.0, 0.0, 7e7], rtol=1e-8, atol=1e-8)
    x, pe = Chamber.exact(out.t)
    np.testing.assert_allclose(out.y[:, 0], x, rtol=1e-7, atol=1e-12)
    np.testing.assert_allclose(out.y[1:, 1], pe[1:], rtol=1e-5)


@pytest.fixture(scope="module")
def chain():
    """40 undamped modes up to 1e5 rad/s, excited to about the tolerance by a slow
    ramp: orders 3-5 cannot damp the high ones (no A-stability), so with the default
    settings they are resolved at ~0.7 rad per step: ~38 000 steps on [0, 0.2]
    (scipy's BDF and SUNDIALS IDA behave the same: ~37 000 and ~41 000).  The step
    counts of the runs below are reported by benchmarks/bench_counts.py."""
    p = OscillatorChain(N=40, w=5e4, d=0.0, a=20.0)
    ts = np.linspace(0.0, 0.2, 21)
    return p, ts, p.exact(ts)


def test_undamped_chain_at_order_2_stays_accurate(chain):
    p, ts, ref = chain
    out = integrate(p, (0.0, 0.2), *p.initial(), rtol=1e-4, atol=1e-6, t_eval=ts,
                    max_order=2)
    positions = slice(0, p.N + 1)
    assert np.abs(out.y[:, positions] - ref[:, positions]).max() < 5e-4
    assert set(out.stats.orders) <= {1, 2}             # max_order is honoured


def test_stald_detects_the_stability_limit_and_stays_accurate(chain):
    p, ts, ref = chain
    out = integrate(p, (0.0, 0.2), *p.initial(), rtol=1e-4, atol=1e-6, t_eval=ts,
                    stald=True)
    positions = slice(0, p.N + 1)
    assert np.abs(out.y[:, positions] - ref[:, positions]).max() < 5e-4
    assert out.stats.stability_limit_reductions >= 1   # the detector fires


def test_stald_leaves_resolved_oscillations_alone():
    # a mode of large amplitude resolved on purpose: nothing to detect
    from .problems import DampedOscillator
    p = DampedOscillator(w=2.0, zeta=0.0)
    ts = np.linspace(0.0, 20.0, 11)
    base = integrate(p, (0.0, 20.0), [1.0, 0.0], [0.0, -4.0], rtol=1e-6, atol=1e-8,
                     t_eval=ts)
    out = integrate(p, (0.0, 20.0), [1.0, 0.0], [0.0, -4.0], rtol=1e-6, atol=1e-8,
                    t_eval=ts, stald=True)
    x, _ = p.exact(ts)
    assert np.abs(out.y[:, 0] - x).max() < 1e-4
    assert np.abs(base.y[:, 0] - x).max() < 1e-4
    # "left alone": the detector makes no order reduction (an integer the problem
    # fixes: a resolved mode of large amplitude gives it nothing to detect)
    assert out.stats.stability_limit_reductions == 0
