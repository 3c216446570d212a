"""The exact check of Pryce's system Jacobian and the LC conversion (compiler/index/conversion.py).

Each system is drawn in a comment with its signature matrix Sigma (rows: equations,
columns: variables, entries: highest derivative order), the canonical offsets c, d and
the system Jacobian J; the expected combination is worked out by hand.
"""
from fractions import Fraction

import numpy as np
import pytest
import sympy as sp
from sympy.polys.matrices import DomainMatrix

from acausal.components.declarations import VariableAttributes
from acausal.components.symbols import time
from acausal.compiler.index.conversion import (block_jacobian, coefficient_oracle, convert,
                                         exact_rank, exact_value, left_null_vectors)
from acausal.compiler.frontend.flatten import FlatEquation, FlatModel, FlatParameter, FlatVariable
from acausal.compiler.structure.graph import LINEAR_CONST as K, UNASSIGNED
from acausal.compiler.structure.pantelides import pantelides
from acausal.compiler.structure.states import select_states
from acausal.compiler.structure.matching import StructurallySingular, make_structure
from acausal.compiler.algebra.symbolic import SymbolicSystem


def sym(name):
    return sp.Symbol(name, real=True)


def der(x, k=1):
    name = x.name
    for _ in range(k):
        name = f"der({name})"
    return sym(name)


def system_of(residuals, variables, orders, parameters=None):
    """A SymbolicSystem of residuals in `variables`, with der chains up to `orders`."""
    parameters = parameters or {}
    flat = FlatModel("T", [FlatVariable(v.name, v, VariableAttributes(), "", "T")
                           for v in variables],
                     [FlatParameter(p.name, p, val) for p, val in parameters.items()],
                     [FlatEquation(r, f"f{k + 1}", "", "T") for k, r in enumerate(residuals)])
    for v in variables:
        for k in range(orders.get(v, 0)):
            flat.derivatives[der(v, k)] = der(v, k + 1)
    system = SymbolicSystem.from_flat(flat)
    values = {p: Fraction(val) for p, val in parameters.items()}
    return system, values


x, y, z, x1, x2 = sym("x"), sym("y"), sym("z"), sym("x1"), sym("x2")
C, C1, C2, R1, R2 = sym("C"), sym("C1"), sym("C2"), sym("R1"), sym("R2")


def same(a, b):
    return sp.simplify(sp.expand(a - b)) == 0


def test_nodal_pair_is_combined_into_an_algebraic_constraint():
    # f1: C (x1' - x2') + (x1 - sin t)/R1 = 0   Sigma = [[1, 1],    c = (0, 0)  d = (1, 1)
    # f2: C (x2' - x1') + x2/R2 = 0                      [1, 1]]
    # J = C [[1, -1], [-1, 1]] is singular; u = (1, 1); theta = 0, l = f1:
    # f1 <- f1 + f2 = (x1 - sin t)/R1 + x2/R2    Sigma = [[0, 0],   c = (1, 0)  d = (1, 1)
    #                                                     [1, 1]]
    f1 = C * (der(x1) - der(x2)) + (x1 - sp.sin(time)) / R1
    f2 = C * (der(x2) - der(x1)) + x2 / R2
    system, values = system_of([f1, f2], [x1, x2], {x1: 1, x2: 1},
                               {C: 1e-3, R1: 100.0, R2: 200.0})
    conv = convert(system, values=values)
    assert conv.value_before == 2 and len(conv.conversions) == 1
    step = conv.conversions[0]
    assert step.replaced == 0 and step.value_before == 2 and step.value_after == 1
    assert [(a, k) for a, _, k in step.terms] == [(1, 0), (1, 0)]
    assert system.equations[0].kind == "equation" and system.equations[0].combination
    assert step.columns == ["der(x1)", "der(x2)"] and step.algebraic
    assert not step.parameter_dependent      # singular for every C
    assert same(system.equations[0].residual, (x1 - sp.sin(time)) / R1 + x2 / R2)
    assert system.equations[0].text == "(f1  [(model) (T)]) + (f2  [(model) (T)])"
    assert conv.sigma.c == [1, 0] and conv.sigma.d == [1, 1]
    assert conv.index == 1 and conv.sigma.dof == 1 and conv.sigma.value == 1
    assert "singular constant coefficient matrix" in conv.notes()[0]


