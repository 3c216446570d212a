"""The numpy backend's array code (acausal.compiler.backends.arraycode) and the C backend's
looped code (acausal.compiler.backends.cloops) compute what the scalar code computes.

Reference: the scalar functions of the same program (one Python statement per value,
the functions the C backend is tested against).  Every function of the array module is
compared with the scalar one at random points, with every relation's frozen value set
at random, on library models with if-expressions, abs/min/max/sign, modes, clocked
parts and index reduction; results must agree to 1e-12 of each output's own scale.
A large model uses the array code on its own, and its simulation is checked against
the exact solution of the ladder's linear ODE (matrix exponential).
"""
import numpy as np
import pytest

import acausal as ac
from acausal.compiler.backends.arraycode import MIN_STATEMENTS, array_source
from acausal.compiler.backends.cbackend import compiler_available
from acausal.compiler.backends.lazycode import ArrayFunction, GeneratedModule
from acausal.library.electromechanical.examples.sampled_speed_control import SampledSpeedLoop
from acausal.library.friction.examples.stick_slip import StickSlip
from acausal.library.gas.examples.moore_greitzer import Surge
from acausal.library.hydraulics.examples.valve_motor import ValveControlledMotor
from acausal.library.multibody.examples.squeezer import AndrewsSqueezer
from acausal.library.rotational.examples.coupled_clutches import CoupledClutches
from acausal.library.translational.examples.mass_with_stop import MassAgainstStop
from acausal.solvers import cbdf
from acausal.tests.models.test_large_ladder import Ladder, _exact

MODELS = [CoupledClutches, ValveControlledMotor, StickSlip, AndrewsSqueezer, Surge,
          SampledSpeedLoop, MassAgainstStop]


def _sizes(prog):
    kinds = [w[0] for w in prog.refs.values()]
    n_m = 1 + max((w[1] for w in prog.refs.values() if w[0] == "m"), default=-1)
    return kinds.count("y"), kinds.count("p"), n_m


def _compare(code, p_values, rng, points=5, arrays=None):
    prog = code.program
    if arrays is None:
        made = array_source(prog, small=True)
        assert made is not None, "every operator of these models has an array form"
        arrays = GeneratedModule(made[0], filename="<test arrays>").namespace()
    n_y, n_p, n_m = _sizes(prog)
    sizes = {"residual": code.n_rows, "jacobian": len(code.jac_rows), "roots": code.n_roots}
    for name in ("residual", "jacobian", "roots", "scales", "expand"):
        scalar = getattr(code, name)
        scalar = getattr(scalar, "fallback", scalar)
        if scalar is None:
            continue
        n_out = sizes.get(name, len(prog.functions.get(name, ())))
        for _ in range(points):
            y = rng.uniform(0.2, 1.5, n_y) * rng.choice([-1.0, 1.0], n_y)
            p = np.asarray(p_values, float)[:n_p]
            m = rng.integers(0, 2, max(n_m, 1)).astype(float)
            t = float(rng.uniform(0.0, 2.0))
            try:
                want = scalar(t, y, p, m, np.empty(n_out))
            except (ValueError, ZeroDivisionError, OverflowError):
                continue            # outside the domain: the array code falls back to it
            got = arrays[name](t, y, p, m, np.empty(n_out))
            ok = np.isfinite(want)
            scale = np.maximum(np.abs(want[ok]), 1e-300)
            assert np.all(np.abs(got[ok] - want[ok]) <= 1e-12 * scale + 1e-12 * np.max(
                np.abs(want[ok]), initial=0.0)), name


@pytest.mark.parametrize("cls", MODELS, ids=lambda c: c.__name__)
def test_array_functions_equal_the_scalar_functions(cls):
    compiled = ac.compile(cls(), backend="numpy", cache=False)
    _compare(compiled.code, compiled.p, np.random.default_rng(7))


@pytest.mark.skipif(not compiler_available(), reason="no C compiler")
@pytest.mark.parametrize("cls", MODELS, ids=lambda c: c.__name__)
def test_looped_c_functions_equal_the_scalar_functions(cls, monkeypatch):
    monkeypatch.setenv("ACAUSAL_ARRAY_CODE", "always")
    compiled = ac.compile(cls(), backend="c", cache=False)
    code = compiled.code
    assert "for (int i = 0;" in code.c_source
    c_functions = {name: getattr(code, name) for name in
                   ("residual", "jacobian", "roots", "scales", "expand")}
    _compare(code, compiled.p, np.random.default_rng(11), arrays=c_functions)



def _against_exact(compiled, n):
    """Simulate the n-section ladder and check currents and voltages at the first,
    second and last section against the matrix-exponential solution."""
    t = np.linspace(0.0, 5e-3, 6)
    res = ac.simulate(compiled, t_end=t[-1], rtol=1e-8, t_eval=t)
    assert res.success, res.message
    x = _exact(n, t)
    for k in (0, 1, n - 1):
        assert np.max(np.abs(res[f"L[{k}].i"] - x[:, k])) <= 1e-5 * np.max(np.abs(x[:, 0]))
        assert np.max(np.abs(res[f"C[{k}].v"] - x[:, n + k])) <= 1e-5 * np.max(np.abs(x[:, n]))
    return res, t

