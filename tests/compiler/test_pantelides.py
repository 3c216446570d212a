"""Pantelides index reduction on small mechanical and electrical models."""
import copy

import pytest

from acausal.compiler.structure.graph import (
    LINEAR_CONST as C, LINEAR_PARAM as P, LINEAR_VAR as V, NONLINEAR as N, UNASSIGNED)
from acausal.compiler.structure.pantelides import pantelides, predict_derivative
from acausal.compiler.structure.matching import (
    IndexReductionFailed, OverdeterminedModel, StructurallySingular, make_structure)

DERS = {"x": "der(x)", "y": "der(y)", "vx": "der(vx)", "vy": "der(vy)"}


def pendulum():
    # vars 0..8: x y vx vy lam der(x) der(y) der(vx) der(vy)
    # ex: der(x) = vx            ey: der(y) = vy
    # fx: m der(vx) = -lam x     fy: m der(vy) = -lam y - m g
    # c:  x^2 + y^2 = L^2
    return make_structure(
        [{"der(x)": C, "vx": C}, {"der(y)": C, "vy": C},
         {"der(vx)": P, "lam": V, "x": V}, {"der(vy)": P, "lam": V, "y": V},
         {"x": N, "y": N}],
        derivatives=DERS, eq_names=["ex", "ey", "fx", "fy", "c"],
        var_names=["x", "y", "vx", "vy", "lam"])


def gear():
    # two inertias coupled by an ideal gear phi2 = n*phi1 (n a parameter)
    # k1: der(phi1) = w1   k2: der(phi2) = w2
    # m1: J1 der(w1) = T(t) - n*tau     m2: J2 der(w2) = tau     g: phi2 = n*phi1
    return make_structure(
        [{"der(phi1)": C, "w1": C}, {"der(phi2)": C, "w2": C},
         {"der(w1)": P, "tau": P}, {"der(w2)": P, "tau": C}, {"phi2": C, "phi1": P}],
        derivatives={"phi1": "der(phi1)", "w1": "der(w1)", "phi2": "der(phi2)",
                     "w2": "der(w2)"},
        eq_names=["k1", "k2", "m1", "m2", "g"], var_names=["phi1", "w1", "phi2", "w2", "tau"])


def names(s, vs):
    return [s.var_names[v] for v in vs]


def test_pendulum_counts_and_new_variables():
    s = pendulum()
    before = copy.deepcopy(s)
    r = pantelides(s)
    assert s == before                                   # input untouched
    assert r.diff_counts == [1, 1, 0, 0, 2]
    S = r.structure
    assert S.var_names[9:] == ["der(der(x))", "der(der(y))"]
    assert S.eq_names[5:] == ["d/dt(c)", "d/dt(ex)", "d/dt(ey)", "d/dt(d/dt(c))"]
    assert S.var_to_diff[5] == 9 and S.diff_to_var[10] == 6
    assert S.eq_to_diff[4] == 5 and S.eq_to_diff[5] == 8 and S.diff_to_eq[6] == 0
    # d/dt(c) = 2x der(x) + 2y der(y): x, y stay (nonlinear), derivatives enter linearly
    assert names(S, S.graph[5]) == ["x", "y", "der(x)", "der(y)"]
    assert S.coeff[5][5] == V and S.coeff[5][0] == N
    # d/dt(ex): der(der(x)) = der(vx); vx had a constant coefficient and drops out
    assert names(S, S.graph[6]) == ["der(vx)", "der(der(x))"]


def test_pendulum_final_matching_uses_highest_derivatives():
    r = pantelides(pendulum())
    S = r.structure
    match = {S.eq_names[e]: S.var_names[v] for e, v in enumerate(r.eq_to_var)
             if v is not UNASSIGNED}
    assert match == {"fx": "lam", "fy": "der(vy)", "d/dt(ex)": "der(vx)",
                     "d/dt(ey)": "der(der(y))", "d/dt(d/dt(c))": "der(der(x))"}
    for v, e in enumerate(r.var_to_eq):
        if e is not UNASSIGNED:
            assert S.var_to_diff[v] is UNASSIGNED and r.eq_to_var[e] == v
            assert S.eq_to_diff[e] is UNASSIGNED


def test_gear_constraint_differentiated_twice():
    r = pantelides(gear())
    assert r.diff_counts == [1, 1, 0, 0, 2]


def test_capacitor_across_voltage_source():
    # src: u = V(t)     cap: C der(u) = i       (index 2)
    s = make_structure([{"u": C}, {"der(u)": P, "i": C}], derivatives={"u": "der(u)"},
                       eq_names=["src", "cap"])
    r = pantelides(s)
    assert r.diff_counts == [1, 0]
    assert names(r.structure, r.structure.graph[2]) == ["der(u)"]   # der(u) = dV/dt


