"""TF-09: Robertson's chemical kinetics (Egeland & Gravdahl, 001 §14.1.4, (14.13)).

    y1' = -0.04 y1 + 1e4 y2 y3
    y2' =  0.04 y1 - 1e4 y2 y3 - 3e7 y2^2
    y3' =  3e7 y2^2,                     y(0) = (1, 0, 0)                  (14.13)

The right-hand sides sum to zero, so y1 + y2 + y3 = 1 is a linear invariant, and a
linear multistep method keeps a linear invariant exactly (001 (14.223)-(14.224)): the
BDF corrector F(y) = alpha y - h f(y) - r has e^T F = alpha e^T y - e^T r for e = (1,1,1),
and e^T (dF/dy) = alpha e^T for any Jacobian, so even one (inexact) Newton iteration puts
the sum where the method puts it.  Unlike tests/solvers/test_accuracy.py, where the
invariant is an algebraic row of a DAE, here it is *not* an equation: the model is the
three ODEs of (14.13) written with ``ac.Component``.

Checked, acausal at rtol 1e-8: the sum stays 1 to 1e-10 over t in [0, 4e5] (measured
1.3e-15), and y agrees with scipy's Radau at rtol 1e-10 on the same equations to 1e-6 of
each component's amplitude (measured 6e-9 for y1, y3 and 1.7e-8 for y2, which peaks at
3.6e-5 near t = 0.01).
"""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal as ac

T_OUT = np.concatenate([[0.0], np.logspace(-5, 5, 41), [4e5]])


class Robertson(ac.Component):
    """The three species of Robertson's reaction, 001 (14.13)."""

    k1 = ac.Parameter(0.04, unit="1/s", description="rate of A -> B")
    k2 = ac.Parameter(3e7, unit="1/s", description="rate of B + B -> C + B")
    k3 = ac.Parameter(1e4, unit="1/s", description="rate of B + C -> A + C")
    y1 = ac.Variable(start=1.0, fixed=True, description="concentration of A")
    y2 = ac.Variable(start=0.0, fixed=True, nominal=1e-5, description="concentration of B")
    y3 = ac.Variable(start=0.0, fixed=True, description="concentration of C")

    def equations(self):
        k1, k2, k3, y1, y2, y3 = self.k1, self.k2, self.k3, self.y1, self.y2, self.y3
        return [ac.Eq(ac.der(y1), -k1 * y1 + k3 * y2 * y3),
                ac.Eq(ac.der(y2), k1 * y1 - k3 * y2 * y3 - k2 * y2**2),
                ac.Eq(ac.der(y3), k2 * y2**2)]


def _rober(t, y):
    return [-0.04 * y[0] + 1e4 * y[1] * y[2],
            0.04 * y[0] - 1e4 * y[1] * y[2] - 3e7 * y[1] ** 2,
            3e7 * y[1] ** 2]


def _rober_jac(t, y):
    return [[-0.04, 1e4 * y[2], 1e4 * y[1]],
            [0.04, -1e4 * y[2] - 6e7 * y[1], -1e4 * y[1]],
            [0.0, 6e7 * y[1], 0.0]]


@pytest.fixture(scope="module")
def run():
    return ac.simulate(Robertson(), t_end=4e5, t_eval=T_OUT, rtol=1e-8, atol=1e-12)


def test_linear_invariant_is_kept(run):
    total = run["y1"] + run["y2"] + run["y3"]
    assert np.max(np.abs(total - 1.0)) < 1e-10


def test_values_match_radau(run):
    ref = solve_ivp(_rober, (0.0, 4e5), [1.0, 0.0, 0.0], method="Radau", rtol=1e-10,
                    atol=[1e-14, 1e-20, 1e-14], jac=_rober_jac, t_eval=T_OUT)
    assert ref.success
    for i, name in enumerate(("y1", "y2", "y3")):
        amp = np.max(np.abs(ref.y[i]))
        err = np.max(np.abs(run[name] - ref.y[i]))
        assert err < 1e-6 * amp, (name, err / amp)
