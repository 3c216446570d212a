"""The sparse LU of the compiled step loop (solvers/cbdf_sparse.c) and the compiled loop
on systems above MAX_DENSE unknowns.

The LU is judged by the backward error of its solutions (``||A x - b||`` against
``||A|| ||x||``, which a stable LU keeps at a small multiple of the unit round-off), on
matrices whose values drift away from the analysed ones.  The compiled loop on models
of 220-250 unknowns is judged against the Python loop (SuperLU) at a tolerance 100 times
tighter, relative to each signal's peak: both loops integrate the same method, so they
differ by the integration error of the looser run, which at rtol 1e-8 stays below 1e-6
of the signal's peak on these circuits, in either loop.
"""
import numpy as np
import pytest
import scipy.sparse as sps

import acausal as ac
from acausal.library import electrical as el
from acausal.solvers.cbdf import MAX_DENSE, library
from acausal.solvers.cbdf_sparse import SparseLU
from acausal.solvers.linalg import LinearSolver, SingularMatrixError

pytestmark = pytest.mark.skipif(library() is None, reason="no C compiler on this machine")

_EPS = np.finfo(float).eps


def _iteration_like(n, seed, cj=1e3):
    """cj I plus a random sparse coupling, and a few algebraic rows without cj."""
    rng = np.random.default_rng(seed)
    A = sps.random(n, n, density=4.0 / n, random_state=rng, format="lil")
    for i in range(n):
        A[i, i] = cj * (0.0 if i % 7 == 3 else 1.0) + rng.standard_normal()
    return sps.csc_matrix(A)


def _factor(A, analysed=None):
    lu = SparseLU(library(), A.shape[0], A.indptr, A.indices, np.arange(A.nnz),
                  A if analysed is None else analysed)
    return lu, lu.factor(A.data)


def _backward_error(A, x, b):
    return np.linalg.norm(A @ x - b) / (abs(A).sum(axis=0).max() * np.abs(x).sum())


def test_solutions_have_a_backward_error_of_a_few_round_offs():
    A = _iteration_like(400, seed=1)
    lu, code = _factor(A)
    assert code == 0
    rng = np.random.default_rng(2)
    for _ in range(3):
        b = rng.standard_normal(400)
        x = lu.solve(b)
        assert _backward_error(A, x, b) < 100 * _EPS
    assert lu.fill() >= A.nnz


def test_values_far_from_the_analysed_ones_are_factored_with_other_pivots():
    """The analysed pivot rows are kept only while they pass the threshold test: with
    the diagonal scaled from 1e3 to 1e-6 they do not, and the LU pivots afresh."""
    analysed = _iteration_like(300, seed=3, cj=1e3)
    A = _iteration_like(300, seed=3, cj=1e-6)
    A.data[np.abs(A.data) < 1e-3] = 0.0           # some analysed pivots become exact zeros
    dense = A.toarray()
    assert np.linalg.matrix_rank(dense) == 300
    lu, code = _factor(A, analysed)
    assert code == 0
    b = np.random.default_rng(4).standard_normal(300)
    assert _backward_error(A, lu.solve(b), b) < 1e3 * _EPS


def test_badly_scaled_rows_are_solved_equilibrated_and_singular_or_nan_is_reported():
    A = _iteration_like(250, seed=5).tolil()
    A[10, :] = 0.0                                  # an equation in tiny units whose
    A[:, 10] = 0.0                                  # pivot cannot be avoided
    A[10, 10], A[10, 11] = 2e-15, 1e-15
    A = sps.csc_matrix(A)
    lu, code = _factor(A)
    assert code == 0
    # well conditioned once the row is scaled back: the solution is accurate although
    # the unequilibrated pivots span 1e15 (the LU is judged again equilibrated)
    x_true = np.random.default_rng(6).standard_normal(250)
    x = lu.solve(A @ x_true)
    assert np.linalg.norm(x - x_true) < 1e-10 * np.linalg.norm(x_true)
    S = A.tolil()
    S[20, :] = 0.0                                   # an empty row
    S = sps.csc_matrix(S)
    assert _factor(S, A)[1] == 4                     # singular
    bad = A.copy()
    bad.data[7] = np.nan
    assert _factor(bad, A)[1] == 5                   # not finite


def test_the_python_loop_refactors_a_kept_pattern_with_superlus_analysis():
    """The Python loop's LinearSolver factors a pattern's first matrix with SuperLU and
    the following ones (values changed, as with cj) with the compiled LU on SuperLU's
    order; a matrix singular on that pattern is still reported as singular."""
    rng = np.random.default_rng(7)
    A1 = _iteration_like(300, seed=7)
    lin = LinearSolver(300, sparse=True)
    lin.factor(A1)
    assert not isinstance(lin._lu, SparseLU)
    A2 = A1.copy()
    A2.data *= 1.0 + 0.3 * rng.standard_normal(A2.nnz)
    lin.factor(A2)
    assert isinstance(lin._lu, SparseLU)
    b = rng.standard_normal(300)
    assert _backward_error(A2, lin.solve(b), b) < 100 * _EPS
    S = A1.copy()
    S.data[S.indptr[20]:S.indptr[21]] = 0.0            # a zero column, same pattern
    with pytest.raises(SingularMatrixError):
        lin.factor(S)


