"""Matching, Dulmage-Mendelsohn parts and diagnosis on small hand-drawn graphs."""
import random

import pytest

from acausal.compiler.structure.graph import LINEAR_CONST as C, LINEAR_PARAM as P, UNASSIGNED
from acausal.compiler.structure.matching import (
    OverdeterminedModel, StructurallySingular, UnderdeterminedModel,
    bipartite_matching, check_structure, diagnose, dulmage_mendelsohn,
    make_structure, maximum_matching)


def test_matching_needs_augmenting_path():
    # e0 - a - e1        greedy gives e0->a, then e1 must push e0 over to b:
    #  \      |          e0->b, e1->a, e2->c
    #   b     c - e2
    s = make_structure([{"a": C, "b": C}, {"a": C, "c": C}, {"c": C}],
                       var_names=["a", "b", "c"])
    var_to_eq, eq_to_var = maximum_matching(s)
    assert eq_to_var == [1, 0, 2]
    assert var_to_eq == [1, 0, 2]


def test_matching_restricted_to_subset():
    # only b and c may be matched: e0 -> b, e1 -> c, e2 has nothing left
    s = make_structure([{"a": C, "b": C}, {"a": C, "c": C}, {"c": C}],
                       var_names=["a", "b", "c"])
    var_to_eq, eq_to_var = maximum_matching(s, vars=[1, 2])
    assert eq_to_var == [1, 2, UNASSIGNED]
    assert var_to_eq == [UNASSIGNED, 0, 1]


def test_matching_long_path_is_iterative():
    # a chain e_i = {v_i, v_{i+1}} with greedy taking v_i ... forces one path of
    # length n through the whole chain when the last equation has only v_0.
    n = 20000
    adj = [[i, i + 1] for i in range(n)] + [[0]]
    l2r, r2l = bipartite_matching(adj, n + 1)
    assert UNASSIGNED not in l2r
    assert sorted(l2r) == list(range(n + 1))


def test_matching_is_maximum_on_random_graphs():
    nx = pytest.importorskip("networkx")
    rng = random.Random(1)
    for _ in range(50):
        n, m = rng.randint(1, 30), rng.randint(1, 30)
        adj = [sorted(rng.sample(range(m), rng.randint(0, min(3, m)))) for _ in range(n)]
        l2r, r2l = bipartite_matching(adj, m)
        g = nx.Graph()
        g.add_nodes_from(("e", i) for i in range(n))
        g.add_nodes_from(("v", j) for j in range(m))
        g.add_edges_from((("e", i), ("v", j)) for i, vs in enumerate(adj) for j in vs)
        ref = nx.bipartite.maximum_matching(g, top_nodes=[("e", i) for i in range(n)])
        assert sum(x is not UNASSIGNED for x in l2r) == len(ref) // 2
        for i, j in enumerate(l2r):
            assert j is UNASSIGNED or (j in adj[i] and r2l[j] == i)


def test_dulmage_mendelsohn_parts():
    # e0: {a}   e1: {a}   -> over-determined: e0, e1 fight for a
    # e2: {b, c}          -> under-determined: one of b, c is free
    s = make_structure([{"a": C}, {"a": C}, {"b": C, "c": C}],
                       var_names=["a", "b", "c"])
    parts = dulmage_mendelsohn(s)
    assert parts.over_eqs == [0, 1] and parts.over_vars == [0]
    assert parts.under_eqs == [2] and parts.under_vars == [1, 2]


def test_diagnose_ok_for_pendulum_chains():
    # der(x) = vx etc.: derivative chains x~der(x) and vx~der(vx) count once each
    s = make_structure(
        [{"der(x)": C, "vx": C}, {"der(vx)": P, "lam": P, "x": P}, {"x": C}],
        derivatives={"x": "der(x)", "vx": "der(vx)"})
    d = diagnose(s)
    assert d.kind == "ok" and (d.n_equations, d.n_unknowns) == (3, 3)


def test_diagnose_over_determined_names():
    # der(x) = -x ; y = 1 ; y = 2   ->  3 equations, 2 unknowns (x, y)
    s = make_structure([{"der(x)": C, "x": C}, {"y": C}, {"y": C}],
                       derivatives={"x": "der(x)"}, eq_names=["ode", "y1", "y2"])
    d = diagnose(s)
    assert d.kind == "over"
    assert d.over_equations == [1, 2] and [s.var_names[v] for v in d.over_variables] == ["y"]
    assert "y1" in str(d) and "y2" in str(d) and "ode" not in str(d)
    with pytest.raises(OverdeterminedModel) as err:
        check_structure(s)
    assert err.value.equations == ["y1", "y2"] and err.value.variables == ["y"]


def test_diagnose_under_determined_names():
    # der(x) = -x + z ; w + z = 0   ->  2 equations, 3 unknowns; z, w undetermined
    s = make_structure([{"der(x)": C, "x": C, "z": C}, {"w": C, "z": C}],
                       derivatives={"x": "der(x)"}, eq_names=["ode", "alg"])
    d = diagnose(s)
    assert d.kind == "under"
    assert sorted(s.var_names[v] for v in d.under_variables) == ["w", "x", "z"]
    with pytest.raises(UnderdeterminedModel) as err:
        check_structure(s)
    assert "w" in err.value.variables and "z" in str(err.value)


def test_state_constrained_twice_is_over_determined():
    # der(x) + x = 0 ; x = 1: balanced as a matching over x and der(x) separately, but
    # both equations only involve the chain x: Pantelides would never terminate.
    s = make_structure([{"der(x)": C, "x": C}, {"x": C}], derivatives={"x": "der(x)"})
    assert diagnose(s).kind == "over"


def test_two_voltage_sources_in_parallel_is_singular():
    #   +--(V1)--+--(V2)--+      s1: vp - vn = V1     s2: vp - vn = V2
    #   |        |        |      kcl: i1 + i2 = 0     gnd: vn = 0
    #   +--------+---gnd--+      4 equations, 4 unknowns, no perfect matching
    s = make_structure([{"vp": C, "vn": C}, {"vp": C, "vn": C}, {"i1": C, "i2": C},
                        {"vn": C}], eq_names=["V1.v", "V2.v", "kcl", "ground"])
    d = diagnose(s)
    assert d.kind == "singular"
    assert [s.eq_names[e] for e in d.over_equations] == ["V1.v", "V2.v", "ground"]
    assert [s.var_names[v] for v in d.under_variables] == ["i1", "i2"]
    with pytest.raises(StructurallySingular) as err:
        check_structure(s)
    assert "V1.v" in str(err.value) and "i1" in str(err.value)


def test_floating_circuit_is_under_determined():
    # A source and a resistor with no reference potential, written with potentials of
    # the two nodes: only the difference vp - vn is fixed.
    #   src: vp - vn = V      res: vp - vn = R*i
    s = make_structure([{"vp": C, "vn": C}, {"vp": C, "vn": C, "i": P}],
                       eq_names=["src", "res"])
    with pytest.raises(UnderdeterminedModel) as err:
        check_structure(s)
    assert set(err.value.variables) == {"vp", "vn", "i"}
