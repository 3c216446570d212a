"""Tarjan BLT ordering."""
from acausal.compiler.structure.blt import blt, strongly_connected_components
from acausal.compiler.structure.graph import LINEAR_CONST as C, UNASSIGNED
from acausal.compiler.structure.matching import make_structure, maximum_matching


def test_scc_order_and_content():
    # 0 -> 1 -> 2 -> 1,  2 -> 3,  4 -> 0,  5 alone          (u -> w: u needs w)
    adj = [[1], [2], [1, 3], [], [0], []]
    assert strongly_connected_components(adj) == [[3], [1, 2], [0], [4], [5]]


def test_scc_deep_chain_does_not_recurse():
    n = 100000
    adj = [[i + 1] for i in range(n - 1)] + [[0]]      # one cycle through everything
    assert strongly_connected_components(adj) == [list(range(n))]
    adj = [[i + 1] for i in range(n - 1)] + [[]]       # a path: sinks first
    comps = strongly_connected_components(adj)
    assert comps[0] == [n - 1] and comps[-1] == [0] and len(comps) == n


def test_blt_hand_graph():
    #  e0: a            -> block 1: a
    #  e1: a, b, c      \  block 2: {b, c} algebraic loop (e1, e2)
    #  e2: b, c         /
    #  e3: c, d         -> block 3: d
    #  e4: d, x         -> block 4: e    (x unmatched: known, e.g. a state)
    s = make_structure([{"a": C}, {"a": C, "b": C, "c": C}, {"b": C, "c": C},
                        {"c": C, "d": C}, {"d": C, "e": C, "x": C}],
                       var_names=["a", "b", "c", "d", "e", "x"])
    var_to_eq, eq_to_var = maximum_matching(s, vars=range(5))
    blocks = blt(s, eq_to_var)
    assert [b.eqs for b in blocks] == [[0], [1, 2], [3], [4]]
    assert [sorted(b.vars) for b in blocks] == [[0], [1, 2], [3], [4]]
    for b in blocks:
        assert b.vars == [eq_to_var[e] for e in b.eqs]


def test_blt_subset_and_unmatched():
    s = make_structure([{"a": C}, {"a": C, "b": C}])
    eq_to_var = [0, 1]
    assert [b.eqs for b in blt(s, eq_to_var, eqs=[1])] == [[1]]
    assert [b.eqs for b in blt(s, [0, UNASSIGNED])] == [[0]]