def test_a_large_model_runs_on_array_code(tmp_path, monkeypatch):
    monkeypatch.setenv("ACAUSAL_CACHE", str(tmp_path))
    n = MIN_STATEMENTS // 4 + 1     # array code, and more unknowns than the dense LU takes
    compiled = ac.compile(Ladder(n), backend="numpy")
    assert isinstance(compiled.code.residual, ArrayFunction)
    assert any("array operations" in note for note in compiled.report.notes)
    _compare(compiled.code, compiled.p, np.random.default_rng(3), points=2)
    # more unknowns than the dense LU takes: the compiled loop's sparse LU calling the
    # array functions back (solvers/cbdf_callbacks.py) when its library is loaded or in
    # this cache, else the Python loop
    assert compiled.n > cbdf.MAX_DENSE
    loop = "c" if cbdf.library(cached_only=True) is not None else "python"
    res, t = _against_exact(compiled, n)
    assert res.stats["step_loop"] == loop
    # the same model from the compile cache: its array code comes with it
    again = ac.compile(Ladder(n), backend="numpy")
    assert any("came from the compile cache" in note for note in again.report.notes)
    assert isinstance(again.code.residual, ArrayFunction)
    res2 = ac.simulate(again, t_end=t[-1], rtol=1e-8, t_eval=t)
    assert np.max(np.abs(res2["C[0].v"] - res["C[0].v"])) <= 1e-12 * np.max(np.abs(res["C[0].v"]))


def test_a_value_outside_the_domain_is_reported_by_the_scalar_code():
    source = "\n".join(["import numpy as np", "_quiet = lambda: np.errstate(all='ignore')",
                        "def residual(t, y, p, m, out):",
                        "    with _quiet():", "        out[:] = np.sqrt(y)", "    return out"])

    def scalar(t, y, p, m, out):
        import math
        out[:] = [math.sqrt(v) for v in y]
        return out

    f = ArrayFunction(GeneratedModule(source, filename="<test arrays>"), "residual", scalar)
    assert f(0.0, np.array([4.0, 9.0]), [], [], np.empty(2)).tolist() == [2.0, 3.0]
    with pytest.raises(ValueError, match="math domain"):
        f(0.0, np.array([4.0, -1.0]), [], [], np.empty(2))


class ClippedRate(ac.Component):
    """der(x) = -x/max(p, 0) while x < 0.5, else -x: with p <= 0 the first branch is
    undefined (compiled as NaN in that mode), x = exp(-t) until t = ln 2."""

    p = ac.Parameter(-1.0)
    x = ac.Variable(start=1.0, fixed=True)

    def equations(self):
        return [ac.Eq(ac.der(self.x),
                      ac.if_else(self.x < 0.5, -self.x / ac.max(self.p, 0), -self.x))]


def test_an_undefined_branch_in_array_code(monkeypatch):
    monkeypatch.setenv("ACAUSAL_ARRAY_CODE", "always")
    compiled = ac.compile(ClippedRate(), backend="numpy", cache=False)
    assert isinstance(compiled.code.residual, ArrayFunction)
    t = np.linspace(0.0, 2.0, 9)
    with pytest.warns(RuntimeWarning, match="stopped early"):
        res = ac.simulate(compiled, 2.0, t_eval=t)
    assert not res.success and "der(x)" in res.message and "not finite" in res.message
    res = ac.simulate(compiled, 2.0, t_eval=t, rtol=1e-9, parameters={"p": 2.0})
    assert res.success
    t1 = np.log(2.0)
    expected = np.where(t < t1, np.exp(-t), 0.5 * np.exp(-(t - t1) / 2.0))
    assert np.max(np.abs(res["x"] - expected)) < 1e-6


def test_every_function_of_the_printer_has_its_numpy_form():
    """Each function the scalar printer knows, printed for arrays, against math."""
    import math

    import sympy as sp

    from acausal.compiler.backends.arraycode import _ArrayEmitter
    from acausal.compiler.backends.emit import _FUNCS
    x, y = sp.symbols("x y")
    em = _ArrayEmitter(lambda q: {x: "x0", y: "x1"}[q])
    xs, ys = np.array([0.3, 0.6]), np.array([1.2, 1.5])
    for f, name in _FUNCS.items():
        args = (x, y) if f is sp.atan2 else (y,) if f is sp.acosh else (x,)
        text = em.expression(f(*args), [])
        got = eval(text, {"np": np, "math": math, "x0": xs, "x1": ys})
        ref = getattr(math, name)
        want = [ref(a, b) if f is sp.atan2 else ref(b if f is sp.acosh else a)
                for a, b in zip(xs, ys)]
        assert np.allclose(got, want, rtol=1e-12, atol=0.0), name


