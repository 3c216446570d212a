"""Equations that say what they are (labels in the report and in errors, never cut),
derived parameters with their values, signals read by their port's name, and
structural parameters declared instead of written into an __init__."""
import inspect
import re

import numpy as np
import pytest

import acausal as ac
from acausal.compiler.frontend.flatten import flatten
from acausal.library import blocks as bl
from acausal.library import rotational as rot


class Pendulum(ac.Component):
    """The planar pendulum in Cartesian coordinates (index 3); the constraint labelled."""

    m = ac.Parameter(1.0, unit="kg")
    L = ac.Parameter(1.0, unit="m")
    g = ac.Parameter(9.81, unit="m/s2")
    x = ac.Variable(start=1.0, unit="m")
    y = ac.Variable(start=0.0, unit="m")
    vx = ac.Variable(start=0.0, unit="m/s")
    vy = ac.Variable(start=0.0, unit="m/s")
    lam = ac.Variable(unit="N/m")

    def equations(self):
        return [ac.Eq(ac.der(self.x), self.vx), ac.Eq(ac.der(self.y), self.vy),
                ac.Eq(self.m * ac.der(self.vx), -self.lam * self.x),
                ac.Eq(self.m * ac.der(self.vy), -self.lam * self.y - self.m * self.g),
                ac.Eq(self.x**2 + self.y**2, self.L**2,
                      label="rod length constraint")]


def test_label_is_shown_whole_in_the_report():
    compiled = ac.compile(Pendulum(), check_units="error", cache=False)
    labelled = [e for e in compiled.report.equations if e["label"]]
    assert labelled and all(e["label"] == "rod length constraint" for e in labelled)
    text = str(compiled.report)
    # the constraint was differentiated twice (index 3), named with its label
    assert re.search(r'2x\s+x\*\*2 \+ y\*\*2 = L\*\*2\s+\[\(model\) \(Pendulum\), "rod length\s+'
                     r'constraint"\]', text)


def test_the_report_wraps_a_long_equation_and_keeps_every_character():
    class Long(Pendulum):
        def equations(self):
            terms = sum(self.x ** k / self.L ** (k - 1) for k in range(2, 30))
            return [ac.Eq(self.vx, ac.der(terms) / 1000, label="a long one")]

    class Top(ac.Component):
        p = Long()

    from acausal.compiler.report import WIDTH, _wrapped
    text = flatten(Top()).equations[-1].text
    lines = _wrapped("    2x  ", text)
    assert len(lines) > 2 and max(map(len, lines)) <= WIDTH
    assert "".join(line.strip() for line in lines).replace(" ", "") == \
        ("2x" + text).replace(" ", "")


def test_a_labelled_equation_is_named_by_its_label_in_errors():
    class Broken(ac.Component):
        x = ac.Variable()
        R = ac.Parameter(float("inf"))

        def equations(self):
            return [ac.Eq(self.x, self.R * 2, label="load line")]

    with pytest.raises(ac.InvalidValue, match='in \\(model\\) \\(Broken\\), "load line"'):
        flatten(Broken())


class Tank(ac.Component):
    """A tank of cross-section A = pi d^2/4 draining at q = k h (Torricelli linearized)."""

    d = ac.Parameter(0.5, unit="m", description="diameter")
    A = ac.Parameter(lambda c: np.pi * c.d**2 / 4, unit="m2", description="cross-section")
    k = ac.Parameter(0.02, unit="m2/s")
    h = ac.Variable(start=1.0, fixed=True, unit="m")

    def equations(self):
        return [ac.Eq(self.A * ac.der(self.h), -self.k * self.h)]


class TwoTanks(ac.Component):
    d = ac.Parameter(0.5, unit="m")
    left = Tank(d=ac.ref("d"))
    right = Tank()


