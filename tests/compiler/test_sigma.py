"""Pryce's Sigma-method, and its agreement with Pantelides."""
import math
import random

import pytest

from acausal.compiler.structure import sigma as sigma_mod
from acausal.compiler.structure.graph import LINEAR_CONST as C, LINEAR_PARAM as P
from acausal.compiler.structure.graph import LINEAR_VAR as V, NONLINEAR as N
from acausal.compiler.structure.pantelides import pantelides
from acausal.compiler.structure.sigma import signature_matrix, sigma_method
from acausal.compiler.structure.states import index1_matching, select_states
from acausal.compiler.structure.matching import StructurallySingular, diagnose, make_structure

NEG = -math.inf


def test_second_order_pendulum_from_pryce_paper():
    # x'' + lam x = 0,  y'' + lam y - g = 0,  x^2 + y^2 - L^2 = 0   (cols x, y, lam)
    r = sigma_method([[2, None, 0], [None, 2, 0], [0, 0, None]])
    assert (r.c, r.d, r.index, r.dof) == ([0, 0, 2], [2, 2, 0], 3, 2)
    assert r.transversal in ([0, 2, 1], [2, 1, 0])


def test_first_order_pendulum_matches_pantelides():
    s = make_structure(
        [{"der(x)": C, "vx": C}, {"der(y)": C, "vy": C},
         {"der(vx)": P, "lam": V, "x": V}, {"der(vy)": P, "lam": V, "y": V},
         {"x": N, "y": N}],
        derivatives={"x": "der(x)", "y": "der(y)", "vx": "der(vx)", "vy": "der(vy)"},
        var_names=["x", "y", "vx", "vy", "lam"])
    sig, cols = signature_matrix(s)
    assert cols == [0, 1, 2, 3, 4]
    assert sig.tolist() == [[1, NEG, 0, NEG, NEG], [NEG, 1, NEG, 0, NEG],
                            [0, NEG, 1, NEG, 0], [NEG, 0, NEG, 1, 0], [0, 0, NEG, NEG, NEG]]
    r = sigma_method(sig)
    assert (r.c, r.d, r.index, r.dof) == ([1, 1, 0, 0, 2], [2, 2, 1, 1, 0], 3, 2)
    assert pantelides(s).diff_counts == r.c
    assert sigma_method(signature_matrix(s, sparse=True)[0]) == r


def test_ode_and_index_one():
    assert sigma_method([[1]]).index == 0                        # x' = f(x)
    r = sigma_method([[1, 0], [0, 0]])                          # x' = f(x,y), 0 = g(x,y)
    assert (r.c, r.d, r.index, r.dof) == ([0, 0], [1, 0], 1, 1)


def test_singular_signature_raises():
    with pytest.raises(StructurallySingular):
        sigma_method([[1, None], [0, None]])
    with pytest.raises(StructurallySingular):
        sigma_method([[0, 1]])


def test_sparse_solver_path(monkeypatch):
    monkeypatch.setattr(sigma_mod, "_OWN_LIMIT", 0)
    r = sigma_method({(0, 0): 2, (0, 2): 0, (1, 1): 2, (1, 2): 0, (2, 0): 0, (2, 1): 0})
    assert (r.c, r.d, r.index) == ([0, 0, 2], [2, 2, 0], 3)


def _random_dae(rng):
    """Random square DAE; derivative chains only as long as their use."""
    n = rng.randint(1, 7)
    order = {f"x{i}": 0 for i in range(n)}
    eqs = []
    for _ in range(n):
        eq = {}
        for i in rng.sample(range(n), rng.randint(1, min(3, n))):
            k = rng.choice([0, 0, 1, 1, 2])
            order[f"x{i}"] = max(order[f"x{i}"], k)
            name = f"x{i}"
            for _ in range(k):
                name = f"der({name})"
            eq[name] = rng.choice([C, P, V, N])
        eqs.append(eq)
    ders = {}
    for b, k in order.items():
        name = b
        for _ in range(k):
            ders[name] = f"der({name})"
            name = ders[name]
    return make_structure(eqs, derivatives=ders, var_names=list(order))


def test_random_models_pantelides_equals_sigma():
    rng = random.Random(7)
    checked = 0
    for _ in range(600):
        s = _random_dae(rng)
        if diagnose(s).kind != "ok":
            with pytest.raises(StructurallySingular):
                sigma_method(signature_matrix(s)[0])
            continue
        checked += 1
        res = sigma_method(signature_matrix(s)[0])
        p = pantelides(s)
        assert p.diff_counts == res.c
        sel = select_states(p)
        assert len(sel.states) == res.dof          # dummy derivatives keep the dof
        index1_matching(p, sel)
    assert checked > 200


def test_own_assignment_matches_scipy_on_random_signatures():
    """The Hungarian method used for small systems (no scipy.optimize import) finds a
    transversal of the same total value as scipy's assignment solver."""
    from scipy.optimize import linear_sum_assignment
    from acausal.compiler.structure.sigma import _hungarian
    import numpy as np
    rng = np.random.default_rng(11)
    for _ in range(300):
        n = int(rng.integers(1, 25))
        a = rng.integers(-2, 4, size=(n, n)).astype(float)
        a[rng.random((n, n)) < 0.5] = -100.0 * n        # absent entries
        cols = _hungarian(-a)
        assert sorted(cols.tolist()) == list(range(n))
        rows, ref = linear_sum_assignment(a, maximize=True)
        assert a[np.arange(n), cols].sum() == a[rows, ref].sum()