def test_combination_with_a_differentiated_equation_and_pruned_derivatives():
    # f1: x' + y - sin t = 0     Sigma = [[1, 0],     c = (1, 0)   d = (2, 1)
    # f2: x'' + y' + x = 0                [2, 1]]
    # J = [[1, 1], [1, 1]]: u = (-1, 1); theta = c_f2 = 0, so l = f2 and
    # f2 <- -f1' + f2 = x + cos t      Sigma = [[1, 0],     c = (0, 1)   d = (1, 0)
    #                                           [0, -]]
    # index 1 + 1 (y is algebraic); der(der(x)) and der(y) are in no equation any more
    f1 = der(x) + y - sp.sin(time)
    f2 = der(x, 2) + der(y) + x
    system, values = system_of([f1, f2], [x, y], {x: 2, y: 1})
    conv = convert(system, values=values)
    step = conv.conversions[0]
    assert step.replaced == 1 and [(a, k) for a, _, k in step.terms] == [(-1, 1), (1, 0)]
    assert same(system.equations[1].residual, x + sp.cos(time))
    assert system.equations[1].text.startswith("-(d/dt(f1")
    assert conv.sigma.c == [0, 1] and conv.sigma.d == [1, 0] and conv.index == 2
    assert conv.sigma.dof == 0
    names = [q.name for q in system.symbols]
    assert names == ["x", "y", "der(x)"]
    s = conv.structure
    assert s.var_to_diff == [2, UNASSIGNED, UNASSIGNED]


def test_integer_coefficients_of_an_algebraic_block():
    # f1: x + 2y - z = 0         Sigma = [[0, 0, 0],    c = (0, 0, 0)   d = (0, 0, 1)
    # f2: 2x + 4y + sin t = 0             [0, 0, -],
    # f3: z' + x = 0                      [0, -, 1]]
    # the block {f1, f2} x {x, y} is [[1, 2], [2, 4]]: u = (2, -1), l = f1:
    # f1 <- 2 f1 - f2 = -2 z - sin t   c = (1, 0, 0)   d = (0, 0, 1), index 2, no state
    system, values = system_of([x + 2 * y - z, 2 * x + 4 * y + sp.sin(time), der(z) + x],
                               [x, y, z], {z: 1})
    conv = convert(system, values=values)
    step = conv.conversions[0]
    assert [a for a, _, _ in step.terms] == [2, -1] and step.replaced == 0
    assert step.matrix == [[1, 2], [2, 4]]
    assert same(system.equations[0].residual, -2 * z - sp.sin(time))
    assert system.equations[0].text.startswith("2*(f1")
    assert conv.sigma.c == [1, 0, 0] and conv.sigma.d == [0, 0, 1]
    assert conv.index == 2 and conv.sigma.dof == 0


@pytest.mark.parametrize("c2, converted", [(2.0, True), (3.0, False)])
def test_singularity_for_particular_parameter_values_is_said_so(c2, converted):
    # f1: C1 x' + y + x - sin t = 0    J = [[C1, 1], [C2, 2]], det = 2 C1 - C2:
    # f2: C2 x' + 2 y = 0              singular for C1 = 1, C2 = 2 only
    # u = (2, -1):  f1 <- 2 f1 - f2 = 2 x - 2 sin t   (exact for these values)
    f1 = C1 * der(x) + y + x - sp.sin(time)
    f2 = C2 * der(x) + 2 * y
    system, values = system_of([f1, f2], [x, y], {x: 1}, {C1: 1.0, C2: c2})
    conv = convert(system, values=values)
    assert conv.changed is converted
    if converted:
        assert conv.conversions[0].parameter_dependent
        assert same(system.equations[0].residual, 2 * x - 2 * sp.sin(time))
        assert "only for the present parameter values" in conv.notes()[0]
        assert conv.index == 2 and conv.sigma.dof == 0
    else:
        assert conv.index == 1 and conv.sigma.dof == 1 and not conv.numeric_blocks


def test_regular_constant_blocks_are_left_alone():
    # f1: x' + y = 0, f2: y - 2 x = 0: J = [[1, 1], [0, 1]] (two 1x1 blocks, regular)
    system, values = system_of([der(x) + y, y - 2 * x], [x, y], {x: 1})
    before = [e.residual for e in system.equations]
    conv = convert(system, values=values)
    assert not conv.changed and not conv.numeric_blocks
    assert [e.residual for e in system.equations] == before
    assert conv.index == 1 and conv.sigma.c == [0, 0]


