"""Partial models of the electrical domain (Modelica.Electrical.Analog.Interfaces)."""
import acausal as ac
from acausal.ports import NegativePin, PositivePin

__all__ = ["OnePort", "TwoPin"]


class TwoPin(ac.Component):
    """Two pins and the voltage between them:  v = p.v - n.v."""

    p = PositivePin()
    n = NegativePin()
    v = ac.Variable(unit="V", description="voltage drop p.v - n.v")

    def equations(self):
        return [ac.Eq(self.v, self.p.v - self.n.v)]


class OnePort(TwoPin):
    """A two-pin element through which one current flows:

        v = p.v - n.v,   0 = p.i + n.i,   i = p.i
    """

    i = ac.Variable(unit="A", description="current from p to n through the element")

    def equations(self):
        return [*super().equations(),
                ac.Eq(0, self.p.i + self.n.i),
                ac.Eq(self.i, self.p.i)]
