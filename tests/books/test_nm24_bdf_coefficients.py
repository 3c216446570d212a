"""NM-24: the backward differentiation formulas and their linear stability (Egeland &
Gravdahl, 001 §14.11.4, §14.11.7, §14.11.10, (14.282)-(14.289)).

The book's BDF of order q, sum_{m=1..q} (1/m) nabla^m y_{n+1} = h f(y_{n+1}, t_{n+1}),
printed for q = 1..6:

    q = 1:  y_{n+1} - y_n
    q = 2:  3/2 y_{n+1} - 2 y_n + 1/2 y_{n-1}
    q = 3:  11/6 y_{n+1} - 3 y_n + 3/2 y_{n-1} - 1/3 y_{n-2}
    q = 4:  25/12 y_{n+1} - 4 y_n + 3 y_{n-1} - 4/3 y_{n-2} + 1/4 y_{n-3}
    q = 5:  137/60 y_{n+1} - 5 y_n + 5 y_{n-1} - 10/3 y_{n-2} + 5/4 y_{n-3} - 1/5 y_{n-4}

(each = h f_{n+1}; acausal's BDF goes to order 5).  For y' = lambda y the characteristic
equation is N(z) - h lambda z^q = 0 (14.284), its roots inside the unit circle for
stability; BDF1 and BDF2 are stable whenever Re(lambda) <= 0, and as lambda h -> infinity
all q roots go to z = 0, so stiff modes are damped out.

acausal's integrator (solvers/bdf.py) is the fixed-leading-coefficient form of DASSL/IDA
on modified divided differences; at a constant step it must reduce to these formulas.
It is driven here on y' = A y with its step held at h (first_step = max_step = h) and
its error test opened (a huge rtol), so every step is accepted at the order it reaches;
the iteration matrix is rebuilt each step so that the linear corrector is solved
exactly.  Checked, once the steps and the order have been constant for q + 1 steps:

* the computed points satisfy the book's formula of that order to round-off, on an
  oscillator at h omega = 0.5 (where a formula with other coefficients of the same order
  would leave a residual of order (h omega)^(q+1));
* the per-step amplification equals the largest root of the book's characteristic
  equation: <= 1 for q = 1, 2 at h omega = 0.1, 0.5, 2 (A-stable; at larger h omega the order
  selection keeps order 1 on the quickly vanishing solution), > 1 for q = 3, 4
  at h omega = 0.5 (not A-stable);
* the book's roots go to z = 0 as |h lambda|^(-1/q) when h lambda -> -infinity, and at
  h lambda = -1e8 each of acausal's steps multiplies y by less than 1e-6.
"""
from fractions import Fraction as Fr

import numpy as np
import pytest

from acausal.solvers.base import DAEProblem
from acausal.solvers.bdf import BDF, MAX_ORDER

BOOK = {1: [1, -1],
        2: [Fr(3, 2), -2, Fr(1, 2)],
        3: [Fr(11, 6), -3, Fr(3, 2), Fr(-1, 3)],
        4: [Fr(25, 12), -4, 3, Fr(-4, 3), Fr(1, 4)],
        5: [Fr(137, 60), -5, 5, Fr(-10, 3), Fr(5, 4), Fr(-1, 5)]}
H = 0.01


class Linear(DAEProblem):
    """y' = A y as the residual y' - A y, with its exact iteration matrix."""

    def __init__(self, A):
        self.A = np.atleast_2d(np.asarray(A, dtype=float))
        super().__init__(self.A.shape[0])

    def residual(self, t, y, yp):
        return yp - self.A @ y

    def jacobian(self, t, y, yp, cj):
        return cj * np.eye(self.n) - self.A


def _run(A, y0, order, n_steps):
    problem = Linear(A)
    y0 = np.asarray(y0, dtype=float)
    bdf = BDF(problem, 0.0, y0, problem.A @ y0, rtol=1e6, atol=1e6, first_step=H,
              max_step=H, max_order=order, t_stop=(n_steps + 10) * H)
    t, y, k = [0.0], [y0.copy()], [0]
    for _ in range(n_steps):
        bdf.force_setup = True          # a fresh matrix: the linear corrector is exact
        bdf.step()
        t.append(bdf.tn)
        y.append(bdf.y.copy())
        k.append(bdf.kused)
    return np.array(t), np.array(y), np.array(k)


