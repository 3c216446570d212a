"""Arrays in the modelling language (acausal.components.arrays).

The linear second-order system M q'' + C q' + K q = 0 with 2x2 matrix parameters is
checked against the matrix exponential of its first-order form (scipy.linalg.expm),
before and after an off-diagonal element of M is tuned; the matrix ODE X' = A X with a
2x2 array variable against X(t) = expm(A t).  Errors: shapes that do not match, indices
out of range, arrays where one value is expected, values of the wrong shape.
"""
import numpy as np
import pytest
from scipy.linalg import expm

import acausal as ac

M0 = np.array([[2.0, 0.0], [0.0, 1.0]])
C0 = np.array([[0.3, -0.1], [-0.1, 0.2]])
K0 = np.array([[30.0, -10.0], [-10.0, 10.0]])
Q0, V0 = np.array([1.0, 0.0]), np.array([0.0, -0.5])
T_END = 2.0


class TwoMassOscillator(ac.Component):
    """M q'' + C q' + K q = 0: two masses, springs and dampers in matrix form."""

    M = ac.Parameter(M0, unit="kg", description="mass matrix")
    C = ac.Parameter(C0, unit="N.s/m", description="damping matrix")
    K = ac.Parameter(K0, unit="N/m", description="stiffness matrix")
    q = ac.Variable(shape=2, start=Q0, fixed=True, unit="m")
    v = ac.Variable(shape=(2,), start=V0, fixed=True, unit="m/s")

    def equations(self):
        return [ac.Eq(ac.der(self.q), self.v),
                ac.Eq(self.M @ ac.der(self.v) + self.C @ self.v + self.K @ self.q, 0)]


def _expm_solution(M, C, K, t):
    """x(t) = expm(A t) x0 for x = (q, v), A = [[0, I], [-M^-1 K, -M^-1 C]]."""
    Minv = np.linalg.inv(M)
    A = np.block([[np.zeros((2, 2)), np.eye(2)], [-Minv @ K, -Minv @ C]])
    return _propagate(A, np.concatenate([Q0, V0]), t)


def _propagate(A, x0, t):
    """expm(A t_k) x0 on the evenly spaced t_k: one exponential of the step, applied k
    times (the round-off of k products stays near k eps)."""
    step = expm(A * (t[1] - t[0]))
    assert np.allclose(np.diff(t), t[1] - t[0], rtol=1e-12, atol=0)
    out = [x0]
    for _ in t[1:]:
        out.append(step @ out[-1])
    return np.array(out)


@pytest.fixture(scope="module")
def compiled():
    return ac.compile(TwoMassOscillator())


def _run(compiled, parameters=None):
    """A run from the declared matrices, changed by ``parameters`` (set_parameters keeps
    its values in the compiled model, which the tests share)."""
    compiled.set_parameters({"M": M0})
    return ac.simulate(compiled, t_end=T_END, rtol=1e-10, n_points=201,
                       parameters=parameters, raise_on_failure=True)


def _relative_error(res, M):
    x = _expm_solution(M, C0, K0, res.t)
    qv = np.hstack([res["q"], res["v"]])
    return np.max(np.abs(qv - x)) / np.max(np.abs(x))


def test_matrix_parameters_flatten_to_named_tunable_elements(compiled):
    names = [f"{m}[{i},{j}]" for m in "MCK" for i in range(2) for j in range(2)]
    assert set(names) <= set(compiled.param_names)
    assert sorted(compiled.states) == ["q[0]", "q[1]", "v[0]", "v[1]"]


def test_second_order_system_matches_the_matrix_exponential(compiled):
    res = _run(compiled)
    assert res["q"].shape == (201, 2)
    np.testing.assert_array_equal(res["q"][:, 1], res["q[1]"])
    assert _relative_error(res, M0) < 1e-7


def test_tuning_an_off_diagonal_mass_element_after_compile(compiled):
    # M[0,1] is 0 at compile time and still a parameter: tuning it couples the masses
    M = M0.copy()
    M[0, 1] = 0.6
    before = _run(compiled)
    res = _run(compiled, {"M[0,1]": 0.6})
    assert _relative_error(res, M) < 1e-7
    change = np.max(np.abs(res["q"] - before["q"])) / np.max(np.abs(before["q"]))
    assert change > 1e-2                # the tuned element took part


