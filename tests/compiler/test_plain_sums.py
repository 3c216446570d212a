"""A residual flattened as a sum of +-symbols is marked plain (FlatEquation.is_plain), and
the passes that look for floor() and delay() skip it -- only while it is still that
residual.  Here a floor() reaches such an equation after flattening, through a
parameter's value, and through a delay() and a floor() written beside plain sums; the
results are the closed forms."""
import numpy as np
import sympy as sp

import acausal as ac
from acausal.compiler.frontend.discrete import freeze_integer_functions
from acausal.compiler.frontend.flatten import flatten
from acausal.compiler.pipeline import compile_model
from acausal.library.electrical import ConstantVoltage, Ground, Resistor


class _FloorThroughParameter(ac.Component):
    """x = b with b = floor(a), a = 2.7: x = 2; y' = x from 0: y(t) = 2 t."""

    a = ac.Parameter(2.7)
    b = ac.Parameter(lambda c: sp.floor(c.a))
    x = ac.Variable()
    y = ac.Variable(start=0.0, fixed=True)

    def equations(self):
        return [ac.Eq(self.x, self.b), ac.Eq(ac.der(self.y), self.x)]


def test_a_floor_in_a_parameter_value_reaches_a_plain_equation():
    flat = flatten(_FloorThroughParameter())
    (eq,) = [eq for eq in flat.equations if eq.text == "x = b"]
    assert eq.terms is not None                  # flattened as the sum x - b, then
    assert not eq.is_plain() and eq.residual.has(sp.floor)   # b's value came in
    assert len(freeze_integer_functions(flat)) == 1                    # so it is walked
    res = ac.simulate(ac.compile(_FloorThroughParameter(), cache=False), t_end=1.5)
    assert res.success
    assert np.allclose(res["x"], 2.0)
    assert abs(res["y"][-1] - 3.0) < 1e-6 * 3.0


class _Stairs(ac.Component):
    """s = t (s' = 1), k = floor(s), w = k (a plain sum), u = delay(s, 0.5):
    w(2.5) = 2 and u(2.5) = 2.0."""

    s = ac.Variable(start=0.0, fixed=True)
    k = ac.Variable()
    w = ac.Variable()
    u = ac.Variable()

    def equations(self):
        return [ac.Eq(ac.der(self.s), 1), ac.Eq(self.k, sp.floor(self.s)),
                ac.Eq(self.w, self.k), ac.Eq(self.u, ac.delay(self.s, 0.5))]


def test_floor_and_delay_beside_plain_sums_take_their_closed_forms():
    flat = flatten(_Stairs())
    plain = {eq.text for eq in flat.equations if eq.is_plain()}
    assert "w = k" in plain and not any("floor" in t or "delay" in t for t in plain)
    res = ac.simulate(ac.compile(_Stairs(), cache=False), t_end=2.5, rtol=1e-8)
    assert res.success
    assert res["w"][-1] == 2.0 and res["k"][-1] == 2.0
    assert abs(res["u"][-1] - 2.0) < 1e-6


class _Divider(ac.Component):
    """A source across two resistors in series: its connections are sums of +-symbols."""

    src = ConstantVoltage(V=3.0)
    R1 = Resistor(R=1.0)
    R2 = Resistor(R=2.0)
    gnd = Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.R1.p), ac.connect(self.R1.n, self.R2.p),
                ac.connect(self.R2.n, self.src.n, self.gnd.p)]


def test_a_plain_sum_is_made_only_when_read_and_then_as_sympy_makes_it():
    c = compile_model(_Divider(), until="alias")
    unmade = {eq.text for eq in c.aliases.removed if eq.unmade is not None}
    # aliases of two variables as flattened, dropped without their residual ever made
    assert {"src.p.v = R1.p.v", "R1.n.v = R2.p.v", "0 = R1.n.i + R1.p.i",
            "R1.n.i + R2.p.i = 0"} <= unmade
    for eq in flatten(_Divider()).equations:
        if eq.terms is not None:
            assert eq.residual == sp.Add(*[k * q for q, k in eq.terms.items()])
            assert eq.is_plain() and eq.unmade is None
    res = ac.simulate(ac.compile(_Divider(), cache=False), t_end=1.0)
    assert abs(res["R2.v"][-1] - 2.0) < 1e-9 and abs(res["R1.i"][-1] - 1.0) < 1e-9
