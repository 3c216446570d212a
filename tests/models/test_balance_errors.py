"""Unbalanced models: the error names the components and variables involved."""
import pytest

import acausal as ac
from acausal.compiler.structure.matching import OverdeterminedModel, UnderdeterminedModel
from acausal.library.electrical import Capacitor, ConstantVoltage, Ground, Resistor


class OneTooMany(ac.Component):
    """A resistor whose current is also forced by an extra equation."""

    src = ConstantVoltage(V=1.0)
    R1 = Resistor(R=1.0)
    gnd = Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.R1.p), ac.connect(self.R1.n, self.src.n, self.gnd.p),
                ac.Eq(self.R1.i, 2.0)]


class Undetermined(ac.Component):
    """A variable that no equation determines."""

    R1 = Resistor(R=1.0)
    gnd = Ground()
    extra = ac.Variable(unit="V")

    def equations(self):
        return [ac.connect(self.R1.p, self.R1.n, self.gnd.p)]


def test_one_equation_too_many_names_the_equations():
    with pytest.raises(OverdeterminedModel) as err:
        ac.compile(OneTooMany())
    msg = str(err.value)
    assert "R1.i" in msg and "over-determined" in msg
    assert "R1 (Resistor)" in msg or "src (ConstantVoltage)" in msg


def test_variable_never_determined_is_named():
    with pytest.raises(UnderdeterminedModel) as err:
        ac.compile(Undetermined())
    msg = str(err.value)
    assert "extra" in msg and "under-determined" in msg