def test_sparse_assignment_matches_scipy_on_random_signatures():
    """The primal-dual method on the finite entries (used past a few dozen equations)
    finds a transversal of the same total value as scipy's dense assignment solver, and
    calls a matrix singular exactly when scipy's best assignment needs an absent entry."""
    from scipy.optimize import linear_sum_assignment
    from acausal.compiler.structure.sigma import _sparse_transversal
    import numpy as np
    rng = np.random.default_rng(5)
    solved = singular = 0
    for _ in range(600):
        n = int(rng.integers(1, 60))
        a = np.where(rng.random((n, n)) < rng.random() * 0.3 + 1.0 / n,
                     rng.integers(0, 4, size=(n, n)), -1)
        if rng.random() < 0.5:                           # mostly nonsingular
            p = rng.permutation(n)
            a[np.arange(n), p] = np.maximum(a[np.arange(n), p], 0)
        i, j = np.nonzero(a >= 0)
        rows, ref = linear_sum_assignment(np.where(a >= 0, a, -50 * (n + 1)),
                                          maximize=True)
        if (a[rows, ref] < 0).any():
            with pytest.raises(StructurallySingular):
                _sparse_transversal(n, i.tolist(), j.tolist(), a[i, j].tolist())
            singular += 1
            continue
        cols = _sparse_transversal(n, i.tolist(), j.tolist(), a[i, j].tolist())
        assert sorted(cols.tolist()) == list(range(n))
        assert a[np.arange(n), cols].min() >= 0
        assert a[np.arange(n), cols].sum() == a[rows, ref].sum()
        solved += 1
    assert solved > 300 and singular > 50


def test_large_model_needs_no_scipy():
    """A signature matrix past the dense size is solved without importing scipy (its
    import is longer than a small model's compile): a chain of n index-2 pairs."""
    import subprocess
    import sys
    code = ("import sys\n"
            "from acausal.compiler.structure.sigma import sigma_method\n"
            "n = 500\n"
            "sig = {}\n"
            "for k in range(n):\n"
            "    x, y = 2 * k, 2 * k + 1\n"
            "    sig[(x, x)] = 1; sig[(x, y)] = 0\n"
            "    sig[(y, x)] = 0\n"
            "    if k: sig[(y, x - 2)] = 0\n"
            "r = sigma_method(sig)\n"
            "print(r.index, r.dof, 'scipy' in sys.modules)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=120, check=True).stdout.split()
    assert out == ["2", "0", "False"]


def test_a_transversal_given_is_used_only_when_its_offsets_prove_it():
    """Pantelides' final matching read as a transversal, as the index-as-written report
    passes it: on random well-posed DAEs it is proved of highest value, and the offsets
    are those the Sigma-method finds alone.  A start whose offsets prove nothing (one
    offset lowered, or a transversal not of highest value) is ignored, same result."""
    from acausal.compiler.structure import sigma as sig_mod
    from acausal.compiler.index.reduction import _pantelides_transversal
    rng = random.Random(3)
    proved = refused = 0
    for _ in range(600):
        s = _random_dae(rng)
        if diagnose(s).kind != "ok":
            continue
        entries, columns = signature_matrix(s, sparse=True)
        alone = sigma_method(entries)
        start = _pantelides_transversal(pantelides(s), columns, s.n_eqs)
        n, _, i, j, val = sig_mod._entries(entries)
        assert sig_mod._certified(n, i, j, val, start) is not None
        proved += 1
        given = sigma_method(entries, start=start)
        assert (given.c, given.d, given.index, given.dof, given.value) == \
            (alone.c, alone.d, alone.index, alone.dof, alone.value)
        transversal, c, d = start
        if max(d) > 0:                 # a tight offset lowered: no longer a proof
            k = d.index(max(d))
            wrong = (transversal, c, d[:k] + [d[k] - 1] + d[k + 1:])
            assert sig_mod._certified(n, i, j, val, wrong) is None
            assert sigma_method(entries, start=wrong) == alone
            refused += 1
    assert proved > 200 and refused > 50


def test_a_start_that_is_not_a_highest_value_transversal_is_refused():
    # x' + y = 0, x + y' = 0 as sigma [[1, 0], [0, 1]]: the diagonal (value 2) is the
    # highest; the anti-diagonal (value 0) with offsets 0 proves nothing
    sig = {(0, 0): 1, (0, 1): 0, (1, 0): 0, (1, 1): 1}
    n, _, i, j, val = sigma_mod._entries(sig)
    assert sigma_mod._certified(n, i, j, val, ([1, 0], [0, 0], [0, 0])) is None
    assert sigma_mod._certified(n, i, j, val, ([0, 1], [0, 0], [1, 1])) is not None
    r = sigma_method(sig, start=([1, 0], [0, 0], [0, 0]))
    assert (r.transversal, r.c, r.d, r.index) == ([0, 1], [0, 0], [1, 1], 0)
