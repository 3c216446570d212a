"""Basic electrical components (Modelica.Electrical.Analog.Basic)."""
import acausal as ac
from acausal.ports import Pin

from .interfaces import OnePort

__all__ = ["Ground", "Resistor", "Capacitor", "Inductor"]


class Ground(ac.Component):
    """Reference potential:  p.v = 0."""

    p = Pin()

    def equations(self):
        return [ac.Eq(self.p.v, 0)]


class Resistor(OnePort):
    """Ideal linear resistor, Ohm's law:  v = R i."""

    R = ac.Parameter(1.0, unit="Ohm", min=0, description="resistance")

    def equations(self):
        return [*super().equations(), ac.Eq(self.v, self.R * self.i)]


class Capacitor(OnePort):
    """Ideal capacitor:  C dv/dt = i."""

    C = ac.Parameter(1.0, unit="F", min=0, description="capacitance")
    v = ac.Variable(start=0.0, unit="V", description="voltage drop p.v - n.v")

    def equations(self):
        return [*super().equations(), ac.Eq(self.C * ac.der(self.v), self.i)]


class Inductor(OnePort):
    """Ideal inductor:  L di/dt = v."""

    L = ac.Parameter(1.0, unit="H", min=0, description="inductance")
    i = ac.Variable(start=0.0, unit="A", description="current from p to n")

    def equations(self):
        return [*super().equations(), ac.Eq(self.L * ac.der(self.i), self.v)]
