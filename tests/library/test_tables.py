"""Lookup tables against numpy / scipy interpolation, and their breakpoints as events.

Algebraic outputs are compared to rounding relative to the table's range; integrated
quantities at rtol 1e-10 to 1e-7 of their size (the integrator's global error is
10-100 rtol).
"""
import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp
from scipy.interpolate import PchipInterpolator, RegularGridInterpolator, interp1d

import acausal as ac
from acausal.library.blocks.tables import (CombiTable1D, CombiTable2D, CombiTimeTable,
                                           interpolant, read_table)

TAB = np.array([[0.0, 0.0, 1.0], [1.0, 2.0, -1.0], [2.0, 2.0, 0.5], [2.0, 5.0, 0.5],
                [3.5, 1.0, 3.0], [5.0, 0.0, 2.0]])


def _source(table, **kw):
    class Source(ac.Component):
        src = CombiTimeTable(table=table, **kw)
        x = ac.Variable(start=0.0, fixed=True, description="integral of y[0]")

        def equations(self):
            return [ac.Eq(ac.der(self.x), self.src.y[0])]
    return Source()


def _close(a, b, scale, tol=1e-12):
    assert np.max(np.abs(np.asarray(a) - np.asarray(b))) <= tol * scale


def _away_from(t, points, gap=1e-9):
    return np.min(np.abs(t[:, None] - np.asarray(points)[None, :]), axis=1) > gap


def test_linear_time_table_lands_on_breakpoints_and_matches_interp():
    res = ac.simulate(_source(TAB), t_end=6.0, rtol=1e-10)
    knots = [1.0, 2.0, 3.5, 5.0]
    times = [float(e) for e in res.events]
    assert len(times) == len(knots)
    assert np.allclose(times, knots, rtol=1e-12, atol=0)
    ok = _away_from(res.t, [2.0])
    for j in (0, 1):
        y = res[f"src.y[{j}].signal"]
        _close(y[ok], np.interp(res.t[ok], TAB[:, 0], TAB[:, 1 + j]), 5.0)
    # the jump row: left limit 2 before t = 2, the later row's 5 from t = 2 on
    y0, at = res["src.y[0].signal"], np.isclose(res.t, 2.0, rtol=0, atol=1e-12)
    assert set(np.round(y0[at], 12)) <= {2.0, 5.0} and y0[at][-1] == pytest.approx(5.0)
    # the integral of a piecewise-linear signal is its trapezoid sum over the rows
    exact = sum((TAB[i + 1, 0] - TAB[i, 0]) * (TAB[i + 1, 1] + TAB[i, 1]) / 2
                for i in range(len(TAB) - 1))
    assert res["x"][-1] == pytest.approx(exact, rel=1e-9)


def test_constant_segments_columns_offset_time_scale_and_start():
    model = _source(TAB, columns=[3], smoothness="constant", offset=0.25, timeScale=2.0,
                    startTime=1.0)
    t = np.linspace(0.0, 14.0, 281)
    res = ac.simulate(model, t_end=14.0, rtol=1e-10, t_eval=t)
    tau = (t - 1.0) / 2.0
    rows = np.clip(np.searchsorted(TAB[:, 0], tau, side="right") - 1, 0, len(TAB) - 1)
    ref = np.where(t >= 1.0, 0.25 + TAB[rows, 2], 0.25)
    ok = _away_from(t, 1.0 + 2.0 * TAB[:, 0])
    _close(res["src.y[0].signal"][ok], ref[ok], 3.0)
    # startTime and the first row coincide: one event there
    assert np.allclose([float(e) for e in res.events], 1.0 + 2.0 * np.array([0, 1, 2, 3.5, 5]),
                       rtol=1e-12, atol=0)


def test_smooth_is_monotone_pchip_split_at_jumps():
    x = np.array([0.0, 0.4, 1.0, 1.5, 2.5, 2.5, 3.0, 4.0, 5.5])
    y = np.array([0.0, 0.3, 2.0, 2.1, 1.0, 4.0, 3.0, 3.2, 0.0])
    table = np.column_stack([x, y])
    t = np.linspace(0.0, 5.5, 221)
    res = ac.simulate(_source(table, smoothness="smooth"), t_end=5.5, rtol=1e-10, t_eval=t)
    left, right = PchipInterpolator(x[:5], y[:5]), PchipInterpolator(x[5:], y[5:])
    ref = np.where(t < 2.5, left(t), right(t))
    ok = _away_from(t, [2.5])
    _close(res["src.y[0].signal"][ok], ref[ok], 4.0)