def test_variable_dependent_block_is_recorded_for_the_runtime():
    # f1: y x' - 1 = 0     Sigma = [[1, 0],    c = (0, 0)   d = (1, 0)
    # f2: y - x - 2 = 0             [0, 0]]    J = [[y, x'], [0, 1]]
    # blocks {f1} (entry y: judged at a point) and {f2} (entry 1: regular)
    system, values = system_of([y * der(x) - 1, y - x - 2], [x, y], {x: 1})
    conv = convert(system, values=values)
    assert not conv.changed and len(conv.numeric_blocks) == 1
    block = conv.numeric_blocks[0]
    assert block.equations == [0] and block.variables == ["der(x)"]
    jac = block_jacobian(block, ["x", "y", "der(x)"], [])
    assert jac(0.0, [0.5, 2.5, 0.4], []).tolist() == [[2.5]]


def test_constant_rows_of_a_mixed_block_give_an_exact_null_vector():
    # f1: x1 + x2 + y - z = 0          c = (0, 0, 0, 0), d = (0, 0, 0, 1); one block
    # f2: 2 x1 + 2 x2 + 2 y - sin t    {f1, f2, f3} in (x1, x2, y):
    # f3: y x1 + x2 - 1 = 0               [[1, 1, 1], [2, 2, 2], [y, 1, x1]]
    # f4: z' + x1 = 0                  f3 depends on the variables, but the constant
    # rows f1, f2 alone have u = (2, -1):  f1 <- 2 f1 - f2 = sin t - 2 z
    system, values = system_of([x1 + x2 + y - z, 2 * x1 + 2 * x2 + 2 * y - sp.sin(time),
                                y * x1 + x2 - 1, der(z) + x1], [x1, x2, y, z], {z: 1})
    conv = convert(system, values=values)
    assert len(conv.conversions) == 1 and conv.conversions[0].matrix == [[1, 1, 1], [2, 2, 2]]
    assert same(system.equations[0].residual, sp.sin(time) - 2 * z)
    assert conv.sigma.c == [1, 0, 0, 0] and conv.sigma.dof == 0
    assert [b.equations for b in conv.numeric_blocks] == [[1, 2]]


def test_redundant_equations_are_named():
    # f1: x' + y = 0, f2: 2 x' + 2 y = 0: J = [[1, 1], [2, 2]], and 2 f1 - f2 is 0 = 0
    system, values = system_of([der(x) + y, 2 * der(x) + 2 * y], [x, y], {x: 1})
    with pytest.raises(StructurallySingular, match="linearly dependent"):
        convert(system, values=values)


# -- exact arithmetic ----------------------------------------------------------------
def test_exact_values_of_coefficients():
    p = {C: Fraction(1e-3), R1: Fraction(100.0)}
    assert exact_value(C / R1 + 1, p) == Fraction(1e-3) / 100 + 1
    assert exact_value(sp.Float(0.1) * C, p) == Fraction(0.1) * Fraction(1e-3)
    assert exact_value(x * C, p) is None                     # a variable: not a constant
    # an irrational constant is one atom, the Fraction of its float value
    assert exact_value(sp.sin(C), p) == Fraction(float(np.sin(1e-3)))
    assert exact_value(sp.pi * C, p) == Fraction(float(np.pi)) * Fraction(1e-3)
    assert exact_value(sp.sqrt(-C), p) is None               # not real
    oracle = coefficient_oracle(system_of([C * der(x) + R1 * x], [x], {x: 1},
                                          {C: 1e-3, R1: 100.0})[0],
                                {C: Fraction(1e-3), R1: Fraction(100.0)})
    assert oracle(0, 0) == Fraction(100.0) and oracle(0, 1) == Fraction(1e-3)


def test_left_null_vector_of_the_structurally_chosen_block():
    # [[1, 1, 0], [1, 1, 1], [0, 0, 1]]: row1 - row2 + row3 = 0
    rows = {0: {0: 1, 1: 1}, 1: {0: 1, 1: 1, 2: 1}, 2: {2: 1}}
    rows = {r: {c: Fraction(v) for c, v in vals.items()} for r, vals in rows.items()}
    null = left_null_vectors(rows)
    assert len(null) == 1
    u = null[0]
    scale = u[0]
    assert {r: q / scale for r, q in u.items()} == {0: 1, 1: -1, 2: 1}


