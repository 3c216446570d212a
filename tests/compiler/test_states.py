"""Dummy-derivative state selection after Pantelides."""
import pytest

from acausal.compiler.structure.blt import blt
from acausal.compiler.structure.graph import (
    ALWAYS, LINEAR_CONST as C, LINEAR_PARAM as P, LINEAR_VAR as V, NEVER,
    NONLINEAR as N, PREFER, UNASSIGNED)
from acausal.compiler.structure.pantelides import pantelides
from acausal.compiler.structure.states import index1_matching, select_states
from acausal.compiler.structure.matching import make_structure
from acausal.errors import StructurallySingular


def pendulum(priority=None):
    # ex: der(x) = vx   ey: der(y) = vy   fx: m der(vx) = -lam x
    # fy: m der(vy) = -lam y - m g        c: x^2 + y^2 = L^2
    return make_structure(
        [{"der(x)": C, "vx": C}, {"der(y)": C, "vy": C},
         {"der(vx)": P, "lam": V, "x": V}, {"der(vy)": P, "lam": V, "y": V},
         {"x": N, "y": N}],
        derivatives={"x": "der(x)", "y": "der(y)", "vx": "der(vx)", "vy": "der(vy)"},
        eq_names=["ex", "ey", "fx", "fy", "c"], var_names=["x", "y", "vx", "vy", "lam"],
        state_priority=priority)


def gear(priority=None):
    # k1: der(phi1) = w1   k2: der(phi2) = w2   m1: J1 der(w1) = T - n tau
    # m2: J2 der(w2) = tau   g: phi2 = n phi1   (n a parameter: LINEAR_PARAM)
    return make_structure(
        [{"der(phi1)": C, "w1": C}, {"der(phi2)": C, "w2": C},
         {"der(w1)": P, "tau": P}, {"der(w2)": P, "tau": C}, {"phi2": C, "phi1": P}],
        derivatives={"phi1": "der(phi1)", "w1": "der(w1)", "phi2": "der(phi2)",
                     "w2": "der(w2)"},
        eq_names=["k1", "k2", "m1", "m2", "g"],
        var_names=["phi1", "w1", "phi2", "w2", "tau"], state_priority=priority)


def run(s):
    r = pantelides(s)
    sel = select_states(r)
    return r, sel, r.structure


def names(s, vs):
    return [s.var_names[v] for v in vs]


def enames(s, es):
    return [s.eq_names[e] for e in es]


def assert_index1(r, sel):
    """The MS93 guarantee: square, structurally nonsingular, der(states) unknown."""
    s = r.structure
    assert len(sel.unknowns) == s.n_eqs
    var_to_eq, eq_to_var = index1_matching(r, sel)
    assert UNASSIGNED not in eq_to_var
    for v, dv in zip(sel.states, sel.state_derivatives):
        assert s.var_to_diff[v] == dv and var_to_eq[dv] is not UNASSIGNED
        assert dv not in sel.dummies and var_to_eq[v] is UNASSIGNED
    for d in sel.dummies:
        assert s.diff_to_var[d] is not UNASSIGNED and d in sel.unknowns
    return eq_to_var


def test_pendulum_two_states_with_dynamic_set():
    r, sel, s = run(pendulum())
    assert names(s, sel.states) == ["x", "vx"]
    assert names(s, sel.state_derivatives) == ["der(x)", "der(vx)"]
    assert names(s, sel.dummies) == ["der(y)", "der(vy)", "der(der(x))", "der(der(y))"]
    assert [(enames(s, e), names(s, d)) for e, d in sel.levels] == [
        (["d/dt(ex)", "d/dt(ey)", "d/dt(d/dt(c))"],
         ["der(vy)", "der(der(x))", "der(der(y))"]),
        (["d/dt(c)"], ["der(y)"])]
    # coefficients 2x, 2y: the choice is only valid while x resp. y is non-zero
    top, low = sel.state_sets
    assert (top.level, enames(s, top.equations), names(s, top.candidates),
            top.n_dummies) == (1, ["d/dt(ex)", "d/dt(ey)", "d/dt(d/dt(c))"],
                               ["der(vx)", "der(vy)", "der(der(x))", "der(der(y))"], 3)
    assert (low.level, enames(s, low.equations), names(s, low.candidates),
            low.n_dummies, names(s, low.dummies)) == (
        2, ["d/dt(c)"], ["der(x)", "der(y)"], 1, ["der(y)"])
    assert_index1(r, sel)