def test_periodic_over_several_periods():
    table = np.array([[0.0, 1.0], [0.3, -1.0], [0.5, 2.0], [1.2, 0.0]])
    T = 1.2
    t = np.linspace(0.0, 4.5, 451)
    res = ac.simulate(_source(table, extrapolation="periodic"), t_end=4.5, rtol=1e-10,
                      t_eval=t)
    ref = np.interp(np.mod(t, T), table[:, 0], table[:, 1])
    ok = _away_from(t, np.arange(1, 4) * T)     # the jump at each wrap
    _close(res["src.y[0].signal"][ok], ref[ok], 3.0, tol=1e-11)
    expected = sorted({round(k * T + ti, 12) for k in range(4) for ti in table[1:, 0]
                       if 0 < k * T + ti < 4.5})
    assert np.allclose([float(e) for e in res.events], expected, rtol=1e-12, atol=0)
    # the signal integrates over each period to the table's trapezoid sum
    per = np.trapezoid(table[:, 1], table[:, 0])
    rest = 4.5 - 3 * T               # trapezoids on the rows are exact for linear segments
    xs = np.append(table[table[:, 0] < rest, 0], rest)
    part = np.trapezoid(np.interp(xs, table[:, 0], table[:, 1]), xs)
    assert res["x"][-1] == pytest.approx(3 * per + part, rel=1e-9)


@pytest.mark.parametrize("smoothness", ["linear", "smooth"])
def test_hold_and_last_two_points(smoothness):
    table = np.array([[1.0, 2.0], [2.0, 3.0], [3.0, 2.5], [4.0, 0.5]])
    t = np.linspace(0.0, 6.0, 241)
    x, y = table[:, 0], table[:, 1]
    for extrapolation in ("hold", "last_two_points"):
        res = ac.simulate(_source(table, smoothness=smoothness, extrapolation=extrapolation),
                          t_end=6.0, rtol=1e-10, t_eval=t)
        if smoothness == "linear" and extrapolation == "hold":
            ref = np.interp(t, x, y)
        elif smoothness == "linear":
            ref = interp1d(x, y, fill_value="extrapolate")(t)
        else:
            p = PchipInterpolator(x, y)
            d = p.derivative()
            ref = p(np.clip(t, 1, 4))
            if extrapolation == "last_two_points":
                ref = np.where(t < 1, y[0] + d(1.0) * (t - 1),
                               np.where(t > 4, y[-1] + d(4.0) * (t - 4), ref))
        _close(res["src.y[0].signal"], ref, 3.0)


def test_table1d_friction_curve_against_solve_ivp():
    """m dv/dt = F(t) - f(v): a mass pushed by F = 3 sin(t) against a measured friction
    curve f(v) (an odd table with a Stribeck dip)."""
    vs = np.array([-3.0, -1.0, -0.3, -0.05, 0.05, 0.3, 1.0, 3.0])
    fs = np.array([-2.5, -1.2, -0.9, -1.4, 1.4, 0.9, 1.2, 2.5])
    m = 0.5

    class Slider(ac.Component):
        friction = CombiTable1D(table=np.column_stack([vs, fs]),
                                extrapolation="last_two_points")
        v = ac.Variable(start=0.0, fixed=True)

        def equations(self):
            return [ac.Eq(self.friction.u.signal, self.v),
                    ac.Eq(m * ac.der(self.v), 3.0 * ac.sin(ac.time) - self.friction.y[0])]

    t = np.linspace(0.0, 10.0, 201)
    res = ac.simulate(Slider(), t_end=10.0, rtol=1e-10, t_eval=t)
    f_ref = interp1d(vs, fs, fill_value="extrapolate")
    ref = solve_ivp(lambda tt, v: [(3.0 * np.sin(tt) - f_ref(v[0])) / m], (0, 10), [0.0],
                    t_eval=t, rtol=1e-12, atol=1e-13, method="DOP853", dense_output=True)
    scale = np.max(np.abs(ref.y[0]))
    assert scale > 1.0      # the mass crosses several breakpoints both ways
    _close(res["v"], ref.y[0], scale, tol=1e-7)
    # every event is the velocity passing a breakpoint of the curve
    v_at = ref.sol(np.array([float(e) for e in res.events]))[0]
    assert len(v_at) >= 4
    assert np.all(np.min(np.abs(v_at[:, None] - vs[None, :]), axis=1) < 1e-6 * scale)


def _periodic_curve(aliased):
    """u = 2 x - 1 (or u = x, an alias) with der(x) = 1 (a state): the breakpoints and the
    period wraps are state events; y[1] is a second column on the same relations."""
    table = np.array([[-1.0, 0.0, 1.0], [0.0, 2.0, -1.0], [1.5, 1.0, 0.0]])

    class Curve(ac.Component):
        tab = CombiTable1D(table=table, extrapolation="periodic")
        x = ac.Variable(start=0.0, fixed=True)

        def equations(self):
            return [ac.Eq(ac.der(self.x), 1.0),
                    ac.Eq(self.tab.u.signal, self.x if aliased else 2.0 * self.x - 1.0)]

    t = np.linspace(0.0, 3.5, 141)
    res = ac.simulate(Curve(), t_end=3.5, rtol=1e-10, t_eval=t)
    u = t if aliased else 2.0 * t - 1.0
    phase = -1.0 + np.mod(u + 1.0, 2.5)
    ok = np.abs(np.mod(u + 1.0 + 1e-9, 2.5)) > 1e-8      # away from the wraps
    for j in (0, 1):
        ref = np.interp(phase, table[:, 0], table[:, 1 + j])
        _close(res[f"tab.y[{j}].signal"][ok], ref[ok], 2.0, tol=1e-8)


