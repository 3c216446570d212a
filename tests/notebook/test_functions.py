"""acausal.functions: the math functions of a model's equations, without importing sympy.

Checked against closed forms: a draining tank der(h) = -k sqrt(h) (Torricelli's law)
has h(t) = (sqrt(h0) - k t / 2)^2; algebraic outputs built from the other functions are
compared with numpy at every output point; abs/min/max on numbers equal the builtins.
"""
import builtins
import subprocess
import sys

import numpy as np
import pytest
import sympy

import acausal as ac
from acausal import functions as fn


class Tank(ac.Component):
    """der(h) = -k sqrt(h), plus outputs that exercise every function of the module."""

    k = ac.Parameter(0.8, unit="1/s", description="outflow coefficient")
    h = ac.Variable(start=1.0, fixed=True, unit="m")
    a = ac.Variable()
    b = ac.Variable()
    c = ac.Variable()
    d = ac.Variable()
    e = ac.Variable()

    def equations(self):
        t = ac.time
        return [ac.Eq(ac.der(self.h), -self.k * ac.sqrt(self.h)),
                ac.Eq(self.a, ac.atan2(ac.sin(t), ac.cos(t))),
                ac.Eq(self.b, ac.log(ac.exp(t) + 1) + ac.log10(1 + t)),
                ac.Eq(self.c, ac.tanh(t) * ac.cosh(t) - ac.sinh(t) + ac.tan(t / 4)),
                ac.Eq(self.d, ac.asin(t / 2) + ac.acos(t / 2) + ac.atan(t) + ac.pi),
                ac.Eq(self.e, ac.max(ac.sin(3 * t), 0.5) + ac.min(t, 1.0)
                      + ac.abs(t - 0.7))]


def test_functions_in_equations_match_closed_forms():
    res = ac.simulate(ac.compile(Tank()), t_end=1.5, rtol=1e-10, atol=1e-12)
    t = res.t
    h_exact = (1.0 - 0.8 * t / 2) ** 2
    assert np.max(np.abs(res["h"] - h_exact)) < 1e-7 * np.max(h_exact)
    expected = {
        "a": t,                                        # atan2(sin t, cos t) = t for t < pi
        "b": np.log(np.exp(t) + 1) + np.log10(1 + t),
        "c": np.tan(t / 4),                            # tanh cosh = sinh
        "d": np.pi / 2 + np.arctan(t) + np.pi,         # asin + acos = pi/2
        "e": np.maximum(np.sin(3 * t), 0.5) + np.minimum(t, 1.0) + np.abs(t - 0.7),
    }
    for name, value in expected.items():
        scale = np.max(np.abs(value))
        assert np.max(np.abs(res[name] - value)) < 1e-9 * scale, name
    # the kinks of max, min and abs are located events, not smoothed over
    assert len(res.events) >= 3


def test_symbolic_results_are_sympy_functions():
    x, y = sympy.symbols("x y", real=True)
    assert fn.abs(x) == sympy.Abs(x)
    assert fn.min(x, y) == sympy.Min(x, y) and fn.max([x, 1]) == sympy.Max(x, 1)
    assert fn.log10(x) == sympy.log(x, 10)
    assert fn.atan2(y, x) == sympy.atan2(y, x)
    assert fn.sqrt(2) == sympy.sqrt(2) and fn.sqrt(2).is_Pow   # stays an exact atom
    assert fn.pi is sympy.pi
    with pytest.raises(TypeError, match="keyword"):
        fn.min(x, y, key=str)


@pytest.mark.parametrize("args", [(3, -1, 2), ([4.0, 2.5],), ((7,),)])
def test_min_max_on_numbers_are_the_builtins(args):
    assert fn.min(*args) == builtins.min(*args)
    assert fn.max(*args) == builtins.max(*args)


def test_abs_min_max_take_what_the_builtins_take():
    assert fn.min(v for v in [7, 5, 9]) == 5
    assert fn.min([], default=0) == 0 and fn.max([1, -3], key=builtins.abs) == -3
    assert fn.abs(-2.5) == 2.5 and type(fn.abs(-2)) is int
    assert np.array_equal(fn.abs(np.array([-1.0, 2.0])), [1.0, 2.0])


def test_public_names_and_no_sympy_on_import():
    for name in fn.__all__:
        assert getattr(ac, name) is getattr(fn, name) or name == "pi"
    code = ("import sys, acausal as ac; assert ac.abs(-1) == 1 and ac.max(1, 2) == 2; "
            "print('sympy' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True)
    assert out.stdout.strip() == "False"