def test_pendulum_state_priority():
    r, sel, s = run(pendulum({"y": PREFER, "vy": PREFER}))
    assert names(s, sel.states) == ["y", "vy"]
    r, sel, s = run(pendulum({"x": NEVER}))
    assert "x" not in names(s, sel.states) and len(sel.states) == 2
    assert_index1(r, sel)


def test_gear_static_selection():
    r, sel, s = run(gear())
    assert names(s, sel.states) == ["phi1", "w1"]
    assert names(s, sel.dummies) == ["der(phi2)", "der(w2)", "der(der(phi1))",
                                     "der(der(phi2))"]
    assert sel.state_sets == []               # constant/parameter coefficients only
    assert_index1(r, sel)


def test_gear_priorities():
    _, sel, s = run(gear({"phi1": NEVER, "w1": NEVER}))
    assert names(s, sel.states) == ["phi2", "w2"]
    _, sel, s = run(gear({"phi2": ALWAYS, "w2": ALWAYS}))
    assert names(s, sel.states) == ["phi2", "w2"]
    with pytest.raises(StructurallySingular, match="phi1"):
        select_states(pantelides(gear({"phi1": ALWAYS, "phi2": ALWAYS})))


def test_gear_keeps_the_variables_with_fixed_starts_as_states():
    """Among equally valid candidates the ones with fixed start values (tie_break) stay
    states; a StateSelect hint still comes first."""
    from acausal.compiler.structure.graph import state_tie_break
    def tied(priority=None):
        s = gear(priority)
        for name in ("phi2", "w2"):
            s.tie_break[s.var_names.index(name)] = state_tie_break(True, None)
        return s
    r, sel, s = run(tied())
    assert names(s, sel.states) == ["phi2", "w2"]
    assert_index1(r, sel)
    _, sel, s = run(tied({"phi1": PREFER, "w1": PREFER}))
    assert names(s, sel.states) == ["phi1", "w1"]
    # a nominal of its own ranks below a fixed start, above nothing
    assert state_tie_break(True, None) > state_tie_break(False, 1e-3) > \
        state_tie_break(None, None)


def test_capacitor_across_voltage_source_has_no_state():
    # src: u = V(t)     cap: C der(u) = i
    s = make_structure([{"u": C}, {"der(u)": P, "i": C}], derivatives={"u": "der(u)"},
                       eq_names=["src", "cap"])
    r, sel, S = run(s)
    assert sel.states == [] and names(S, sel.dummies) == ["der(u)"]
    e2v = assert_index1(r, sel)
    order = [(enames(S, b.eqs), names(S, b.vars)) for b in blt(S, e2v)]
    assert order == [(["src"], ["u"]), (["d/dt(src)"], ["der(u)"]), (["cap"], ["i"])]


def test_two_capacitors_in_parallel_one_state():
    # C1 der(u1) = i1   C2 der(u2) = i2   u1 = u2   i1 + i2 = I(t)
    s = make_structure([{"der(u1)": P, "i1": C}, {"der(u2)": P, "i2": C},
                        {"u1": C, "u2": C}, {"i1": C, "i2": C}],
                       derivatives={"u1": "der(u1)", "u2": "der(u2)"},
                       var_names=["u1", "u2", "i1", "i2"])
    r, sel, S = run(s)
    assert names(S, sel.states) == ["u1"] and names(S, sel.dummies) == ["der(u2)"]
    assert sel.state_sets == []
    assert_index1(r, sel)


def test_inductor_in_series_with_current_source_has_no_state():
    s = make_structure([{"der(iL)": P, "u": C}, {"iL": C}], derivatives={"iL": "der(iL)"})
    r, sel, S = run(s)
    assert sel.states == [] and names(S, sel.dummies) == ["der(iL)"]
    assert_index1(r, sel)


def test_ode_keeps_all_states():
    # der(x) = v, der(v) = -x: nothing differentiated, nothing dummy
    s = make_structure([{"der(x)": C, "v": C}, {"der(v)": C, "x": C}],
                       derivatives={"x": "der(x)", "v": "der(v)"}, var_names=["x", "v"])
    r, sel, S = run(s)
    assert names(S, sel.states) == ["x", "v"] and sel.dummies == [] and sel.levels == []
    assert_index1(r, sel)