@pytest.mark.skipif(not compiler_available(), reason="no C compiler")
def test_a_ladder_runs_on_looped_c(monkeypatch):
    """The compiled step loop calling looped C functions, against the exact solution."""
    monkeypatch.setenv("ACAUSAL_ARRAY_CODE", "always")
    n = 60
    compiled = ac.compile(Ladder(n), backend="c", cache=False)
    assert "for (int i = 0;" in compiled.code.c_source
    # the report says so, with the residual's statements and the loops they became
    import re
    said = [re.search(r"the C backend evaluates the residual's (\d+) statements in "
                      r"(\d+) loops", note) for note in compiled.report.notes]
    said = [m for m in said if m]
    assert len(said) == 1 and 0 < int(said[0][2]) < int(said[0][1])
    res, t = _against_exact(compiled, n)


def test_a_negated_long_sum_is_one_dot_product(monkeypatch):
    """The ground shared by a 40-section ladder's capacitors has a current that is the
    negated sum of the others, -(i_1 + ... + i_41) (a node balance solved for it):
    the array code and the looped C read its terms as one dot product, not one
    operation (and one C line) each, and compute what the scalar code computes."""
    from acausal.compiler.backends.arraycode import LONG_SUM, _expr_statement, _linear_part
    n = 40
    compiled = ac.compile(Ladder(n), backend="numpy", cache=False)
    prog = compiled.code.program
    negated = [e for e in prog.assigned if e.is_Mul and e.args[0] == -1
               and e.args[1].is_Add and len(e.args[1].args) > LONG_SUM]
    assert len(negated) == 1
    e = negated[0]
    st = _expr_statement(("a", 0), e, {q: ("y", k) for k, q in
                                       enumerate(sorted(e.free_symbols, key=str))})
    linear, rest = _linear_part(st)
    assert len(linear) == n + 1 and rest == []
    # the dot product is the expression: at random values of its leaves
    rng = np.random.default_rng(1)
    leaves = {q: rng.uniform(-1, 1) for q in e.free_symbols}
    by_number = {k: leaves[q] for q, k in st.expr[1].items()}
    dot = sum(c * by_number[k] for c, k in linear)
    assert abs(dot - float(e.xreplace(leaves))) <= 1e-12 * sum(map(abs, leaves.values()))
    _compare(compiled.code, compiled.p, np.random.default_rng(3))
    if compiler_available():
        monkeypatch.setenv("ACAUSAL_ARRAY_CODE", "always")
        looped = ac.compile(Ladder(n), backend="c", cache=False)
        source = looped.code.c_source
        assert f"for (int k = 0; k < {n + 1}; ++k) s += C[k]*w[" in source
        code = looped.code
        _compare(code, looped.p, np.random.default_rng(5), arrays={
            name: getattr(code, name) for name in
            ("residual", "jacobian", "roots", "scales", "expand")})


@pytest.mark.skipif(not compiler_available(), reason="no C compiler")
def test_looped_c_reads_its_index_arrays_at_run_time(tmp_path, monkeypatch):
    """A looped library is given its index arrays when it is loaded: two ladders alive
    at once each compute their own exact solution, also after a twin that shared one's
    library was freed, and a pickled one, its library deleted, is rebuilt from its
    source and given its index again."""
    import hashlib
    import os
    import pickle

    from acausal.native import build as cbuild
    monkeypatch.setenv("ACAUSAL_ARRAY_CODE", "always")
    monkeypatch.setenv("ACAUSAL_CACHE", str(tmp_path))
    first = ac.compile(Ladder(60), backend="c", cache=False)
    second = ac.compile(Ladder(61), backend="c", cache=False)
    for compiled in (first, second):
        code = compiled.code
        index = code.c_layout["index"]
        assert index is not None and len(index) > 0
        assert "static const int" not in code.c_source
        # the source names the index it reads: one library, one index
        assert hashlib.sha256(index.tobytes()).hexdigest()[:24] in code.c_source
        assert cbuild.flags_for(code.c_source) == cbuild.FLAGS_LOOPED
    assert first.code.library != second.code.library
    # a second model of the same source loads the same library; freeing it leaves the
    # first one's index in place
    twin = ac.compile(Ladder(60), backend="c", cache=False)
    assert twin.code.library == first.code.library
    del twin
    import gc
    gc.collect()
    res, t = _against_exact(first, 60)
    _against_exact(second, 61)
    data = pickle.dumps(first)
    os.remove(first.code.library)
    loaded = pickle.loads(data)
    assert loaded.backend == "c" and os.path.exists(loaded.code.library)
    again = ac.simulate(loaded, t_end=t[-1], rtol=1e-8, t_eval=t)
    scale = np.max(np.abs(res["C[0].v"]))
    assert np.max(np.abs(again["C[0].v"] - res["C[0].v"])) <= 1e-12 * scale