def test_table1d_periodic_in_a_state_and_two_columns():
    _periodic_curve(aliased=False)


def test_table1d_periodic_input_aliased_to_a_state():
    """The table's input is an alias of a state (u = x): its frozen mod() reads x."""
    _periodic_curve(aliased=True)


@pytest.mark.parametrize("extrapolation", ["hold", "last_two_points"])
def test_table2d_bilinear_against_regular_grid(extrapolation):
    g1, g2 = np.array([0.0, 0.5, 1.5, 2.0]), np.array([-1.0, 0.0, 1.0])
    vals = np.array([[0.0, 1.0, 2.0], [1.0, 3.0, 1.0], [-1.0, 0.5, 4.0], [2.0, 2.0, 0.0]])

    class Map(ac.Component):
        tab = CombiTable2D(grid1=g1, grid2=g2, values=vals, extrapolation=extrapolation)

        def equations(self):
            return [ac.Eq(self.tab.u1.signal, ac.time - 0.5),
                    ac.Eq(self.tab.u2.signal, 1.4 * ac.sin(2.0 * ac.time))]

    t = np.linspace(0.0, 3.0, 301)
    res = ac.simulate(Map(), t_end=3.0, rtol=1e-10, t_eval=t)
    u1, u2 = t - 0.5, 1.4 * np.sin(2.0 * t)
    if extrapolation == "hold":
        u1, u2 = np.clip(u1, g1[0], g1[-1]), np.clip(u2, g2[0], g2[-1])
    ref = RegularGridInterpolator((g1, g2), vals, bounds_error=False, fill_value=None)(
        np.column_stack([u1, u2]))
    _close(res["tab.y.signal"], ref, 4.0, tol=1e-10)


def test_large_table_is_a_balanced_tree():
    n = 1000
    x = np.linspace(0.0, 10.0, n)
    expr = interpolant(ac.time, x, np.sin(x))

    def depth(e):
        return 1 + max((depth(a) for a, _ in e.args), default=0) if e.func.__name__ == \
            "Piecewise" else 0
    assert depth(expr) == int(np.ceil(np.log2(n + 1)))
    rels = {c for pw in expr.atoms(sp.Piecewise) for _, c in pw.args if c != sp.true}
    assert len(rels) == n            # one relation per row, shared by all branches


def test_csv_reading(tmp_path):
    path = tmp_path / "data.csv"
    path.write_text("# measured flow\ntime, q1, q2\n0, 1.5, 2\n0.5; 2.5; 3  # note\n\n"
                    "1.0\t0\t-1\n")
    data = read_table(path)
    assert np.array_equal(data, [[0, 1.5, 2], [0.5, 2.5, 3], [1.0, 0, -1]])
    t = np.linspace(0.0, 1.0, 11)
    res = ac.simulate(_source(str(path), columns=[3]), t_end=1.0, rtol=1e-10, t_eval=t)
    _close(res["src.y[0].signal"], np.interp(t, data[:, 0], data[:, 2]), 3.0)


@pytest.mark.parametrize("text, words", [
    ("0, 1\n1, __import__('os').system('false')\n", ["line 2", "is not a number"]),
    ("0, 1\n1, 2, 3\n", ["line 2", "columns"]),
    ("0, 1\n2, 2\n1, 3\n", ["line 3", "must not decrease"]),
    ("0, 1\n1, nan\n", ["line 2", "finite"]),
    ("0, 1\n", ["at least 2 rows"]),
    ("# nothing\n", ["no table rows"]),
])
def test_malformed_csv_is_a_typed_error(tmp_path, text, words):
    path = tmp_path / "bad.csv"
    path.write_text(text)
    with pytest.raises(ac.InvalidValue) as err:
        CombiTimeTable(table=str(path))
    msg = str(err.value)
    assert "CombiTimeTable" in msg and str(path) in msg
    assert all(w in msg for w in words)


@pytest.mark.parametrize("kw, words", [
    (dict(table=[[0, 1], [1, 2], [1, 3], [1, 4]]), ["three times"]),
    (dict(table=[[0, 1, 2]]), ["at least 2 rows"]),
    (dict(table=[1, 2, 3]), ["2-D"]),
    (dict(table=[[0, 1], [1, 2]], columns=[3]), ["column 3"]),
    (dict(table=[[0, 1], [1, 2]], smoothness="cubic"), ["smoothness"]),
    (dict(table=[[0, 1], [1, np.inf]]), ["row 2", "finite"]),
])
def test_malformed_array_is_a_typed_error(kw, words):
    with pytest.raises(ac.InvalidValue) as err:
        CombiTable1D(**kw)
    assert all(w in str(err.value) for w in words) and "CombiTable1D" in str(err.value)


def test_malformed_2d_grid_is_a_typed_error():
    with pytest.raises(ac.InvalidValue, match="grid2"):
        CombiTable2D(grid1=[0, 1], grid2=[1, 0], values=[[0, 0], [0, 0]])
    with pytest.raises(ac.InvalidValue, match="shape"):
        CombiTable2D(grid1=[0, 1], grid2=[0, 1, 2], values=[[0, 0], [0, 0]])