# ---------------------------------------------------------------- compiled models
def _sections(component, n):
    component.R = [el.Resistor(R=1.0) for _ in range(n)]
    component.L = [el.Inductor(L=1e-3) for _ in range(n)]
    component.C = [el.Capacitor(C=1e-3) for _ in range(n)]


def _ladder_from(component, node):
    """Series R and L, shunt C (to the ground node's connection), from ``node`` on."""
    eqs = []
    for r, l, c in zip(component.R, component.L, component.C):
        eqs += [ac.connect(node, r.p), ac.connect(r.n, l.p), ac.connect(l.n, c.p)]
        node = c.p
    return eqs


class _Ladder(ac.Component):
    """A source into n sections (series R, L; shunt C) with one ground: 2n states."""

    def __init__(self, n, source, **mods):
        super().__init__(**mods)
        self.src = source
        self.gnd = el.Ground()
        _sections(self, n)

    def equations(self):
        return [ac.connect(self.src.n, self.gnd.p, *[c.n for c in self.C])] + \
            _ladder_from(self, self.src.p)


class _RectifiedLadder(ac.Component):
    """A 50 Hz sine through 1 Ohm and an ideal diode onto 100 uF || 100 Ohm (the
    rectifier of tests/library/test_electrical.py, whose diode switches twice a
    period: state events), which feeds n sections."""

    def __init__(self, n, **mods):
        super().__init__(**mods)
        self.src = el.SineVoltage(V=5.0, f=50.0, phase=-0.3)
        self.gnd = el.Ground()
        self.Rs = el.Resistor(R=1.0)
        self.diode = el.IdealDiode()
        self.Cs = el.Capacitor(C=1e-4)
        self.load = el.Resistor(R=100.0)
        _sections(self, n)

    def equations(self):
        return [ac.connect(self.src.n, self.gnd.p, self.Cs.n, self.load.n,
                           *[c.n for c in self.C]),
                ac.connect(self.src.p, self.Rs.p), ac.connect(self.Rs.n, self.diode.p),
                ac.connect(self.diode.n, self.Cs.p, self.load.p)] + \
            _ladder_from(self, self.diode.n)


def _compare(c, t_end, t):
    """(reference, compiled-loop run, its error, the Python loop's error at the same
    rtol): errors relative to the peak of their group (capacitor voltages, inductor
    currents), against the Python loop at rtol 1e-10."""
    ref = ac.simulate(c, t_end=t_end, rtol=1e-10, t_eval=t, step_loop="python")
    runs = {loop: ac.simulate(c, t_end=t_end, rtol=1e-8, t_eval=t, step_loop=loop)
            for loop in ("python", "c")}
    assert c.n > MAX_DENSE
    assert runs["c"].stats["step_loop"] == "c"
    assert runs["c"].stats["linear_solver"] == "sparse"
    assert ref.stats["step_loop"] == runs["python"].stats["step_loop"] == "python"
    errors = []
    for res in (runs["c"], runs["python"]):
        worst = 0.0
        for suffix in (".v", ".i"):
            names = [k for k in c.states if k.endswith(suffix)]
            peak = max(np.max(np.abs(ref[k])) for k in names)
            worst = max(worst, max(np.max(np.abs(res[k] - ref[k])) for k in names) / peak)
        errors.append(worst)
    return ref, runs["c"], errors[0], errors[1]


def test_a_ladder_above_the_dense_limit_matches_the_python_loop():
    """A 1 V step at 5 ms (a time event) into 110 sections: 220 unknowns."""
    c = ac.compile(_Ladder(110, el.StepVoltage(V=1.0, startTime=5e-3)), backend="c")
    t = np.linspace(0, 0.05, 101)
    ref, res, err_c, err_py = _compare(c, 0.05, t)
    # the global error of rtol 1e-8 over some 300 steps: 8e-7 of the peak in either loop
    assert err_c < 3e-6 and err_c < 1.5 * err_py + 1e-9
    # a damped wave: at 45 ms after the step it has raised the 20th capacitor by 2 %
    assert np.max(np.abs(ref["C[20].v"])) > 0.01


def test_a_rectified_ladder_switches_with_the_python_loop():
    """An ideal diode between a sine and 120 sections (241 unknowns): the compiled
    loop finds the same switching times and the same waveforms."""
    c = ac.compile(_RectifiedLadder(120), backend="c")
    t = np.linspace(0, 0.04, 81)
    ref, res, err_c, err_py = _compare(c, 0.04, t)
    assert len(ref.events) >= 3
    assert len(res.events) == len(ref.events)
    assert np.max(np.abs(np.array(res.events) - np.array(ref.events))) < 1e-6 * 0.04
    assert err_c < 3e-6 and err_c < 1.5 * err_py + 1e-9
