"""Tearing of algebraic loops."""
from acausal.compiler.structure.graph import (
    LINEAR_CONST as C, LINEAR_PARAM as P, LINEAR_VAR as V, NONLINEAR as N)
from acausal.compiler.structure.matching import make_structure
from acausal.compiler.structure.tearing import tear


def check(s, eqs, vars, t):
    """Inner assignments are causal given the iteration variables."""
    assert len(t.iteration_vars) == len(t.residual_eqs)
    assert sorted(t.iteration_vars + [v for _, v in t.inner]) == sorted(vars)
    assert sorted(t.residual_eqs + [e for e, _ in t.inner]) == sorted(eqs)
    known = set(t.iteration_vars)
    for e, v in t.inner:
        assert {w for w in s.graph[e] if w in vars} - known <= {v}
        known.add(v)


def test_linear_cycle_needs_one_iteration_variable():
    # e0: a + b = 1     e1: b - c = 0     e2: c + a = 2        (a cycle a-b-c-a)
    s = make_structure([{"a": C, "b": C}, {"b": C, "c": C}, {"c": C, "a": C}],
                       var_names=["a", "b", "c"])
    t = tear(s, [0, 1, 2], [0, 1, 2])
    check(s, [0, 1, 2], [0, 1, 2], t)
    assert len(t.iteration_vars) == 1


def test_resistive_network_loop():
    # two resistors in parallel fed through a third, in branch form:
    # e0: u0 = R0 i0   e1: u1 = R1 i1   e2: u1 = R2 i2   e3: i0 = i1 + i2   e4: u0 + u1 = U
    s = make_structure([{"u0": C, "i0": P}, {"u1": C, "i1": P}, {"u1": C, "i2": P},
                        {"i0": C, "i1": C, "i2": C}, {"u0": C, "u1": C}],
                       var_names=["u0", "u1", "i0", "i1", "i2"])
    eqs, vars = list(range(5)), list(range(5))
    t = tear(s, eqs, vars)
    check(s, eqs, vars, t)
    assert len(t.iteration_vars) == 1


def test_nonlinear_entries_are_not_solved():
    # e0: a = sin(b)     e1: b = a^3 + b^5 ... b only nonlinear in e1, a only in e0
    s = make_structure([{"a": C, "b": N}, {"a": N, "b": N}], var_names=["a", "b"])
    t = tear(s, [0, 1], [0, 1])
    check(s, [0, 1], [0, 1], t)
    assert t.iteration_vars == [1] and t.inner == [(0, 0)] and t.residual_eqs == [1]


def test_linear_var_only_when_allowed():
    # e0: x*a = 1 (a with variable coefficient x)    e1: a + b = 0
    s = make_structure([{"a": V, "x": N}, {"a": C, "b": C}], var_names=["a", "b", "x"])
    assert len(tear(s, [0, 1], [0, 1]).iteration_vars) == 1
    t = tear(s, [0, 1], [0, 1], allow_linear_var=True)
    assert t.iteration_vars == [] and t.inner == [(0, 0), (1, 1)]


def test_custom_solvable():
    s = make_structure([{"a": C, "b": C}, {"a": C, "b": C}], var_names=["a", "b"])
    t = tear(s, [0, 1], [0, 1], solvable=lambda e, v: False)
    assert len(t.iteration_vars) == 2 and t.inner == []


def test_pendulum_loop_tears_on_the_multiplier():
    # after index reduction the accelerations and lam form one linear loop; guessing
    # lam makes every other unknown explicit, d/dt(d/dt(c)) is the residual
    from acausal.compiler.structure.blt import blt
    from acausal.compiler.structure.pantelides import pantelides
    from acausal.compiler.structure.states import index1_matching, select_states
    s = make_structure(
        [{"der(x)": C, "vx": C}, {"der(y)": C, "vy": C},
         {"der(vx)": P, "lam": V, "x": V}, {"der(vy)": P, "lam": V, "y": V},
         {"x": N, "y": N}],
        derivatives={"x": "der(x)", "y": "der(y)", "vx": "der(vx)", "vy": "der(vy)"},
        eq_names=["ex", "ey", "fx", "fy", "c"], var_names=["x", "y", "vx", "vy", "lam"])
    p = pantelides(s)
    S = p.structure
    _, eq_to_var = index1_matching(p, select_states(p))
    loop = blt(S, eq_to_var)[-1]
    assert len(loop.eqs) == 5
    t = tear(S, loop.eqs, loop.vars)
    check(S, loop.eqs, loop.vars, t)
    assert [S.var_names[v] for v in t.iteration_vars] == ["lam"]
    assert [S.eq_names[e] for e in t.residual_eqs] == ["d/dt(d/dt(c))"]
