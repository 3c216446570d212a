"""The error test on the states alone (``error_test="states"``, :mod:`acausal.solvers.bdf`):
the algebraic unknowns are solved from the states at output times and where a crossing
is located.

The model: a stiff linear state x' = -a x + sin(w t), x(0) = 0, in closed form, and a
high-gain algebraic unknown z of an implicit relation, z + z^3/G^2 = G tanh(x/d) (its
gain G/d = 1e9 at x = 0), with a relation z > G/4 that switches a variable.  z is exact
wherever x is: z/G is the real root of u + u^3 = tanh(x/d), and the crossings are where
x = d artanh(1/4 + 1/64).  Its interpolant between steps is not bounded by the error
test: the values at output times and at crossings are the model's own.
"""
import numpy as np
import pytest
from scipy.optimize import brentq

import acausal as ac

A, W, G, D = 1e4, 2 * np.pi * 50, 1e3, 1e-6
T_END, RTOL = 0.04, 1e-8


class HighGain(ac.Component):
    x = ac.Variable(start=0.0, fixed=True, nominal=1e-4)
    z = ac.Variable(start=0.0, nominal=1e3)
    on = ac.Variable(start=0.0)

    def equations(self):
        return [ac.Eq(ac.der(self.x), -A * self.x + ac.sin(W * ac.time)),
                ac.Eq(self.z + self.z ** 3 / G ** 2, G * ac.tanh(self.x / D)),
                ac.Eq(self.on, ac.if_else(self.z > 0.25 * G, 1.0, 0.0))]


class Rigid(ac.Component):
    """Two masses held together (index 2)."""
    x1 = ac.Variable(start=0.0, fixed=True)
    x2 = ac.Variable(start=0.0)
    v1 = ac.Variable(start=0.0, fixed=True)
    v2 = ac.Variable(start=0.0)
    f = ac.Variable(start=0.0)

    def equations(self):
        return [ac.Eq(ac.der(self.x1), self.v1), ac.Eq(ac.der(self.x2), self.v2),
                ac.Eq(ac.der(self.v1), 1.0 - self.f), ac.Eq(2.0 * ac.der(self.v2), self.f),
                ac.Eq(self.x1, self.x2)]


def x_exact(t):
    return (A * np.sin(W * t) - W * np.cos(W * t) + W * np.exp(-A * t)) / (A * A + W * W)


def z_exact(t):
    return G * np.array([brentq(lambda u: u + u ** 3 - v, -1.0, 1.0)
                         for v in np.tanh(x_exact(np.atleast_1d(t)) / D)])


def crossings_exact():
    xc = D * np.arctanh(0.25 + 0.25 ** 3)
    t = np.linspace(1e-7, T_END, 40001)
    f = x_exact(t) - xc
    return [brentq(lambda s: x_exact(s) - xc, t[i], t[i + 1])
            for i in range(t.size - 1) if f[i] * f[i + 1] < 0]


@pytest.fixture(scope="module")
def compiled():
    return ac.compile(HighGain(), check_units="off")


def test_the_states_alone_give_z_at_output_times_and_crossings(compiled):
    res = ac.simulate(compiled, t_end=T_END, rtol=RTOL, n_points=4001, error_test="states")
    assert res.success, res.message
    assert res.stats["error_test"] == "states"
    assert res.stats["interpolated_outputs"] == 0       # every z solved, none interpolated
    assert np.max(np.abs(res["x"] - x_exact(res.t))) <= 1e-6 * 1e-4
    # z follows x with the gain G/d: 1e-5 of G is x within 1e-14 at the steepest
    assert np.max(np.abs(res["z"] - z_exact(res.t))) <= 1e-5 * G
    exact = crossings_exact()
    got = [e.time for e in res.events]
    assert len(got) == len(exact) == 4
    assert np.max(np.abs(np.array(got) - exact)) <= 1e-8     # of a 20 ms period


def test_the_states_alone_give_the_values_the_full_test_gives(compiled):
    """The same run with every unknown in the error test: both at the closed form."""
    for test in ("all", "states"):
        res = ac.simulate(compiled, t_end=T_END, rtol=RTOL, n_points=801, error_test=test)
        assert res.success and res.stats["error_test"] == test
        assert np.max(np.abs(res["x"] - x_exact(res.t))) <= 1e-6 * 1e-4
        assert np.max(np.abs(res["z"] - z_exact(res.t))) <= 1e-5 * G


def test_error_test_is_checked():
    with pytest.raises(ac.InvalidArgument, match="error_test"):
        ac.simulate(Rigid(), t_end=1.0, error_test="algebraic", check_units="off")


def test_every_unknown_is_in_the_test_by_default():
    res = ac.simulate(Rigid(), t_end=1.0, rtol=1e-8, check_units="off")
    assert res.stats["error_test"] == "all"
    # F = 1 on both masses together: x = t^2 / 6
    assert abs(res["x2"][-1] - 1.0 / 6.0) <= 1e-7


def test_a_second_run_is_bitwise_the_first(compiled):
    """The values at output times start from a factorization of the run's own."""
    runs = [ac.simulate(compiled, t_end=T_END, rtol=RTOL, n_points=401, error_test="states")
            for _ in range(2)]
    assert runs[0]["z"].tobytes() == runs[1]["z"].tobytes()