def test_tuning_a_whole_matrix_after_compile(compiled):
    M = np.array([[2.5, -0.3], [0.2, 0.8]])
    res = _run(compiled, {"M": M})
    assert _relative_error(res, M) < 1e-7
    with pytest.raises(ac.InvalidValue, match=r"parameter array 'M' has shape \(2, 2\), "
                                              r"the value given has shape \(2,\)"):
        compiled.set_parameters({"M": [1.0, 2.0]})


def test_modification_with_a_matrix_at_instantiation():
    M = np.array([[3.0, 0.5], [0.5, 1.5]])
    res = ac.simulate(TwoMassOscillator(M=M), t_end=T_END, rtol=1e-10, n_points=101,
                      raise_on_failure=True)
    assert _relative_error(res, M) < 1e-7


class MatrixODE(ac.Component):
    """X' = A X, X(0) = I: a 2x2 array variable, X(t) = expm(A t)."""

    A = ac.Parameter([[-0.5, 2.0], [-1.0, -0.2]], unit="1/s")
    X = ac.Variable(shape=(2, 2), start=np.eye(2), fixed=True)

    def equations(self):
        return [ac.Eq(ac.der(self.X), self.A @ self.X)]


class Holder(ac.Component):
    """Array variables inside a list of sub-components: names a[i].X[j,k]."""

    def __init__(self, **modifications):
        super().__init__(**modifications)
        self.a = [MatrixODE(), MatrixODE(A=[[0.0, 1.0], [-4.0, 0.0]])]


def test_matrix_variable_results_have_the_matrix_shape():
    res = ac.simulate(Holder(), t_end=1.5, rtol=1e-10, n_points=31, raise_on_failure=True)
    for k, A in enumerate((np.array([[-0.5, 2.0], [-1.0, -0.2]]),
                           np.array([[0.0, 1.0], [-4.0, 0.0]]))):
        X = res[f"a[{k}].X"]
        assert X.shape == (31, 2, 2)
        exact = np.array([expm(A * t) for t in res.t])
        assert np.max(np.abs(X - exact)) / np.max(np.abs(exact)) < 1e-7
        np.testing.assert_array_equal(X[:, 1, 0], res[f"a[{k}].X[1,0]"])
    assert res["der(a[0].X)"].shape == (31, 2, 2)
    assert "a[1].X[0,1]" in res.to_pandas().columns


class Elementwise(ac.Component):
    """Slices, Python loops over elements and elementwise functions."""

    k = ac.Parameter(np.array([1.0, 2.0, 3.0]), unit="1/s", min=0)
    x = ac.Variable(shape=3, start=[1.0, 2.0, 3.0], fixed=True)
    y = ac.Variable(shape=3)
    total = ac.Variable()

    def equations(self):
        return [ac.Eq(ac.der(self.x), -self.k * self.x),
                [ac.Eq(yi, ac.sin(xi) + 1) for xi, yi in zip(self.x[:2], self.y[:2])],
                ac.Eq(self.y[2], ac.exp(self.x)[2]),
                ac.Eq(self.total, self.x.sum())]


def test_slices_loops_and_elementwise_functions():
    res = ac.simulate(Elementwise(), t_end=1.0, rtol=1e-10, n_points=11,
                      raise_on_failure=True)
    x = np.array([1.0, 2.0, 3.0]) * np.exp(-np.outer(res.t, [1.0, 2.0, 3.0]))
    assert np.max(np.abs(res["x"] - x)) / 3.0 < 1e-7
    np.testing.assert_allclose(res["y"][:, :2], np.sin(res["x"][:, :2]) + 1, rtol=1e-12)
    np.testing.assert_allclose(res["y[2]"], np.exp(res["x[2]"]), rtol=1e-12)
    np.testing.assert_allclose(res["total"], res["x"].sum(axis=1), rtol=1e-12)


# -- errors in the user's names ------------------------------------------------------------
def _model(body, **declarations):
    cls = type("Bad", (ac.Component,), {"equations": body,
                                         "q": ac.Variable(shape=2, start=0.0),
                                         "x": ac.Variable(),
                                         **declarations})
    return cls


