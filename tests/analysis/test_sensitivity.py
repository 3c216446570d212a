"""Forward sensitivities against central differences of simulations."""
import numpy as np
import pytest

import acausal as ac
from acausal.analysis import estimate
from acausal.analysis.sensitivity import output_sensitivities, simulate_sensitivities

from .test_estimate import A_TRUE, MotorStep, Tank


def _fd(compiled, j, t, names, rel=1e-4):
    """p_j dy/dp_j by simulations at p_j (1 +- rel), values read before p is restored."""
    p0, out = compiled.p[j], []
    for f in (1 + rel, 1 - rel):
        compiled.p[j] = p0 * f
        res = ac.simulate(compiled, t_end=t[-1], t_eval=t, rtol=1e-12, atol=1e-12)
        out.append(np.column_stack([res[n] for n in names]))
    compiled.p[j] = p0
    return (out[0] - out[1]) / (2 * rel)


def test_dc_motor_sensitivities_match_finite_differences():
    c = ac.compile(MotorStep())
    names = ["motor.rotor.w", "motor.La.i"]
    P = [c.param_names.index(n) for n in ("motor.R", "motor.k", "motor.J")]
    t = np.linspace(0.0, 0.1, 41)
    tt, Z, S = simulate_sensitivities(c, P, t, rtol=1e-10)
    _, dY = output_sensitivities(c, tt, Z, S, P, names)
    for b, j in enumerate(P):
        ref = _fd(c, j, t, names)
        assert np.max(np.abs(dY[:, b] - ref)) < 1e-6 * np.max(np.abs(ref))


def test_forward_and_finite_difference_estimates_agree_for_the_tank():
    c = ac.compile(Tank(a=A_TRUE))
    t = np.linspace(0.0, 10.0, 101)
    q = ac.simulate(c, t_end=10.0, t_eval=t, rtol=1e-10)["q"]
    q = q + 0.001 * np.random.default_rng(3).standard_normal(len(t))
    fd = estimate(c, {"t": t, "q": q}, {"a": 1.0})
    fw = estimate(c, {"t": t, "q": q}, {"a": 1.0}, sensitivities="forward")
    assert fw["a"] == pytest.approx(fd["a"], rel=1e-6)
    assert fw.std_errors["a"] == pytest.approx(fd.std_errors["a"], rel=1e-3)
    # the point of forward sensitivities, and a count of the method, not of rounding:
    # one simulation per Gauss-Newton iteration against 1 + 2 per parameter (8 vs 35)
    assert fw.n_simulations < fd.n_simulations
