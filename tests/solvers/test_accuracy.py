"""Accuracy of the BDF integrator against independent references."""
import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from acausal.solvers import EventAction, integrate

from .problems import DampedOscillator, Decay, HeatChain, Robertson, VanDerPol


class VanDerPolCrossings(VanDerPol):
    """Van der Pol reporting the zero crossings of x as (non-changing) events."""

    n_roots = 1

    def roots(self, t, y, yp):
        return y[:1]

    def handle_event(self, t, y, yp, crossed):
        return EventAction(changed=False)


@pytest.fixture(scope="module")
def vdp_reference():
    p = VanDerPol(1000.0)
    return solve_ivp(p.ode, (0.0, 2.0), [2.0, 0.0], method="Radau", rtol=1e-12,
                     atol=1e-14, jac=p.ode_jac, dense_output=True)


def test_van_der_pol_stiff_matches_radau(vdp_reference):
    p = VanDerPolCrossings(1000.0)
    ts = np.linspace(0.0, 2.0, 201)
    out = integrate(p, (0.0, 2.0), [2.0, 0.0], rtol=1e-6, atol=1e-8, t_eval=ts)
    assert out.success
    ref = vdp_reference.sol(ts)
    smooth = np.abs(ref[1]) < 10.0          # away from the fast jumps
    assert smooth.sum() > 150
    rel = np.abs(out.y[smooth, 0] - ref[0, smooth]) / np.abs(ref[0, smooth])
    assert rel.max() < 1e-4
    # the jumps: zero crossings of x located by the event machinery
    sol = vdp_reference.sol
    grid = np.linspace(0.0, 2.0, 4001)
    x = sol(grid)[0]
    idx = np.flatnonzero(np.sign(x[:-1]) != np.sign(x[1:]))
    t_ref = np.array([brentq(lambda t: sol(t)[0], grid[i], grid[i + 1], xtol=1e-14)
                      for i in idx])
    t_ours = np.array(out.event_times)
    assert t_ours.size == t_ref.size == 2
    assert np.all(np.abs(t_ours - t_ref) / t_ref < 1e-4)


def test_robertson_dae_matches_lsoda():
    p = Robertson()
    te = np.append(np.logspace(-5, 5, 31), 4e5)
    out = integrate(p, (0.0, 4e5), [1.0, 0.0, 0.0], rtol=1e-6,
                    atol=np.array([1e-8, 1e-14, 1e-8]), t_eval=te)
    ref = solve_ivp(p.ode, (0.0, 4e5), [1.0, 0.0, 0.0], method="LSODA", rtol=1e-12,
                    atol=[1e-16, 1e-22, 1e-16], jac=p.ode_jac, dense_output=True).sol(te).T
    assert out.y.shape == ref.shape
    err = np.abs(out.y - ref)
    assert np.all(err[:, 0] <= 1e-4 * np.abs(ref[:, 0]) + 1e-10)
    assert np.all(err[:, 2] <= 1e-4 * np.abs(ref[:, 2]) + 1e-10)
    not_tiny = ref[:, 1] > 1e-10
    assert np.all(err[not_tiny, 1] <= 1e-4 * ref[not_tiny, 1])
    # the conservation law is a linear algebraic row of the DAE, which the corrector
    # (its last correction unscaled) satisfies to rounding on the sum's scale 1
    assert np.abs(out.y.sum(axis=1) - 1.0).max() < 1e-12 * 1.0


def test_damped_oscillator_tolerance_proportionality():
    p = DampedOscillator()
    ts = np.linspace(0.0, 10.0, 101)
    x_ref, v_ref = p.exact(ts)
    rows = []
    for rtol in [1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9]:
        out = integrate(p, (0.0, 10.0), [1.0, 0.0], rtol=rtol, atol=1e-3 * rtol, t_eval=ts)
        err = max(np.abs(out.y[:, 0] - x_ref).max(), np.abs(out.y[:, 1] - v_ref).max())
        rows.append((rtol, err, out.stats.steps, out.stats.residual_evaluations))
    print("\n  rtol      max error   steps  residuals")
    for r in rows:
        print(f"  {r[0]:.0e}   {r[1]:.3e}   {r[2]:5d}  {r[3]:6d}")
    rt, er = np.log10([r[0] for r in rows]), np.log10([r[1] for r in rows])
    slope = np.polyfit(rt, er, 1)[0]
    print(f"  log-log slope {slope:.3f}")
    assert 0.7 < slope < 1.3
    assert all(r[1] < 100 * r[0] for r in rows)


