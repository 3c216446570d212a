"""Static signal operations (Modelica.Blocks.Math)."""
import acausal as ac

from acausal.ports import RealInput, RealOutput

from .interfaces import SI2SO, SISO, SO

__all__ = ["Gain", "Add", "Add3", "Feedback", "Product", "Division", "Abs", "Sqrt", "Min",
           "Max", "InverseBlockConstraints"]


class Gain(SISO):
    """y = k u."""

    k = ac.Parameter(1.0, description="gain")

    def equations(self):
        return [ac.Eq(self.y, self.k * self.u)]


class Add(SI2SO):
    """y = k1 u1 + k2 u2."""

    k1 = ac.Parameter(1.0, description="gain of u1")
    k2 = ac.Parameter(1.0, description="gain of u2")

    def equations(self):
        return [ac.Eq(self.y, self.k1 * self.u1 + self.k2 * self.u2)]


class Add3(SO):
    """y = k1 u1 + k2 u2 + k3 u3  (MSL Blocks.Math.Add3)."""

    k1 = ac.Parameter(1.0, description="gain of u1")
    k2 = ac.Parameter(1.0, description="gain of u2")
    k3 = ac.Parameter(1.0, description="gain of u3")
    u1 = RealInput()
    u2 = RealInput()
    u3 = RealInput()

    def equations(self):
        return [ac.Eq(self.y, self.k1 * self.u1 + self.k2 * self.u2 + self.k3 * self.u3)]


class Feedback(SI2SO):
    """Control error:  y = u1 - u2 (u1 the reference, u2 the feedback)."""

    def equations(self):
        return [ac.Eq(self.y, self.u1 - self.u2)]


class Product(SI2SO):
    """y = u1 u2."""

    def equations(self):
        return [ac.Eq(self.y, self.u1 * self.u2)]


class Division(SI2SO):
    """y = u1 / u2  (MSL Blocks.Math.Division; u2 must not reach 0)."""

    def equations(self):
        return [ac.Eq(self.y, self.u1 / self.u2)]


class Abs(SISO):
    """y = |u|  (its kink at u = 0 is an event)."""

    def equations(self):
        return [ac.Eq(self.y, ac.abs(self.u.signal))]


class Sqrt(SISO):
    """y = sqrt(u)  (u >= 0)."""

    def equations(self):
        return [ac.Eq(self.y, ac.sqrt(self.u.signal))]


class Min(SI2SO):
    """y = min(u1, u2)  (a switch between the inputs is an event)."""

    def equations(self):
        return [ac.Eq(self.y, ac.min(self.u1.signal, self.u2.signal))]


class Max(SI2SO):
    """y = max(u1, u2)  (a switch between the inputs is an event)."""

    def equations(self):
        return [ac.Eq(self.y, ac.max(self.u1.signal, self.u2.signal))]


class InverseBlockConstraints(ac.Component):
    """Makes an inverse model of the block placed between y2 and u2 (MSL
    Blocks.Math.InverseBlockConstraints): its output is forced to the signal at u1, and
    the input it needs comes out at y1:

        u1 = u2,   y1 = y2
    """

    u1 = RealInput()
    u2 = RealInput()
    y1 = RealOutput()
    y2 = RealOutput()

    def equations(self):
        return [ac.Eq(self.u1.signal, self.u2.signal), ac.Eq(self.y1.signal, self.y2.signal)]
