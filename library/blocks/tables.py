"""Lookup tables and measured input data (Modelica.Blocks.Sources.CombiTimeTable,
Modelica.Blocks.Tables.CombiTable1Ds and CombiTable2Ds).

A table is turned into one expression per output column whose pieces are chosen by
relations of the abscissa alone, ``x < x_k`` for each distinct breakpoint ``x_k``.  The
relations are arranged as a balanced binary search tree of ``if_else`` (depth
``ceil(log2 n)``), not as a chain of ``n`` nested branches: a 1000-row table then
evaluates about 10 relations per call, and every column of a table shares the same
relations.  (A chain also fails outright: past about 200 rows its generated code exceeds
Python's limit on nested parentheses.  Measured, medians of 3 on a shared 2-core
machine: a 1000-row time table compiles in about 6 s, 1.6 s of it building the tree.)
For :class:`CombiTimeTable` the abscissa is ``(time - shiftTime) / timeScale``, linear in
time, so every breakpoint is an exact time event (the integrator lands on it);
periodic extrapolation reads the phase through ``Mod`` (a frozen floor value, switching
at the start of each period), which keeps the relations linear in time between events.
For :class:`CombiTable1D` and :class:`CombiTable2D` the abscissa is an input, and the
breakpoints are state events located on the input's trajectory.

Interpolation on a segment [x_a, x_b] with h = x_b - x_a and s = (x - x_a)/h:

* ``"linear"``:    y = y_a + (y_b - y_a) s
* ``"constant"``:  y = y_a (the value of the row at the segment's left end)
* ``"smooth"``:    the cubic Hermite polynomial
  y = (2s^3 - 3s^2 + 1) y_a + (s^3 - 2s^2 + s) h d_a + (-2s^3 + 3s^2) y_b + (s^3 - s^2) h d_b
  with the monotone slopes d_k of Fritsch & Carlson (SIAM J. Numer. Anal. 17, 1980) in
  the weighted harmonic-mean form of Fritsch & Butland (1984) and the one-sided
  three-point end slopes of Moler (*Numerical Computing with MATLAB*, sec. 3.4), i.e.
  what scipy's ``PchipInterpolator`` computes.  Chosen over Akima's spline because
  measured data (a valve opening, a flow rate) must not overshoot: a monotone interval of
  the data stays monotone and the curve never leaves the range of its neighbours; it is
  C1 and local (a row changes only its neighbouring segments).

Repeated abscissae (two rows with the same x) are a jump, as in the MSL: the output is
continuous from the left up to x and takes the value of the later row from x on.  The
smooth interpolant is computed separately on each side of a jump.

Extrapolation outside [x_first, x_last]:

* ``"hold"``: the first / last value.
* ``"last_two_points"``: the straight line continuing the end segment (its slope at the
  end for ``"smooth"``, zero for ``"constant"``).
* ``"periodic"``: the table repeats with period x_last - x_first,
  x -> x_first + mod(x - x_first, x_last - x_first); the last row's value is taken at
  the start of the next period.  The smooth slopes are those of the table as given
  (C1 across the wrap only if the data are).

Tables are given as arrays or CSV files.  A CSV file is read as text, field by field with
``float`` (it never executes anything from the file); ``#`` starts a comment, fields are
separated by commas, semicolons or white space, and one header line of names is allowed.
A malformed table raises :class:`acausal.InvalidValue` naming the component, the file and
the line.
"""
from __future__ import annotations

import math
import os
import re

import numpy as np
from acausal._sympy import sympy as sp

import acausal as ac
from acausal.ports import RealInput, RealOutput

__all__ = ["CombiTimeTable", "CombiTable1D", "CombiTable2D", "read_table"]

SMOOTHNESS = ("linear", "constant", "smooth")
EXTRAPOLATION = ("hold", "last_two_points", "periodic")
_SPLIT = re.compile(r"[,;\s]+")