def _settled(t, k, order):
    """Indices n whose last order + 1 steps were all of size H at this order."""
    steps = np.diff(t)
    return [n for n in range(order + 1, len(t))
            if np.all(k[n - order:n + 1] == order)
            and np.allclose(steps[n - order - 1:n], H, rtol=1e-12)]


def _oscillator(h_omega):
    return (h_omega / H) * np.array([[0.0, 1.0], [-1.0, 0.0]])


def _largest_root(order, h_lambda):
    a = np.array([complex(c) for c in BOOK[order]])
    a[0] -= h_lambda
    return np.max(np.abs(np.roots(a)))


def test_max_order_is_5():
    assert MAX_ORDER == 5


@pytest.mark.parametrize("order", [1, 2, 3, 4, 5])
def test_constant_step_points_satisfy_the_book_formula(order):
    A = _oscillator(0.5)
    t, y, k = _run(A, [1.0, 0.0], order, 80)
    rows = _settled(t, k, order)
    assert len(rows) > 20
    a = [float(c) for c in BOOK[order]]
    worst = 0.0
    for n in rows:
        lhs = sum(a[j] * y[n - j] for j in range(order + 1))
        size = sum(abs(a[j]) * np.max(np.abs(y[n - j])) for j in range(order + 1))
        worst = max(worst, np.max(np.abs(lhs - H * A @ y[n])) / size)
    # round-off of the corrector's linear solve, relative to the terms of the formula; a
    # coefficient wrong in its third digit leaves a residual of order 1e-3 of them
    assert worst < 1e-10


def _amplification(order, h_omega):
    # enough steps to measure, few enough that |y| stays far above underflow
    root = _largest_root(order, 1j * h_omega)
    n_steps = int(min(300, 40 + 30 / max(abs(np.log10(root)), 1e-3)))
    t, y, k = _run(_oscillator(h_omega), [1.0, 0.0], order, n_steps)
    rows = _settled(t, k, order)
    first, last = rows[len(rows) // 2], rows[-1]
    norm = np.linalg.norm(y, axis=1)
    return (norm[last] / norm[first]) ** (1.0 / (last - first))


@pytest.mark.parametrize("order", [1, 2])
@pytest.mark.parametrize("h_omega", [0.1, 0.5, 2.0])
def test_bdf1_bdf2_damp_on_the_imaginary_axis(order, h_omega):
    growth = _amplification(order, h_omega)
    root = _largest_root(order, 1j * h_omega)
    assert root <= 1.0
    assert growth == pytest.approx(root, rel=1e-9)


@pytest.mark.parametrize("order", [3, 4])
def test_bdf3_bdf4_grow_near_the_imaginary_axis(order):
    growth = _amplification(order, 0.5)
    root = _largest_root(order, 0.5j)
    assert root > 1.0
    assert growth == pytest.approx(root, rel=1e-9)


@pytest.mark.parametrize("order", [1, 2, 3, 4, 5])
def test_stiff_limit_roots_go_to_zero(order):
    """The book's formulas: as h lambda -> -infinity all q roots go to z = 0, as
    |h lambda|^(-1/q) (the polynomial tends to (a_0 - h lambda) z^q)."""
    r12, r16 = _largest_root(order, -1e12), _largest_root(order, -1e16)
    assert r16 < r12 < 2e-2
    # the next term of the expansion is O(|z|): 1e-2 at most here
    assert r12 / r16 == pytest.approx(1e4 ** (1.0 / order), rel=1e-2)


def test_stiff_mode_is_damped_out_in_one_step():
    """acausal at h lambda = -1e8 (it stays at order 1 there: the estimates of higher
    orders never win on a solution that vanishes): every step divides y by > 1e6."""
    t, y, k = _run(np.array([[-1e8 / H]]), [1.0], 5, 12)
    ratios = np.abs(y[1:, 0]) / np.abs(y[:-1, 0])
    assert np.all(ratios < 1e-6)