def test_exact_rank_against_an_independent_computation():
    rng = np.random.default_rng(3)
    a = rng.integers(-3, 4, size=(40, 40)) * (rng.random((40, 40)) < 0.15)
    a[:, 7] = a[:, 3] - 2 * a[:, 11]            # rank deficiency by construction
    a[5] = a[1] + a[2]
    rows = {i: {j: Fraction(int(a[i, j])) for j in range(40) if a[i, j]} for i in range(40)}
    reference = DomainMatrix.from_Matrix(sp.Matrix(a.tolist())).convert_to(sp.QQ).rank()
    assert exact_rank(rows) == reference < 40
    for u in left_null_vectors(rows):
        v = np.zeros(40, dtype=object)
        for i, q in u.items():
            v[i] = q
        assert all(x == 0 for x in v @ a.astype(object))


def test_thousand_row_path_laplacian():
    # The Laplacian of a path of n nodes: rank n - 1, left null vector (1, ..., 1); the
    # Markowitz order keeps the elimination on the tridiagonal pattern.
    n = 1000
    rows = {}
    for i in range(n):
        row = {i: Fraction(2 if 0 < i < n - 1 else 1)}
        if i > 0:
            row[i - 1] = Fraction(-1)
        if i < n - 1:
            row[i + 1] = Fraction(-1)
        rows[i] = row
    assert exact_rank(rows) == n - 1
    (u,) = left_null_vectors(rows)
    assert len(u) == n and len(set(u.values())) == 1


# -- numeric dummy choice (compiler/structure/states.py) ---------------------------------------
def _ms_structure():
    # ey: der(y) = -y + l1            g1: y + x1 + x2 = s1(t)
    # e1: der(x1) = -x1 + l1 + l2     g2: x1 + x2 + x3 = s2(t)
    # e2: der(x2) = -2 x2 + l1 + l2   g3: x3 = s3(t)
    # e3: der(x3) = -x3 + l2 + l3     (x' = A x + G^T l, G x = s: index 2, one state)
    # Level 1 of the dummy-derivative method: rows g1', g2', g3', columns der(y),
    # der(x1), der(x2), der(x3), the constant matrix G:
    #        y  x1 x2 x3
    #   g1' [1, 1, 1, 0]
    #   g2' [0, 1, 1, 1]
    #   g3' [0, 0, 0, 1]
    # The preference order (later declared first) gives x3, x2, x1 structurally:
    # [[1, 1, 0], [1, 1, 1], [0, 0, 1]] is singular; the exact greedy takes x3, x2, y.
    return make_structure(
        [{"der(y)": K, "y": K, "l1": K}, {"der(x1)": K, "x1": K, "l1": K, "l2": K},
         {"der(x2)": K, "x2": K, "l1": K, "l2": K}, {"der(x3)": K, "x3": K, "l2": K, "l3": K},
         {"y": K, "x1": K, "x2": K}, {"x1": K, "x2": K, "x3": K}, {"x3": K}],
        derivatives={v: f"der({v})" for v in ("y", "x1", "x2", "x3")},
        eq_names=["ey", "e1", "e2", "e3", "g1", "g2", "g3"],
        var_names=["y", "x1", "x2", "x3", "l1", "l2", "l3"])


def test_exact_rank_choice_of_dummy_derivatives():
    r = pantelides(_ms_structure())
    s = r.structure
    structural = select_states(r)
    assert sorted(s.var_names[v] for v in structural.dummies) == \
        ["der(x1)", "der(x2)", "der(x3)"]
    table = {("d/dt(g1)", "der(y)"): 1, ("d/dt(g1)", "der(x1)"): 1,
             ("d/dt(g1)", "der(x2)"): 1, ("d/dt(g2)", "der(x1)"): 1,
             ("d/dt(g2)", "der(x2)"): 1, ("d/dt(g2)", "der(x3)"): 1,
             ("d/dt(g3)", "der(x3)"): 1}

    def coefficient(e, v):
        q = table.get((s.eq_names[e], s.var_names[v]))
        return None if q is None else Fraction(q)

    numeric = select_states(r, coefficient)
    assert sorted(s.var_names[v] for v in numeric.dummies) == ["der(x2)", "der(x3)", "der(y)"]
    assert [s.var_names[v] for v in numeric.states] == ["x1"]
    (level, before, after), = numeric.numeric_changes
    assert level == 1 and sorted(s.var_names[v] for v in before) == \
        ["der(x1)", "der(x2)", "der(x3)"]