# -- reading and checking -----------------------------------------------------------------
def read_table(path, owner: str = "table") -> np.ndarray:
    """The numbers of a CSV/text file as an (n x m) float array (module docstring)."""
    rows, width, header_seen = [], None, False
    try:
        with open(path, newline="") as fh:
            lines = fh.read().splitlines()
    except OSError as err:
        raise ac.InvalidValue(f"{owner}: cannot read table file {path}: {err.strerror}") from None
    for lineno, line in enumerate(lines, start=1):
        text = line.split("#", 1)[0].strip()
        if not text:
            continue
        fields = [f for f in _SPLIT.split(text) if f]
        try:
            values = [float(f) for f in fields]
        except ValueError:
            if not rows and not header_seen:
                header_seen = True          # one line of column names before the data
                continue
            bad = next(f for f in fields if not _is_float(f))
            raise ac.InvalidValue(f"{owner}: {path}, line {lineno}: {bad!r} is not a "
                                  "number") from None
        if width is None:
            width = len(values)
        elif len(values) != width:
            raise ac.InvalidValue(f"{owner}: {path}, line {lineno}: {len(values)} columns, "
                                  f"the lines before have {width}")
        rows.append((lineno, values))
    if not rows:
        raise ac.InvalidValue(f"{owner}: {path} holds no table rows")
    data = np.array([v for _, v in rows], dtype=float)
    _check(data, f"{owner}: {path}", ", line ", [n for n, _ in rows])
    return data


def _is_float(text) -> bool:
    try:
        float(text)
        return True
    except ValueError:
        return False


def _as_table(table, owner: str) -> np.ndarray:
    """The table given as an array or a path, checked."""
    if isinstance(table, (str, os.PathLike)):
        return read_table(table, owner)
    try:
        data = np.array(table, dtype=float)
    except (TypeError, ValueError):
        raise ac.InvalidValue(f"{owner}: table must be a 2-D array of numbers or a file "
                              "path") from None
    if data.ndim != 2:
        raise ac.InvalidValue(f"{owner}: table must be 2-D (rows of abscissa, values), "
                              f"got shape {data.shape}")
    _check(data, owner, ": row ", list(range(1, data.shape[0] + 1)))
    return data


def _check(data, owner, where, line_of):
    """Shape, finite values, abscissa non-decreasing with at most two equal in a row.
    ``owner`` names the component (and file), ``where + line_of[i]`` the row i."""
    n, m = data.shape
    if n < 2 or m < 2:
        raise ac.InvalidValue(f"{owner}: a table needs at least 2 rows and 2 columns "
                              f"(abscissa and one value column), got {n} x {m}")
    bad = np.argwhere(~np.isfinite(data))
    if bad.size:
        i, j = bad[0]
        raise ac.InvalidValue(f"{owner}{where}{line_of[i]}: column {j + 1} is "
                              f"{data[i, j]} (not a finite number)")
    x = data[:, 0]
    for i in range(1, n):
        if x[i] < x[i - 1]:
            raise ac.InvalidValue(f"{owner}{where}{line_of[i]}: abscissa {x[i]} is below "
                                  f"the previous row's {x[i - 1]} (must not decrease)")
        if i >= 2 and x[i] == x[i - 1] == x[i - 2]:
            raise ac.InvalidValue(f"{owner}{where}{line_of[i]}: abscissa {x[i]} appears "
                                  "three times (two equal rows make a jump, no more)")
    if x[-1] == x[0]:
        raise ac.InvalidValue(f"{owner}: the abscissa spans no interval ({x[0]} only)")


def _choice(value, allowed, what, owner):
    if value not in allowed:
        raise ac.InvalidValue(f"{owner}: {what} must be one of {', '.join(allowed)}, "
                              f"not {value!r}")
    return value


def _columns(columns, m, owner) -> list:
    """1-based column numbers of the value columns (MSL convention: column 1 is x)."""
    cols = list(range(2, m + 1)) if columns is None else [int(c) for c in columns]
    if not cols:
        raise ac.InvalidValue(f"{owner}: columns is empty")
    for c in cols:
        if not 2 <= c <= m:
            raise ac.InvalidValue(f"{owner}: column {c} is not a value column of the table "
                                  f"(2 ... {m}; column 1 is the abscissa)")
    return cols


