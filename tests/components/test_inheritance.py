"""Equations over the class hierarchy (Modelica's ``extends``): each class's own
equations once, base classes first; super() calls refused; explicit replacement."""
import numpy as np
import pytest

import acausal as ac
from acausal.compiler.frontend.flatten import flatten
from acausal.library.electrical import Capacitor, Ground, OnePort, Resistor, StepVoltage


def _texts(model):
    return [e.text for e in flatten(model).equations if e.kind == "equation"]


class _RC(ac.Component):
    src = StepVoltage(V=1.0)
    R1 = Resistor(R=2.0)
    C1 = Capacitor(C=0.5, v={"start": 0.0, "fixed": True})
    gnd = Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.R1.p), ac.connect(self.R1.n, self.C1.p),
                ac.connect(self.C1.n, self.src.n, self.gnd.p)]


def test_bases_equations_are_included_once_base_first():
    # OnePort: v = p.v - n.v, 0 = p.i + n.i, i = p.i; then Ohm's law
    class Top(ac.Component):
        R1 = Resistor(R=3.0)

    assert _texts(Top()) == ["R1.v = -R1.n.v + R1.p.v", "0 = R1.n.i + R1.p.i",
                             "R1.i = R1.p.i", "R1.v = R1.R*R1.i"]


def test_three_levels_and_a_mixin_follow_the_method_resolution_order():
    class A(ac.Component):
        x = ac.Variable()
        y = ac.Variable()
        z = ac.Variable()

        def equations(self):
            return [ac.Eq(self.x, 1)]

    class Mixin:          # not a component: contributes no equations of its own
        def extra(self):
            return 3

    class B(A):
        def equations(self):
            return [ac.Eq(self.y, 2 * self.x)]

    class C(Mixin, B):
        def equations(self):
            return [ac.Eq(self.z, self.extra() * self.y)]

    class Top(ac.Component):
        c = C()

    assert _texts(Top()) == ["c.x = 1", "c.y = 2*c.x", "c.z = 3*c.y"]


def test_a_subclass_without_equations_keeps_its_bases():
    class Big(_RC):
        R1 = Resistor(R=20.0)

    big, base = flatten(Big()), flatten(_RC())
    assert [e.text for e in big.equations] == [e.text for e in base.equations]
    # three nodes: two of two ports (2 equations each), one of three ports (3)
    assert sum(e.kind == "connect" for e in big.equations) == 7


def test_derived_model_adds_connections_and_simulates_like_the_analytic_rc():
    class Loaded(_RC):
        R2 = Resistor(R=2.0)

        def equations(self):
            return [ac.connect(self.C1.p, self.R2.p), ac.connect(self.R2.n, self.gnd.p)]

    t = np.linspace(0, 2, 21)
    res = ac.simulate(Loaded(), t_end=2.0, t_eval=t, rtol=1e-10, atol=1e-12)
    # Thevenin: v_inf = 1 * R2/(R1+R2) = 0.5, tau = (R1 || R2) C = 1 * 0.5
    exact = 0.5 * (1 - np.exp(-t / 0.5))
    assert np.max(np.abs(res["C1.v"] - exact)) < 1e-7


def test_super_call_is_refused_when_the_class_is_made():
    with pytest.raises(ac.InvalidInheritance, match=r"Bad\.equations calls "
                       r"super\(\)\.equations\(\); the bases' equations are included "
                       r"automatically — remove the call"):
        class Bad(OnePort):
            R = ac.Parameter(1.0, unit="Ohm")

            def equations(self):
                return [*super().equations(), ac.Eq(self.v, self.R * self.i)]


def test_super_call_of_initial_equations_is_refused_too():
    with pytest.raises(ac.InvalidInheritance, match=r"super\(\)\.initial_equations\(\)"):
        class Bad(_RC):
            def initial_equations(self):
                return list(super().initial_equations())


def test_explicit_base_call_is_refused_when_read_never_double_counted():
    class Sneaky(Resistor):
        def equations(self):
            return [*Resistor.equations(self)]

    class Top(ac.Component):
        r = Sneaky()

    with pytest.raises(ac.InvalidInheritance,
                       match=r"Sneaky\.equations calls Resistor\.equations\(self\)"):
        flatten(Top())


def test_replaces_drops_the_named_base_only():
    class Open(Resistor):
        """A resistor replaced by an open circuit: OnePort's equations stay."""

        @ac.replaces(Resistor)
        def equations(self):
            return [ac.Eq(self.i, 0)]

    class Sub(Open):        # and its subclasses keep the replacement
        pass

    class Top(ac.Component):
        r = Sub()

    assert _texts(Top()) == ["r.v = -r.n.v + r.p.v", "0 = r.n.i + r.p.i", "r.i = r.p.i",
                             "r.i = 0"]


def test_replaces_of_a_class_that_is_not_a_base_is_refused():
    with pytest.raises(ac.InvalidInheritance, match="replaces Capacitor, which is not a "
                                                    "base class of Odd"):
        class Odd(Resistor):
            @ac.replaces(Capacitor)
            def equations(self):
                return []


def test_replaces_of_a_base_without_own_equations_is_refused():
    class Plain(Resistor):
        pass

    with pytest.raises(ac.InvalidInheritance, match="Plain, which has no equations"):
        class Odd(Plain):
            @ac.replaces(Plain)
            def equations(self):
                return []


def test_none_from_a_base_names_the_base():
    class Forgot(OnePort):
        def equations(self):
            ac.Eq(self.v, 0)        # no return

    class Child(Forgot):
        def equations(self):
            return [ac.Eq(self.i, 0)]

    class Top(ac.Component):
        c = Child()

    with pytest.raises(ac.InvalidEquation, match=r"'c' \(Child\)\.equations\(\) \(of "
                       r".*Forgot\) returned None"):
        flatten(Top())


def test_library_has_no_super_equation_calls():
    """Every library class was created (the guard ran on each); none reads its base's."""
    import importlib
    import pkgutil

    import acausal.library as lib
    for m in pkgutil.walk_packages(lib.__path__, "acausal.library."):
        importlib.import_module(m.name)
    from acausal.components.inheritance import _calls_super

    def subclasses(c):
        for s in c.__subclasses__():
            yield s
            yield from subclasses(s)

    checked = 0
    for cls in subclasses(ac.Component):
        if cls.__module__.startswith("acausal.library"):
            for name in ("equations", "initial_equations"):
                f = vars(cls).get(name)
                if f is not None:
                    checked += 1
                    assert not _calls_super(f.__wrapped__.__code__, name), cls
    assert checked > 100


def test_a_replacing_method_may_call_the_replaced_one():
    class Shorted(Resistor):
        """Ohm's law kept as written by Resistor, filtered to nothing: v = 0 instead."""

        @ac.replaces(Resistor)
        def equations(self):
            kept = [e for e in Resistor.equations(self) if "R" not in str(e.rhs)]
            return kept + [ac.Eq(self.v, 0)]

    class Top(ac.Component):
        r = Shorted()

    assert _texts(Top()) == ["r.v = -r.n.v + r.p.v", "0 = r.n.i + r.p.i", "r.i = r.p.i",
                             "r.v = 0"]