def test_orders_reach_five_and_stats_counted():
    out = integrate(Decay(), (0.0, 20.0), [1.0], rtol=1e-10, atol=1e-12)
    st = out.stats
    assert max(st.orders) == 5 and min(st.orders) == 1
    # bookkeeping identities, the same on every machine (how much work the steps take,
    # e.g. how rarely the matrix is factored, is reported by benchmarks/bench_counts.py)
    assert sum(st.orders.values()) == st.steps == len(out.t) - 1
    assert st.residual_evaluations >= st.newton_iterations >= st.steps
    assert 1 <= st.lu_factorizations == st.jacobian_evaluations
    assert st.linear_solver == "dense"
    assert abs(out.y[-1, 0] - np.exp(-20.0)) < 1e-9 * 1e-3 + 1e-12
    np.testing.assert_allclose(out.y[:, 0], np.exp(-out.t), rtol=1e-7, atol=1e-10)
    np.testing.assert_allclose(out.yp[:, 0], -out.y[:, 0], rtol=1e-5, atol=1e-11)


def test_sparse_heat_chain_matches_dense_and_expm():
    n = 200
    u0 = np.zeros(n)
    u0[0] = 1.0
    ts = np.array([0.1, 0.5, 1.0])
    sparse = integrate(HeatChain(n, sparse=True), (0.0, 1.0), u0, rtol=1e-8,
                       atol=1e-10, t_eval=ts)
    dense = integrate(HeatChain(n, sparse=False), (0.0, 1.0), u0, rtol=1e-8,
                      atol=1e-10, t_eval=ts)
    assert sparse.stats.linear_solver == "sparse"
    assert dense.stats.linear_solver == "dense"
    # the two LUs round differently, which moves accept/reject decisions and so the step
    # sequence: the runs agree to the global error of the integration (each within 100
    # rtol of the exact solution, relative to u's scale 1), not to rounding
    scale = np.abs(dense.y).max()
    ref = HeatChain(n).reference
    for k, t in enumerate(ts):
        assert np.abs(sparse.y[k] - ref(t, u0)).max() < 1e-6 * scale
        assert np.abs(dense.y[k] - ref(t, u0)).max() < 1e-6 * scale
    assert np.abs(sparse.y - dense.y).max() < 1e-6 * scale


def test_robertson_final_state_matches_ida():
    pytest.importorskip("sksundae")
    from sksundae.ida import IDA

    p = Robertson()
    atol = np.array([1e-8, 1e-14, 1e-8])

    def res(t, y, yp, r):
        r[:] = p.residual(t, y, yp)

    def jac(t, y, yp, r, cj, JJ):
        JJ[:, :] = p.jacobian(t, y, yp, cj)

    for rtol in (1e-4, 1e-6, 1e-8):
        ida = IDA(res, rtol=rtol, atol=atol, jacfn=jac, algebraic_idx=[2],
                  max_num_steps=100000).solve([0.0, 4e5], [1.0, 0.0, 0.0],
                                              [-0.04, 0.04, 0.0])
        ours = integrate(p, (0.0, 4e5), [1.0, 0.0, 0.0], rtol=rtol, atol=atol)
        # the step counts are compared by benchmarks/bench_solvers.py, not asserted
        np.testing.assert_allclose(ours.y[-1], ida.y[-1], rtol=max(50 * rtol, 1e-5), atol=1e-12)


def test_max_step_first_step_and_max_steps_are_honoured():
    from acausal.solvers import SimulationError

    p = DampedOscillator()
    out = integrate(p, (0.0, 2.0), [1.0, 0.0], rtol=1e-4, atol=1e-7, max_step=0.01,
                    first_step=1e-3)
    h = np.diff(out.t)
    assert h.max() <= 0.01 * (1 + 1e-12) and h[0] <= 1e-3  # (cut on an error-test failure)
    assert out.t[-1] == 2.0                  # the end point is t_end itself, not a sum of h
    with pytest.raises(SimulationError) as info:
        integrate(p, (0.0, 10.0), [1.0, 0.0], max_steps=50)
    assert "maximum number of steps" in info.value.reason
    assert info.value.partial.t.size == 51 and info.value.partial.t[-1] < 10.0  # t0, 50 steps
