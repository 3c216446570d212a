"""Static signal operations (Modelica.Blocks.Math)."""
import acausal as ac

from .interfaces import SI2SO, SISO

__all__ = ["Gain", "Add", "Feedback", "Product"]


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


class Feedback(SI2SO):
    """Control error:  y = u1 - u2 (u1 the reference, u2 the feedback)."""

    def equations(self):
        return [ac.Eq(self.y, self.u1 - self.u2)]


class Product(SI2SO):
    """y = u1 u2."""

    def equations(self):
        return [ac.Eq(self.y, self.u1 * self.u2)]
