"""Messages a newcomer meets: correct units of higher derivatives, reprs and errors of
bounded length, "did you mean" for result and parameter names, a structural zero named
as the cause of the error it causes, ``equations()`` that does not return a list,
``linearize`` of an input that is a structural zero, and ``acausal list`` of a domain
whose components live in sub-modules."""
import re

import numpy as np
import pytest

import acausal as ac
from acausal.components.units import per_second, with_derivatives
from acausal.library import electrical as el
from acausal.library import hydraulics as hy
from acausal.library.blocks import Constant
from acausal.library.translational import Fixed, Force, Mass, Spring

from .test_bad_input import RC      # 1 V charging C1 = 10 mF through R1 = 1 Ohm


def test_units_of_higher_derivatives():
    units = with_derivatives({"mass.s": "m", "w": "rad/s", "q": "m3/(s.Pa)", "x": ""},
                             ["der(mass.s)", "der(der(mass.s))", "der(der(der(mass.s)))",
                              "der(w)", "der(der(w))", "der(q)", "der(x)", "der(der(x))"])
    assert units["der(mass.s)"] == "m/s"
    assert units["der(der(mass.s))"] == "m/s2"
    assert units["der(der(der(mass.s)))"] == "m/s3"
    assert units["der(w)"] == "rad/s2" and units["der(der(w))"] == "rad/s3"
    assert units["der(q)"] == "(m3/(s.Pa))/s"
    # no unit declared: none made up (it was "1/s", wrong for any dimensional x)
    assert units["der(x)"] == "" and units["der(der(x))"] == ""
    assert per_second("1") == "1/s" and per_second("1/s") == "1/s2"


def test_did_you_mean_for_result_and_parameter_names():
    res = ac.simulate(RC(), t_end=0.01)
    with pytest.raises(KeyError, match=r"no variable 'C1.vv' in the result \(did you mean "
                                       r"'C1.v'\?\)"):
        res["C1.vv"]
    with pytest.raises(ac.NotInModel, match=r"no tunable parameter 'R1.r' \(did you mean "
                                            r"'R1.R'\?\)"):
        ac.simulate(RC(), t_end=0.01, parameters={"R1.r": 5.0})
    with pytest.raises(ac.NotInModel, match="'C1.v' .*it is a variable, not a parameter"):
        ac.simulate(RC(), t_end=0.01, parameters={"C1.v": 5.0})
    with pytest.raises(ac.NotInModel, match=r"did you mean 'R1.R'"):
        ac.sweep(RC(), {"R1.r": [1.0, 2.0]}, t_end=0.01, n_points=3)


def test_equations_that_are_not_a_list_say_so():
    class Bare(ac.Component):
        x = ac.Variable(start=1.0, fixed=True)

        def equations(self):
            return ac.Eq(ac.der(self.x), -self.x)

    with pytest.raises(ac.InvalidEquation, match=r"Bare\).equations\(\): returned der\(x\) "
                                                 r"= -x \(Equation\), not a list of "
                                                 r"equations: return a list"):
        ac.compile(Bare())


class Tank(ac.Component):
    """A constant inflow into a volume of oil drained by a laminar orifice."""

    src = hy.ConstantFlow()
    vol = hy.Volume(V=0.0, p={"start": 1e5, "fixed": True})
    orf = hy.LaminarOrifice()
    tank = hy.FixedPressure()

    def equations(self):
        return [ac.connect(self.src.port, self.vol.port, self.orf.port_a),
                ac.connect(self.orf.port_b, self.tank.port)]


def test_a_structural_zero_is_named_as_the_cause():
    # V = 0 removes V/beta der(p): no state is left for the fixed start value of p,
    # which the model's equations then contradict (p = 1e7 Pa from the orifice)
    with pytest.raises(ac.InitializationFailed, match=r"over-specified and inconsistent.*"
                       r"vol\.p = 100000\.0.*given 0 are structural zeros.*vol\.V"):
        ac.simulate(Tank(), 1.0)


class Pushed(ac.Component):
    """A mass on a spring pushed by a force Constant(k = 0): m s'' = k - c s."""

    mass = Mass(m=2.0)
    spring = Spring(c=1.0)
    wall = Fixed()
    force = Force()
    k = Constant(k=0.0)

    def equations(self):
        return [ac.connect(self.wall.flange, self.spring.flange_a),
                ac.connect(self.spring.flange_b, self.mass.flange_a),
                ac.connect(self.force.flange, self.mass.flange_b),
                ac.connect(self.k.y, self.force.f)]