# -- the interpolant as pieces -------------------------------------------------------------
def _pchip_slopes(x, y) -> np.ndarray:
    """Monotone C1 slopes at the points x (strictly increasing), module docstring."""
    n = len(x)
    h = np.diff(x)
    delta = np.diff(y) / h
    if n == 2:
        return np.array([delta[0], delta[0]])
    d = np.zeros(n)
    for k in range(1, n - 1):
        if delta[k - 1] * delta[k] > 0:
            w1, w2 = 2 * h[k] + h[k - 1], h[k] + 2 * h[k - 1]
            d[k] = (w1 + w2) / (w1 / delta[k - 1] + w2 / delta[k])
    d[0] = _end_slope(h[0], h[1], delta[0], delta[1])
    d[-1] = _end_slope(h[-1], h[-2], delta[-1], delta[-2])
    return d


def _end_slope(h0, h1, m0, m1) -> float:
    """Three-point one-sided slope, limited to keep the end segment monotone."""
    d = ((2 * h0 + h1) * m0 - h0 * m1) / (h0 + h1)
    if math.copysign(1, d) != math.copysign(1, m0) or m0 == 0:
        return 0.0
    if math.copysign(1, m0) != math.copysign(1, m1) and abs(d) > abs(3 * m0):
        return 3 * m0
    return d


class _Pieces:
    """One column's segments between the distinct abscissae ``knots``.

    ``seg[k] = (x_a, y_a, d_a, x_b, y_b, d_b)`` for the interval [knots[k], knots[k+1]),
    with ``y_a`` the value of the later row at a jump and ``y_b`` the earlier one.
    """

    def __init__(self, x, y, smoothness):
        self.knots = np.unique(x)
        last = {xi: i for i, xi in enumerate(x)}            # last row at each abscissa
        first = {xi: i for i, xi in reversed(list(enumerate(x)))}
        slope = np.zeros(len(x))
        if smoothness == "smooth":
            # pieces between jumps are interpolated separately
            starts = [0] + [i for i in range(1, len(x)) if x[i] == x[i - 1]]
            ends = starts[1:] + [len(x)]
            for a, b in zip(starts, ends):
                if b - a >= 2:
                    slope[a:b] = _pchip_slopes(x[a:b], y[a:b])
        self.seg = []
        for xa, xb in zip(self.knots[:-1], self.knots[1:]):
            i, j = last[xa], first[xb]
            self.seg.append((xa, y[i], slope[i], xb, y[j], slope[j]))
        self.y_first, self.y_last = y[0], y[-1]
        self.smoothness = smoothness

    def leaf(self, k, x):
        """The interpolant on segment k as an expression of x."""
        xa, ya, da, xb, yb, db = self.seg[k]
        if self.smoothness == "constant":
            return sp.Float(float(ya))
        h, dx = xb - xa, x - float(xa)
        if self.smoothness == "linear":
            return float(ya) + float((yb - ya) / h) * dx
        # the Hermite form above in powers of dx (Horner): exact y_a at x_a
        m = (yb - ya) / h
        c2 = (3 * m - 2 * da - db) / h
        c3 = (da + db - 2 * m) / h**2
        return float(ya) + dx * (float(da) + dx * (float(c2) + dx * float(c3)))

    def outside(self, x, extrapolation):
        """(left, right): the expressions below the first and from the last knot on."""
        if extrapolation != "last_two_points" or self.smoothness == "constant":
            return sp.Float(float(self.y_first)), sp.Float(float(self.y_last))
        xa, ya, da, xb, yb, db = self.seg[0]
        left_slope = da if self.smoothness == "smooth" else (yb - ya) / (xb - xa)
        left = float(self.y_first) + float(left_slope) * (x - float(xa))
        xa, ya, da, xb, yb, db = self.seg[-1]
        right_slope = db if self.smoothness == "smooth" else (yb - ya) / (xb - xa)
        return left, float(self.y_last) + float(right_slope) * (x - float(xb))