def test_exact_rank_choice_keeps_a_regular_structural_choice():
    # same pattern, but g1 = y + x1 + 2 x2: the structural choice x1, x2, x3 is regular
    r = pantelides(_ms_structure())
    s = r.structure

    def coefficient(e, v):
        if s.eq_names[e] == "d/dt(g1)" and s.var_names[v] == "der(x2)":
            return Fraction(2)
        return Fraction(1) if v in s.graph[e] else None

    numeric = select_states(r, coefficient)
    assert numeric.dummies == select_states(r).dummies and not numeric.numeric_changes


def test_rank_mod_p_certifies_exact_full_rank():
    """Full row rank modulo the prime is full row rank over the rationals (the rows then
    have no left null vector); rows with a dependent row are never certified."""
    import random

    from acausal.compiler.index.modp import full_row_rank_mod_p as _full_row_rank_mod_p
    rng = random.Random(7)
    for trial in range(1500):
        n = rng.randint(1, 7)
        m = rng.randint(n, 8)
        rows = {i: {j: Fraction(rng.randint(-3, 3), rng.choice([1, 1, 2, 3]))
                    for j in rng.sample(range(m), rng.randint(1, m))} for i in range(n)}
        dependent = trial % 3 == 0 and n > 1
        if dependent:
            rows[n - 1] = {j: 2 * v for j, v in rows[rng.randrange(n - 1)].items()}
        certified = _full_row_rank_mod_p(rows)
        assert certified == (not left_null_vectors(rows))   # no unlucky prime here
        assert not (dependent and certified)


def test_rank_mod_p_in_the_array_phase_agrees_with_exact_elimination(monkeypatch):
    """Once the active rows are few and filled in, the elimination mod p goes on in a
    numpy array (compiler/index/modp.py); made to switch at once, and after a few sparse
    pivots, it certifies exactly the rows that have no left null vector, square and
    wide, with dependent rows (a multiple of another, or the sum of two) and with
    large entries (residues of any size below the prime, whose products exceed 2**53)."""
    import random

    from acausal.compiler.index import modp
    monkeypatch.setattr(modp, "DENSE_ROWS", 10**6)
    monkeypatch.setattr(modp, "DENSE_FILL", 0.0)
    rng = random.Random(11)
    for trial in range(400):
        monkeypatch.setattr(modp, "_CHECK_EVERY", rng.choice([0, 1, 3]))
        n = rng.randint(2, 12)
        m = rng.randint(n, 14)
        rows = {i: {j: Fraction(rng.choice([rng.randint(-4, 4), rng.randint(-10**12, 10**12)]),
                                rng.choice([1, 1, 2, 5]))
                    for j in rng.sample(range(m), rng.randint(1, min(m, 4)))}
                for i in range(n)}
        kind = trial % 4
        if kind == 1:
            rows[n - 1] = {j: -3 * v for j, v in rows[rng.randrange(n - 1)].items()}
        elif kind == 2:
            i, k = rng.sample(range(n - 1), 2) if n > 2 else (0, 0)
            total = dict(rows[i])
            for j, v in rows[k].items():
                total[j] = total.get(j, 0) + v
            rows[n - 1] = total
        certified = modp.full_row_rank_mod_p(rows)
        assert certified == (not left_null_vectors(rows))
        if kind in (1, 2):
            assert not certified


def test_a_one_row_block_whose_coefficient_is_zero_is_converted():
    # f1: (C1 - C2) x' + x - sin t = 0 with C1 = C2 = 1:  Sigma = [[1]], J = [[C1 - C2]]
    # = [[0]]: the one-row block is singular (u = (1)), and f1 without its x' term is
    # x - sin t = 0, algebraic (Sigma = [[0]], index 1, no degree of freedom)
    f1 = (C1 - C2) * der(x) + x - sp.sin(time)
    system, values = system_of([f1], [x], {x: 1}, {C1: 1.0, C2: 1.0})
    conv = convert(system, values=values)
    assert conv.changed and conv.conversions[0].parameter_dependent
    assert same(system.equations[0].residual, x - sp.sin(time))
    assert conv.sigma.c == [0] and conv.sigma.d == [0] and conv.sigma.dof == 0
    # with C2 = 2 the coefficient is -1: the block is regular and nothing changes
    system, values = system_of([f1], [x], {x: 1}, {C1: 1.0, C2: 2.0})
    conv = convert(system, values=values)
    assert not conv.changed and conv.sigma.d == [1] and conv.sigma.dof == 1
