"""The C backend against the numpy backend: the same functions, the same runs.

Both print the same operations in the same order (compiler/backends/emit.py), so they agree to
rounding: every generated function at random points, and whole simulations with
events, modes, when-clauses, sampled controllers and dynamic state selection, to 1e-12
of each signal's own scale.  Without a C compiler the module is skipped, except the test that ``"auto"``
then falls back and says so.
"""
import math

import numpy as np
import pytest
import sympy as sp

import acausal as ac
from acausal.compiler.backends import cbackend
from acausal.library.electromechanical.examples.sampled_speed_control import SampledSpeedLoop
from acausal.library.examples.motor_drive import MotorDrive
from acausal.library.examples.pendulum import DoublePendulum, Pendulum
from acausal.library.hydraulics.examples.valve_motor import ValveControlledMotor
from acausal.tests.heater import LimitedHeater
from acausal.tests.models.test_events import BouncingBall

needs_cc = pytest.mark.skipif(cbackend.compiler_available() is None,
                              reason="no C compiler on this machine")

MODELS = [(MotorDrive, 0.5), (Pendulum, 3.0), (DoublePendulum, 1.0),
          (ValveControlledMotor, 0.1), (LimitedHeater, 600.0), (BouncingBall, 3.0),
          (SampledSpeedLoop, 0.03)]


def _pair(model_class):
    return (ac.compile(model_class(), backend="numpy"),
            ac.compile(model_class(), backend="c"))


@needs_cc
@pytest.mark.parametrize("model_class, t_end", MODELS, ids=lambda m: getattr(m, "__name__", ""))
def test_every_generated_function_agrees_at_random_points(model_class, t_end):
    py, c = _pair(model_class)
    assert (py.backend, c.backend) == ("numpy", "c")
    rng = np.random.default_rng(3)
    z0 = ac.initial_values(py)
    for _ in range(5):
        z = z0 * (1 + 0.1 * rng.standard_normal(z0.size)) + 0.01 * rng.standard_normal(z0.size)
        for name in ("residual", "jacobian", "roots", "scales", "expand"):
            f_py, f_c = getattr(py.code, name), getattr(c.code, name)
            n = {"residual": py.code.n_rows, "jacobian": len(py.code.jac_rows),
                 "roots": py.code.n_roots, "scales": len(py.model_code.relations.ops),
                 "expand": py.meta["n_all"]}[name]
            a = f_py(0.3, z, py.p, py.m, np.empty(n))
            b = f_c(0.3, z, c.p, py.m.copy(), np.empty(n))
            scale = np.maximum(np.abs(a), np.finfo(float).tiny)
            assert np.all(np.abs(a - b) <= 1e-12 * scale), name
        if py.whens is not None:         # conditions, reinit and assigned values, clocks
            n = py.whens.code.n_rows
            a = py.whens.code.residual(0.3, z, py.p, py.m, np.empty(n))
            b = c.whens.code.residual(0.3, z, c.p, py.m.copy(), np.empty(n))
            assert np.all(np.abs(a - b) <= 1e-12 * np.maximum(np.abs(a), 1e-300)), "whens"


@needs_cc
@pytest.mark.parametrize("loop", ["python", "c"])
@pytest.mark.parametrize("model_class, t_end", MODELS, ids=lambda m: getattr(m, "__name__", ""))
def test_simulations_agree_to_1e_12_of_each_signal(model_class, t_end, loop):
    py, c = _pair(model_class)
    # the same step loop on both (the compiled loop calls the numpy code back): the two
    # loops factor with different LUs, so they agree to the tolerance, not to rounding
    # (tests/solvers/test_cbdf.py)
    a = ac.simulate(py, t_end=t_end, rtol=1e-6, step_loop=loop)
    b = ac.simulate(c, t_end=t_end, rtol=1e-6, step_loop=loop)
    assert a.stats["step_loop"] == b.stats["step_loop"] == loop
    assert a.success and b.success
    assert len(a.t) == len(b.t)
    np.testing.assert_allclose(b.t, a.t, rtol=1e-12, atol=0)
    for name in py.states + list(py.names):
        x, y = a[name], b[name]
        scale = max(np.max(np.abs(x)), np.finfo(float).tiny)
        assert np.max(np.abs(x - y)) <= 1e-12 * scale, name


@needs_cc
def test_a_domain_error_in_c_names_the_equation_as_python_does():
    """sqrt of a negative start value: C computes NaN, the call is repeated in Python,
    and the message names der(x) as the numpy backend does."""

    class SqrtOfStart(ac.Component):
        x = ac.Variable(start=-1.0)

        def equations(self):
            return [ac.Eq(ac.der(self.x), -sp.sqrt(self.x))]

    messages = []
    for backend in ("numpy", "c"):
        with pytest.raises(ac.InitializationFailed) as err:
            ac.simulate(SqrtOfStart(), t_end=1.0, backend=backend)
        messages.append(str(err.value))
    assert messages[0] == messages[1]
    assert "der(x)" in messages[1] and "math domain error" in messages[1]


@needs_cc
def test_the_library_is_cached_by_its_source(tmp_path, monkeypatch):
    monkeypatch.setenv("ACAUSAL_CACHE", str(tmp_path))
    first = ac.compile(Pendulum(), backend="c")
    second = ac.compile(Pendulum(), backend="c")
    libs = list(tmp_path.glob("model_*.so"))
    assert len(libs) == 1
    assert first.code.library == second.code.library == str(libs[0])


def test_without_a_compiler_auto_falls_back_and_c_refuses(monkeypatch):
    monkeypatch.setenv("CC", "no-such-compiler-acausal")
    compiled = ac.compile(Pendulum(), backend="auto")
    assert compiled.backend == "numpy"
    assert any("C backend is not available" in n for n in compiled.report.notes)
    res = ac.simulate(compiled, t_end=1.0, rtol=1e-8)
    assert res.success and abs(res["x"][-1] ** 2 + res["y"][-1] ** 2 - 1.0) < 1e-6
    with pytest.raises(cbackend.BackendError, match="no C compiler"):
        ac.compile(Pendulum(), backend="c")
    with pytest.raises(ValueError, match="backend must be one of"):
        ac.compile(Pendulum(), backend="fortran")


@needs_cc
def test_a_sum_of_thousands_of_terms_compiles_in_both_backends():
    """One node balance of 5,000 currents: printed as balanced groups, so neither
    CPython's compiler nor the C compiler meets one expression of 5,000 operands."""
    n = 5000
    x = sp.symbols(f"x0:{n}")
    s = sp.Symbol("s")
    from acausal.compiler.backends.codegen import plan, python_code
    prog = plan([s - sp.Add(*[(k + 1) * x[k] for k in range(n)])], [s, *x], [])
    code = python_code(prog)
    source, sizes = cbackend.c_source({"f_": prog})
    cbackend.attach(code, cbackend.build(source), "f_", sizes["f_"])
    z = np.linspace(0.0, 1.0, n + 1)
    expected = z[0] - math.fsum((k + 1) * z[k + 1] for k in range(n))
    r = code.residual(0.0, z, np.array([]), np.array([]), np.empty(1))[0]
    scale = math.fsum((k + 1) * z[k + 1] for k in range(n))
    assert abs(r - expected) <= 1e-12 * scale
    jac = code.jacobian(0.0, z, np.array([]), np.array([]), np.empty(n + 1))
    np.testing.assert_array_equal(jac, [1.0] + [-(k + 1.0) for k in range(n)])