def _search_tree(x, knots, leaves):
    """``leaves[k]`` where ``knots[k-1] <= x < knots[k]`` (leaves[0] below knots[0],
    leaves[n] from knots[n-1] on), as a balanced tree of if_else on ``x < knot``."""
    def build(lo, hi):
        if lo == hi:
            return leaves[lo]
        mid = (lo + hi) // 2          # intervals lo..mid lie below knots[mid]
        # ac.if_else's form, built unevaluated: sympy's Piecewise simplification walks
        # the whole subtree at every level, quadratic in the table's length
        return sp.Piecewise((build(lo, mid), sp.StrictLessThan(x, float(knots[mid]))),
                            (build(mid + 1, hi), sp.true), evaluate=False)
    return build(0, len(leaves) - 1)


def interpolant(x, xs, ys, smoothness="linear", extrapolation="hold"):
    """The table (xs, ys) at the expression ``x``, as an event-generating expression."""
    pieces = _Pieces(np.asarray(xs, float), np.asarray(ys, float), smoothness)
    knots = pieces.knots
    if extrapolation == "periodic":
        period = float(knots[-1] - knots[0])
        x = float(knots[0]) + sp.Mod(x - float(knots[0]), period)
    left, right = pieces.outside(x, extrapolation)
    leaves = [left] + [pieces.leaf(k, x) for k in range(len(pieces.seg))] + [right]
    if extrapolation == "periodic":
        # x stays in [knots[0], knots[-1]): the outer intervals are never taken
        leaves = leaves[1:-1]
        return _search_tree(x, knots[1:-1], leaves)
    return _search_tree(x, knots, leaves)


# -- the blocks ----------------------------------------------------------------------------
class _TableBlock(ac.Component):
    """Outputs ``y[0] ... y[m-1]``, one per selected column, plus the checked table."""

    def _setup(self, table, columns, smoothness, extrapolation):
        owner = type(self).__name__
        self.data = _as_table(table, owner)
        self.columns = _columns(columns, self.data.shape[1], owner)
        self.smoothness = _choice(smoothness, SMOOTHNESS, "smoothness", owner)
        self.extrapolation = _choice(extrapolation, EXTRAPOLATION, "extrapolation", owner)
        self.y = [RealOutput() for _ in self.columns]

    def _values(self, x):
        return [interpolant(x, self.data[:, 0], self.data[:, c - 1], self.smoothness,
                            self.extrapolation) for c in self.columns]


class CombiTimeTable(_TableBlock):
    """Time table (Modelica.Blocks.Sources.CombiTimeTable):

        y[j] = offset + f_j((time - shiftTime) / timeScale)   for time >= startTime,
        y[j] = offset                                          for time <  startTime,

    with f_j the interpolant of table column ``columns[j]`` (1-based; column 1 is time)
    over the first column, as the module docstring describes.  ``table`` is an
    (n x (1 + m)) array or the path of a CSV file.  Every breakpoint is a time event.

    Examples
    --------
    >>> src = CombiTimeTable(table=[[0, 0], [1, 2], [2, 2]])   # ramp up, then hold
    >>> len(src.y)
    1
    """

    offset = ac.Parameter(0.0, description="added to every output")
    timeScale = ac.Parameter(1.0, unit="s", min=0, description="unit of the table's time")
    startTime = ac.Parameter(0.0, unit="s", description="output = offset before startTime")
    shiftTime = ac.Parameter(lambda c: c.startTime, unit="s",
                             description="time of the table's zero (default startTime)")

    def __init__(self, table=((0.0, 0.0), (1.0, 1.0)), columns=None, smoothness="linear",
                 extrapolation="hold", **mods):
        super().__init__(**mods)
        self._setup(table, columns, smoothness, extrapolation)

    def equations(self):
        tau = (ac.time - self.shiftTime) / self.timeScale
        return [ac.Eq(y, self.offset + ac.if_else(ac.time >= self.startTime, f, 0))
                for y, f in zip(self.y, self._values(tau))]