def test_equation_between_arrays_of_different_shapes():
    bad = _model(lambda self: [ac.Eq(ac.der(self.q), self.q[:1])])
    with pytest.raises(ac.InvalidEquation, match=r"the model \(Bad\).*the left side has "
                                                 r"shape \(2,\), the right side has shape "
                                                 r"\(1,\)"):
        ac.compile(bad())


def test_array_against_a_scalar_variable_is_a_shape_mismatch():
    bad = _model(lambda self: [ac.Eq(self.x, self.q)])
    with pytest.raises(ac.InvalidEquation, match=r"Bad.*the left side is a scalar, the "
                                                 r"right side has shape \(2,\)"):
        ac.compile(bad())


def test_index_out_of_range_names_the_array():
    class Part(ac.Component):
        q = ac.Variable(shape=2)

        def equations(self):
            return [ac.Eq(self.q[0], 1.0), ac.Eq(self.q[2], 2.0)]

    class Top(ac.Component):
        part = Part()

    with pytest.raises(ac.InvalidIndex, match=r"'part' \(Part\).*index 2 is out of range "
                                              r"for 'part.q' of shape \(2,\)"):
        ac.compile(Top())


def test_array_where_one_value_is_expected():
    bad = _model(lambda self: [ac.Eq(self.q, 0.0),
                               ac.Eq(ac.der(self.x), ac.if_else(self.x > 0, self.q, 0))])
    with pytest.raises(ac.InvalidEquation, match=r"array of shape \(2,\) is used where one "
                                                 r"value is expected"):
        ac.compile(bad())


def test_array_in_a_condition():
    bad = _model(lambda self: [ac.Eq(self.q, 0.0),
                               ac.when(self.q > 0, ac.reinit(self.x, 0.0)),
                               ac.Eq(ac.der(self.x), 1.0)])
    with pytest.raises(ac.InvalidEquation, match="condition"):
        ac.compile(bad())


def test_matrix_value_of_the_wrong_shape():
    with pytest.raises(ac.InvalidValue, match=r"the model \(TwoMassOscillator\): parameter "
                                              r"M has shape \(3, 3\), but it is declared "
                                              r"with shape \(2, 2\)"):
        ac.compile(TwoMassOscillator(M=np.eye(3)))


def test_array_value_for_a_scalar_parameter():
    cls = _model(lambda self: [ac.Eq(ac.der(self.x), -self.a * self.x), ac.Eq(self.q, 0.0)],
                 a=ac.Parameter(1.0))
    with pytest.raises(ac.InvalidValue, match="parameter a = .* is not a real number .*"
                                              "declared a scalar"):
        ac.compile(cls(a=np.ones(2)))


def test_start_values_of_the_wrong_shape():
    with pytest.raises(ac.InvalidValue, match=r"variable q: attribute start has shape "
                                              r"\(3,\), the variable has shape \(2,\)"):
        ac.compile(TwoMassOscillator(q={"start": [1.0, 2.0, 3.0]}))


def test_element_attributes_are_checked_when_the_class_is_made():
    with pytest.raises(ac.InvalidValue, match=r"Part.q: element \[1\]: start = 5.0 lies "
                                              r"outside \[min, max\]"):
        class Part(ac.Component):
            q = ac.Variable(shape=2, start=[0.0, 5.0], max=[1.0, 2.0])


def test_shape_from_a_structural_attribute():
    class Line(ac.Component):
        tau = ac.Parameter(0.5, shape="n", unit="s", min=0)
        x = ac.Variable(shape="n", start=1.0, fixed=True)

        def __init__(self, n, **modifications):
            self.n = n
            super().__init__(**modifications)

        def equations(self):
            return [ac.Eq(self.tau * ac.der(self.x), -self.x)]

    compiled = ac.compile(Line(4, tau=[0.5, 1.0, 2.0, 4.0]))
    assert [n for n in compiled.param_names if n.startswith("tau")] == \
        ["tau[0]", "tau[1]", "tau[2]", "tau[3]"]
    res = ac.simulate(compiled, t_end=1.0, rtol=1e-10, n_points=5, raise_on_failure=True)
    exact = np.exp(-np.outer(res.t, 1 / np.array([0.5, 1.0, 2.0, 4.0])))
    assert np.max(np.abs(res["x"] - exact)) < 1e-7