def test_linearize_takes_an_input_that_is_a_structural_zero():
    ss = ac.linearize(Pushed(), ["k.k"], ["mass.s"])
    # x = (s, v): s' = v, v' = (k - c s)/m: B = [0, 1/m], and the static gain 1/c
    order = [ss.states.index("mass.s"), ss.states.index("mass.v")]
    assert np.allclose(ss.B.ravel()[order], [0.0, 0.5], atol=1e-9)
    gain = (ss.D - ss.C @ np.linalg.solve(ss.A, ss.B)).item()
    assert abs(gain - 1.0) <= 1e-9
    with pytest.raises(ac.NotInModel, match="structural zero.*pass the Component"):
        ac.linearize(ac.compile(Pushed()), ["k.k"], ["mass.s"])


class FloatingLadder(ac.Component):
    """A 200-section RC ladder driven by a voltage source, without a ground: every
    potential is determined only up to a constant, so the model is under-determined."""

    def __init__(self, n=200, **mods):
        super().__init__(**mods)
        self.src = el.ConstantVoltage(V=1.0)
        self.R = [el.Resistor(R=1.0) for _ in range(n)]
        self.C = [el.Capacitor(C=1e-3) for _ in range(n)]

    def equations(self):
        eqs = [ac.connect(self.src.n, *[c.n for c in self.C])]
        node = self.src.p
        for r, c in zip(self.R, self.C):
            eqs += [ac.connect(node, r.p), ac.connect(r.n, c.p)]
            node = c.p
        return eqs


def test_a_structural_error_of_a_large_model_is_of_bounded_length():
    from acausal.errors import StructuralError
    with pytest.raises(StructuralError) as err:
        ac.compile(FloatingLadder())
    text = str(err.value)
    # the 201 node balances sum to 0 = 0 (one is redundant without a ground)
    assert "linearly dependent" in text and re.search(r"and \d+ more", text)
    assert len(text) < 4000        # every equation listed, and their sum: 41 kB


class UndrivenLadder(ac.Component):
    """A 200-section RC ladder behind a signal voltage whose input nothing drives (not a
    top-level input: the source's own): under-determined."""

    def __init__(self, n=200, **mods):
        super().__init__(**mods)
        self.src = el.SignalVoltage()
        self.gnd = el.Ground()
        self.R = [el.Resistor(R=1.0) for _ in range(n)]
        self.C = [el.Capacitor(C=1e-3) for _ in range(n)]

    def equations(self):
        eqs = [ac.connect(self.src.n, self.gnd.p, *[c.n for c in self.C])]
        node = self.src.p
        for r, c in zip(self.R, self.C):
            eqs += [ac.connect(node, r.p), ac.connect(r.n, c.p)]
            node = c.p
        return eqs


def test_an_under_determined_large_model_names_every_component_first_and_briefly():
    from acausal.compiler.structure.matching import UnderdeterminedModel
    with pytest.raises(UnderdeterminedModel) as err:
        ac.compile(UndrivenLadder())
    text = str(err.value)
    assert "src.i [src (SignalVoltage)]" in text and re.search(r"and \d+ more", text)
    assert text.count("a Ground component is missing") == 1     # a port's hint once
    assert "alpha" not in text      # a 0 that removed no derivative is not a cause
    assert len(text) < 6000         # was 76 kB: every variable and equation listed


def test_event_records_and_energy_audits_print_short():
    from acausal.result import Event
    long = "f = " + " + ".join(f"x{k}" for k in range(400)) + " [friction (Karnopp)]"
    ev = Event(1.5, "relation", [long], [(long, 0.0, 1.0)] * 7)
    text = repr(ev)
    assert len(text) < 700 and "..." in text and "and 3 more" in text
    assert ev.relations == [long]                 # the data keeps the whole text
    res = ac.simulate(RC(), t_end=0.05)
    audit = ac.energy_balance(res, RC())
    printed = repr(audit)
    assert printed.startswith("<EnergyBalance of") and len(printed) < 2000
    assert str(audit) == printed


def test_acausal_list_shows_the_components_of_sub_modules():
    from acausal.library.catalogue import describe_domain
    names = list(describe_domain("friction")["components"])
    for model in ("StribeckFriction", "KarnoppFriction", "DahlFriction", "LuGreFriction",
                  "ElastoPlasticFriction"):
        assert f"translational.{model}" in names and f"rotational.{model}" in names
    assert not any(n.split(".")[-1].startswith("Partial") for n in names)
    # a domain exporting its classes at the top keeps them once, by their short name
    electrical = describe_domain("electrical")["components"]
    assert "Resistor" in electrical and not any(n.endswith(".Resistor") for n in electrical)