def test_two_capacitors_in_parallel():
    # C1 der(u1) = i1   C2 der(u2) = i2   u1 = u2   i1 + i2 = I(t)
    s = make_structure([{"der(u1)": P, "i1": C}, {"der(u2)": P, "i2": C},
                        {"u1": C, "u2": C}, {"i1": C, "i2": C}],
                       derivatives={"u1": "der(u1)", "u2": "der(u2)"},
                       var_names=["u1", "u2", "i1", "i2"])
    assert pantelides(s).diff_counts == [0, 0, 1, 0]


def test_inductor_in_series_with_current_source():
    # L der(iL) = u      iL = I(t)
    s = make_structure([{"der(iL)": P, "u": C}, {"iL": C}], derivatives={"iL": "der(iL)"})
    assert pantelides(s).diff_counts == [0, 1]


def test_index_one_model_is_untouched():
    # der(x) = -x + z ; 0 = z - x^2
    s = make_structure([{"der(x)": C, "x": C, "z": C}, {"z": C, "x": N}],
                       derivatives={"x": "der(x)"})
    r = pantelides(s)
    assert r.diff_counts == [0, 0] and r.structure.n_eqs == 2


def test_singular_models_raise_with_names():
    # two voltage sources in parallel
    s = make_structure([{"vp": C, "vn": C}, {"vp": C, "vn": C}, {"i1": C, "i2": C},
                        {"vn": C}], eq_names=["V1.v", "V2.v", "kcl", "ground"])
    with pytest.raises(StructurallySingular) as err:
        pantelides(s)
    assert {"V1.v", "V2.v"} <= set(err.value.equations)
    assert isinstance(err.value, IndexReductionFailed)
    # a state fixed twice: Pantelides alone would differentiate forever
    s = make_structure([{"der(x)": C, "x": C}, {"x": C}], derivatives={"x": "der(x)"},
                       eq_names=["ode", "fix"])
    with pytest.raises(OverdeterminedModel) as err:
        pantelides(s)
    assert err.value.variables == ["x"]


def test_differentiate_callback_gets_existing_derivatives():
    calls = []

    def differentiate(s, e):
        for v in s.graph[e]:           # the pass created every der(v) beforehand
            assert s.var_to_diff[v] is not UNASSIGNED
        calls.append(s.eq_names[e])
        return predict_derivative(s, e)

    r = pantelides(pendulum(), differentiate=differentiate)
    assert calls == ["c", "ex", "ey", "d/dt(c)"]
    assert r.diff_counts == [1, 1, 0, 0, 2]


def test_callback_can_report_exact_incidence():
    # the symbolic layer knows d/dt(c) cancels y's term (say): its result is used
    def differentiate(s, e):
        vs, co = predict_derivative(s, e)
        if s.eq_names[e] == "c":
            vs = [v for v in vs if s.var_names[v] != "der(y)"]
        return vs, {v: co[v] for v in vs}

    r = pantelides(pendulum(), differentiate=differentiate)
    assert "der(y)" not in names(r.structure, r.structure.graph[5])


def test_max_rounds_guard():
    with pytest.raises(IndexReductionFailed, match="did not terminate"):
        pantelides(pendulum(), max_rounds=1)


def test_long_chain_differentiates_every_link_like_the_pendulum():
    # (its run time is reported by benchmarks/bench_counts.py and bench_structure.py)
    n = 300
    eqs, ders = [], {}
    for i in range(1, n + 1):        # point masses on rigid links, like the benchmark
        x, y, vx, vy, lam = (f"x{i}", f"y{i}", f"vx{i}", f"vy{i}", f"lam{i}")
        for a in (x, y, vx, vy):
            ders[a] = f"der({a})"
        eqs += [{f"der({x})": C, vx: C}, {f"der({y})": C, vy: C}]
        fx = {f"der({vx})": P, lam: V, x: V}
        fy = {f"der({vy})": P, lam: V, y: V}
        if i < n:
            fx.update({f"lam{i + 1}": V, f"x{i + 1}": V})
            fy.update({f"lam{i + 1}": V, f"y{i + 1}": V})
        c = {x: N, y: N}
        if i > 1:
            c.update({f"x{i - 1}": N, f"y{i - 1}": N})
        eqs += [fx, fy, c]
    r = pantelides(make_structure(eqs, derivatives=ders))
    assert r.diff_counts == [1, 1, 0, 0, 2] * n