def test_derived_parameters_are_listed_with_their_values():
    compiled = ac.compile(TwoTanks(d=0.4), check_units="error", cache=False)
    derived = compiled.derived_parameters
    assert derived["left.A"] == pytest.approx(np.pi * 0.4**2 / 4, rel=1e-14)
    assert derived["right.A"] == pytest.approx(np.pi * 0.5**2 / 4, rel=1e-14)
    assert derived["left.d"] == pytest.approx(0.4, rel=1e-14)     # bound by ref
    assert "left.A" not in compiled.param_names                    # not tunable itself
    text = str(compiled.report)
    assert "derived parameters (bound to other parameters):" in text
    assert re.search(r"left\.A = 0\.785398\d*\*left\.d\*\*2 = "
                     + re.escape(f"{np.pi * 0.4**2 / 4:.6g}"), text)
    # and the level falls as exp(-k t / A), A the derived value
    res = ac.simulate(compiled, t_end=5.0, t_eval=np.linspace(0, 5, 11), rtol=1e-10,
                      atol=1e-12)
    exact = np.exp(-0.02 * res.t / derived["left.A"])
    assert np.max(np.abs(res["left.h"] - exact)) < 1e-7


def test_signals_are_read_by_the_port_name_and_the_old_name():
    class Loop(ac.Component):
        src = bl.Step(height=2.0, startTime=0.0)
        lag = bl.FirstOrder(k=1.0, T=0.5) if hasattr(bl, "FirstOrder") else \
            bl.TransferFunction(b=[1.0], a=[0.5, 1.0])

        def equations(self):
            return [ac.connect(self.src.y, self.lag.u)]

    res = ac.simulate(Loop(), t_end=2.0, t_eval=np.linspace(0, 2, 21), rtol=1e-10,
                      atol=1e-12)
    assert "lag.y" in res and "lag.y.signal" in res
    assert np.array_equal(res["lag.y"], res["lag.y.signal"])
    assert np.max(np.abs(res["lag.y"] - 2 * (1 - np.exp(-res.t / 0.5)))) < 1e-7


def test_structural_parameters_need_no_init():
    assert "__init__" not in vars(bl.TransferFunction)
    tf = bl.TransferFunction(b=[2.0], a=np.array([1.0, 3.0, 2.0]))   # 2/((s+1)(s+2))
    assert tf.a == [1.0, 3.0, 2.0] and len(tf.state) == 2
    sig = inspect.signature(bl.TransferFunction)
    assert repr(sig.parameters["a"].annotation) == "structural"
    assert "a : structural" in bl.TransferFunction.__doc__
    with pytest.raises(ac.InvalidValue, match="TransferFunction: structural parameter a "
                                              "= 'x' is not a real number"):
        bl.TransferFunction(a=["x", 1.0])
    with pytest.raises(ac.InvalidValue, match="TransferFunction.a is a structural "
                                              "parameter"):
        tf.a = [1.0]

    class Holder(ac.Component):
        tf = bl.TransferFunction(b=[1.0], a=[1.0, 1.0])

    with pytest.raises(ac.InvalidValue, match="'a' is a structural parameter, fixed "
                                              "when the component is made"):
        Holder(tf={"a": [1.0, 2.0]})


def test_a_structural_parameter_with_build_in_a_user_component():
    """A chain of n first-order lags, n structural: the step response of 1/(s+1)^n at
    t is the Erlang distribution function 1 - exp(-t) sum_{k<n} t^k/k!."""
    class Lag(ac.Component):
        x = ac.Variable(start=0.0, fixed=True)
        u = ac.Variable()

        def equations(self):
            return [ac.Eq(ac.der(self.x), self.u - self.x)]

    class Chain(ac.Component):
        n = ac.Parameter(3, structural=True, min=1, description="number of lags")

        def build(self):
            self.lags = [Lag() for _ in range(self.n)]

        def equations(self):
            eqs = [ac.Eq(self.lags[0].u, 1.0)]
            eqs += [ac.Eq(b.u, a.x) for a, b in zip(self.lags, self.lags[1:])]
            return eqs

    res = ac.simulate(Chain(n=4), t_end=3.0, t_eval=np.linspace(0, 3, 7), rtol=1e-10,
                      atol=1e-12)
    t = res.t
    erlang = 1 - np.exp(-t) * (1 + t + t**2 / 2 + t**3 / 6)
    assert np.max(np.abs(res["lags[3].x"] - erlang)) < 1e-7
    with pytest.raises(ac.InvalidValue, match="structural parameter n = 0 is below its "
                                              "minimum 1"):
        Chain(n=0)
