"""Two sources imposing one quantity: a 1 V and a 2 V source in parallel on a resistor,
and two speed sources on one mass.  Each is refused as structurally singular; the
message names the equation that is one too many (a source's own equation, left with no
unknown once the connections are resolved) and says that the flows between the two
sources are what is undetermined, rather than pointing at a missing ground."""
import pytest

import acausal as ac
from acausal.compiler.structure.matching import StructuralError
from acausal.library import blocks as bl
from acausal.library import electrical as el
from acausal.library import translational as tr


class ParallelVoltageSources(ac.Component):
    s1 = el.ConstantVoltage(V=1.0)
    s2 = el.ConstantVoltage(V=2.0)
    R = el.Resistor(R=1.0)
    gnd = el.Ground()

    def equations(self):
        return [ac.connect(self.s1.p, self.s2.p, self.R.p),
                ac.connect(self.s1.n, self.s2.n, self.R.n, self.gnd.p)]


class TwoSpeedsOnOneMass(ac.Component):
    a = bl.Constant(k=1.0)
    b = bl.Constant(k=2.0)
    s1 = tr.Speed()
    s2 = tr.Speed()
    m = tr.Mass(m=1.0)

    def equations(self):
        return [ac.connect(self.a.y, self.s1.v_ref), ac.connect(self.b.y, self.s2.v_ref),
                ac.connect(self.s1.flange, self.m.flange_a),
                ac.connect(self.s2.flange, self.m.flange_b)]


def test_parallel_voltage_sources_name_the_equation_with_no_unknown():
    with pytest.raises(StructuralError) as err:
        ac.compile(ParallelVoltageSources(), backend="numpy")
    text = str(err.value)
    assert "s2 (ConstantVoltage)" in text
    assert "they involve no unknown" in text
    assert "(they involve only: )" not in text
    assert "impose the same quantity" in text


def test_two_speed_sources_say_the_forces_are_what_is_left_open():
    with pytest.raises(StructuralError) as err:
        ac.compile(TwoSpeedsOnOneMass(), backend="numpy")
    text = str(err.value)
    assert "s2.v = der(s2.s)" in text or "s1.v = der(s1.s)" in text
    assert "impose the same quantity" in text