def test_equation_with_a_list_side_and_the_array_port_error():
    class Line(ac.Component):
        x = ac.Variable(shape=2)

        def equations(self):
            return [ac.Eq(self.x, [1.0, ac.time])]

    res = ac.simulate(Line(), t_end=1.0, n_points=3, raise_on_failure=True)
    np.testing.assert_array_equal(res["x[1]"], res.t)

    class BusPin(ac.Port):
        v = ac.Across(shape=2, unit="V")

    class Device(ac.Component):
        p = BusPin()

    with pytest.raises(ac.InvalidValue, match=r"'p' \(BusPin\): port variable v is an array"):
        ac.compile(Device())


class Attributed(ac.Component):
    """Per-element attributes and bounds."""

    k = ac.Parameter([1.0, 2.0], unit="1/s", min=[0.5, 1.5], max=10.0)
    x = ac.Variable(shape=2, start=[1.0, 2.0], fixed=[True, False], nominal=[1.0, 1e3],
                    min=0.0, max=[5.0, 50.0], state_select=["prefer", "avoid"], unit="m")

    def equations(self):
        return [ac.Eq(ac.der(self.x), -self.k * self.x)]


def test_attributes_per_element_reach_the_flat_variables():
    from acausal.compiler.frontend.flatten import flatten
    flat = flatten(Attributed())
    x0, x1 = flat.variable("x[0]").attrs, flat.variable("x[1]").attrs
    assert (x0.start, x0.fixed, x0.nominal, x0.max, x0.state_select) == \
        (1.0, True, 1.0, 5.0, "prefer")
    assert (x1.start, x1.fixed, x1.nominal, x1.max, x1.state_select) == \
        (2.0, False, 1e3, 50.0, "avoid")
    assert x0.min == x1.min == 0.0 and x0.unit == x1.unit == "m"
    with pytest.raises(ac.InvalidValue, match=r"parameter k\[1\] = 1.0 is below its "
                                              r"minimum 1.5"):
        ac.compile(Attributed(k=[1.0, 1.0]))
    with pytest.raises(ac.InvalidValue, match=r"Gains.k: default value\[1\] 1.0 is below "
                                              r"its minimum 2.0"):
        class Gains(ac.Component):
            k = ac.Parameter(1.0, shape=2, min=[0.0, 2.0])


def test_a_result_read_from_columns_gives_arrays_whole():
    t = np.linspace(0.0, 1.0, 5)
    columns = {f"M[{i},{j}]": (10 * i + j) * t for i in range(2) for j in range(3)}
    res = ac.Result.from_table(t, {**columns, "q[0]": t, "q[1]": 2 * t, "other": t})
    assert res["M"].shape == (5, 2, 3)
    np.testing.assert_array_equal(res["M"][:, 1, 2], 12 * t)
    np.testing.assert_array_equal(res["q"], np.column_stack([t, 2 * t]))
    with pytest.raises(KeyError, match="no variable 'p'"):
        res["p"]


class ComputedStiffness(TwoMassOscillator):
    """K computed from two spring rates: a matrix parameter given as a function of the
    component (two masses in a chain, wall -k_1- m_1 -k_2- m_2)."""

    k_1 = ac.Parameter(20.0, unit="N/m")
    k_2 = ac.Parameter(10.0, unit="N/m")
    K = ac.Parameter(lambda c: [[c.k_1 + c.k_2, -c.k_2], [-c.k_2, c.k_2]], shape=(2, 2),
                     unit="N/m", description="stiffness matrix from k_1, k_2")


def test_matrix_parameter_computed_from_scalar_parameters():
    compiled = ac.compile(ComputedStiffness())
    assert _relative_error(_run(compiled), M0) < 1e-7          # K = K0
    res = _run(compiled, parameters={"k_2": 15.0})
    x = _expm_solution(M0, C0, np.array([[35.0, -15.0], [-15.0, 15.0]]), res.t)
    qv = np.hstack([res["q"], res["v"]])
    assert np.max(np.abs(qv - x)) < 1e-7 * np.max(np.abs(x))


def test_computed_matrix_of_the_wrong_shape():
    with pytest.raises(ac.InvalidValue, match=r"parameter K has shape \(3,\), but it is "
                                              r"declared with shape \(2, 2\)"):
        ac.compile(ComputedStiffness(K=lambda c: [c.k_1, c.k_2, 0.0]))