class CombiTable1D(_TableBlock):
    """Characteristic u -> y (Modelica.Blocks.Tables.CombiTable1Ds):

        y[j] = f_j(u)

    with f_j the interpolant of column ``columns[j]`` (1-based; column 1 is u) as in the
    module docstring: a valve or pump curve, a friction table.  The breakpoints are
    state events of u.
    """

    u = RealInput()

    def __init__(self, table=((0.0, 0.0), (1.0, 1.0)), columns=None, smoothness="linear",
                 extrapolation="hold", **mods):
        super().__init__(**mods)
        self._setup(table, columns, smoothness, extrapolation)

    def equations(self):
        return [ac.Eq(y, f) for y, f in zip(self.y, self._values(self.u.signal))]


class CombiTable2D(ac.Component):
    """Bilinear table y = f(u1, u2) on a grid (Modelica.Blocks.Tables.CombiTable2Ds).

    On the cell [a_i, a_{i+1}] x [b_j, b_{j+1}], with s = (u1 - a_i)/(a_{i+1} - a_i) and
    r = (u2 - b_j)/(b_{j+1} - b_j):

        y = (1-s)(1-r) v_ij + s(1-r) v_(i+1)j + (1-s) r v_i(j+1) + s r v_(i+1)(j+1)

    ``grid1`` (n1, strictly increasing) and ``grid2`` (n2) are the abscissae of u1 and u2,
    ``values`` the (n1 x n2) array v.  Outside the grid: ``"hold"`` clamps each input to
    its range, ``"last_two_points"`` continues the edge cells' bilinear form.
    """

    u1 = RealInput()
    u2 = RealInput()
    y = RealOutput()

    def __init__(self, grid1=(0.0, 1.0), grid2=(0.0, 1.0), values=((0.0, 0.0), (0.0, 0.0)),
                 extrapolation="hold", **mods):
        super().__init__(**mods)
        owner = type(self).__name__
        self.grid1 = self._grid(grid1, "grid1", owner)
        self.grid2 = self._grid(grid2, "grid2", owner)
        try:
            v = np.array(values, dtype=float)
        except (TypeError, ValueError):
            raise ac.InvalidValue(f"{owner}: values must be an array of numbers") from None
        if v.shape != (len(self.grid1), len(self.grid2)):
            raise ac.InvalidValue(f"{owner}: values has shape {v.shape}, the grids need "
                                  f"{(len(self.grid1), len(self.grid2))}")
        if not np.all(np.isfinite(v)):
            i, j = np.argwhere(~np.isfinite(v))[0]
            raise ac.InvalidValue(f"{owner}: values[{i}, {j}] is {v[i, j]} (not finite)")
        self.values = v
        self.extrapolation = _choice(extrapolation, ("hold", "last_two_points"),
                                     "extrapolation", owner)

    @staticmethod
    def _grid(g, name, owner):
        g = np.array(g, dtype=float).ravel()
        if g.size < 2 or not np.all(np.isfinite(g)) or np.any(np.diff(g) <= 0):
            raise ac.InvalidValue(f"{owner}: {name} must hold at least 2 finite, strictly "
                                  f"increasing values, got {g.tolist()}")
        return g

    def equations(self):
        a, b, v = self.grid1, self.grid2, self.values

        def bilinear(i, s, j, r):
            return ((1 - s) * (1 - r) * v[i, j] + s * (1 - r) * v[i + 1, j]
                    + (1 - s) * r * v[i, j + 1] + s * r * v[i + 1, j + 1])

        def inner(i, s):
            return _axis_tree(self.u2.signal, b, self.extrapolation,
                              lambda j, r: bilinear(i, s, j, r))

        return [ac.Eq(self.y, _axis_tree(self.u1.signal, a, self.extrapolation, inner))]


def _axis_tree(u, grid, extrapolation, leaf):
    """``leaf(i, s)`` on the grid interval i that holds u, s = (u - g_i)/(g_(i+1) - g_i)
    its fraction; outside the grid s is held at 0 or 1 (``"hold"``) or continues
    linearly on the edge interval (``"last_two_points"``)."""
    n = len(grid) - 1
    cells = [leaf(i, (u - grid[i]) / (grid[i + 1] - grid[i])) for i in range(n)]
    if extrapolation == "hold":
        return _search_tree(u, grid, [leaf(0, 0)] + cells + [leaf(n - 1, 1)])
    return _search_tree(u, grid[1:-1], cells)
