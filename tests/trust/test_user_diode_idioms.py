"""A user's own diode, written with the idioms of numerical Python: ``np.exp`` or
``math.exp`` of the voltage, an ``if`` on it, ``np.where``, ``max``.  Each fails inside
sympy or numpy; the refusal names the component and says what to write instead
(``ac.exp``, ``ac.if_else``, ``ac.max``).  Written in acausal's notation the same diode
runs, and is checked against the rectifier's node equation solved by brentq."""
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

import acausal as ac
from acausal.library import electrical as el
from acausal.library.electrical.interfaces import OnePort
from acausal.errors import ModelError

IS, VT = 1e-9, 0.05


def _diode(law):
    class UserDiode(OnePort):
        """i = Is (exp(v/Vt) - 1) for v > 0, else 0."""

        def equations(self):
            return [ac.Eq(self.i, law(self.v))]
    return UserDiode


def _rectifier(diode):
    class Rectifier(ac.Component):
        src = el.SineVoltage(V=2.0, f=50.0, phase=0.3)
        D = diode()
        R = el.Resistor(R=100.0)
        gnd = el.Ground()

        def equations(self):
            return [ac.connect(self.src.p, self.D.p), ac.connect(self.D.n, self.R.p),
                    ac.connect(self.src.n, self.R.n, self.gnd.p)]
    return Rectifier


@pytest.mark.parametrize("law, advice", [
    (lambda v: IS * (np.exp(v / VT) - 1), "use ac.sin"),
    (lambda v: IS * (math.exp(v / VT) - 1), "use ac.sin"),
    (lambda v: IS * (ac.exp(v / VT) - 1) if v > 0 else 0, "ac.if_else(condition, a, b)"),
    (lambda v: np.where(v > 0, IS * (ac.exp(v / VT) - 1), 0), "ac.if_else"),
    (lambda v: max(IS * (ac.exp(v / VT) - 1), 0), "ac.max"),
], ids=["np.exp", "math.exp", "if", "np.where", "max"])
def test_numerical_python_idioms_are_refused_with_the_notation_to_use(law, advice):
    with pytest.raises(ModelError) as err:
        ac.compile(_rectifier(_diode(law))(), backend="numpy")
    assert "'D' (UserDiode)" in str(err.value)
    assert advice in str(err.value)


def test_the_same_diode_in_acausal_notation_against_the_node_equation():
    law = _diode(lambda v: ac.if_else(v > 0, IS * (ac.exp(v / VT) - 1), 0))
    t = np.linspace(0.0, 0.04, 161)
    res = ac.simulate(_rectifier(law)(), 0.04, t_eval=t, rtol=1e-10, backend="numpy")
    assert res.success

    def current(tt):
        vs = 2.0 * np.sin(2 * np.pi * 50 * tt + 0.3)
        if vs <= 0:
            return 0.0
        vd = brentq(lambda v: IS * np.expm1(v / VT) - (vs - v) / 100.0, 0.0, vs, xtol=1e-15)
        return (vs - vd) / 100.0
    ref = np.array([current(tt) for tt in t])
    assert np.max(np.abs(res["R.i"] - ref)) < 1e-7 * np.max(np.abs(ref))
