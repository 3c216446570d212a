"""Static signal operations (Modelica.Blocks.Math)."""
from acausal._sympy import sympy as sp

import acausal as ac

from acausal.ports import BooleanInput, RealInput, RealOutput

from .interfaces import SI2SO, SISO, SO

__all__ = ["Gain", "Add", "Add3", "Feedback", "Product", "Division", "Abs", "Sqrt", "Min",
           "Max", "InverseBlockConstraints", "MultiSum", "MinMax", "LinearDependency",
           "MultiSwitch", "WrapAngle"]


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


class _RealMISO(SO):
    """``nu`` Real inputs ``u[0] ... u[nu-1]`` (the MSL's u[1..nu]), one output y
    (PartialRealMISO); ``nu`` is given when the block is made."""

    nu = ac.Parameter(0, structural=True, min=0, description="number of input connections")

    def build(self):
        self.u = [RealInput() for _ in range(int(self.nu))]


class MultiSum(_RealMISO):
    """Sum of Reals:  y = k[1] u[1] + k[2] u[2] + ... + k[nu] u[nu]  (MSL
    Blocks.Math.MultiSum; y = 0 without inputs).  The gains ``k`` (default all 1) are
    fixed when the block is made."""

    k = ac.Parameter((), structural=True, description="input gains (default all 1)")

    def build(self):
        super().build()
        self.gains = [float(g) for g in self.k] or [1.0] * len(self.u)
        if len(self.gains) != len(self.u):
            raise ac.InvalidValue(f"MultiSum: k has {len(self.gains)} gains for nu = "
                                  f"{len(self.u)} inputs")

    def equations(self):
        return [ac.Eq(self.y, sum((k * u.signal for k, u in zip(self.gains, self.u)), 0))]


class MinMax(ac.Component):
    """The minimum and the maximum element of the input vector (MSL Blocks.Math.MinMax):

        yMax = max(u),   yMin = min(u)

    (a change of the element that is largest or smallest is an event)."""

    nu = ac.Parameter(0, structural=True, min=0, description="number of input connections")
    yMax = RealOutput()
    yMin = RealOutput()

    def build(self):
        if int(self.nu) < 1:
            raise ac.InvalidValue("MinMax: nu = 0 inputs have no minimum or maximum")
        self.u = [RealInput() for _ in range(int(self.nu))]

    def equations(self):
        largest = smallest = self.u[0].signal
        for u in self.u[1:]:
            largest, smallest = ac.max(largest, u.signal), ac.min(smallest, u.signal)
        return [ac.Eq(self.yMax, largest), ac.Eq(self.yMin, smallest)]


class LinearDependency(SI2SO):
    """A linear combination of the two inputs (MSL Blocks.Math.LinearDependency):

        y = y0 + k1 u1 + k2 u2
    """

    y0 = ac.Parameter(0.0, description="initial value")
    k1 = ac.Parameter(0.0, description="gain of u1")
    k2 = ac.Parameter(0.0, description="gain of u2")

    def equations(self):
        return [ac.Eq(self.y, self.y0 + self.k1 * self.u1 + self.k2 * self.u2)]


class MultiSwitch(SO):
    """The Real expression of the first active Boolean input (MSL Blocks.Math.MultiSwitch):

        y = expr[i] for the first i with u[i] true, else y_default

    ``nu`` and the values ``expr`` (default all 0) are fixed when the block is made (the
    MSL's expr is a time-varying input; its examples give constants)."""

    nu = ac.Parameter(0, structural=True, min=0, description="number of input connections")
    expr = ac.Parameter((), structural=True,
                        description="y = expr[i] if u[i] is the first true input")
    y_default = ac.Parameter(0.0, description="default value of output y if all u[i] = "
                                              "false")

    def build(self):
        self.u = [BooleanInput() for _ in range(int(self.nu))]
        self.values = [float(x) for x in self.expr] or [0.0] * len(self.u)
        if len(self.values) != len(self.u):
            raise ac.InvalidValue(f"MultiSwitch: expr has {len(self.values)} values for "
                                  f"nu = {len(self.u)} inputs")

    def equations(self):
        y = self.y_default
        for u, value in reversed(list(zip(self.u, self.values))):
            y = ac.if_else(u, value, y)
        return [ac.Eq(self.y, y)]


class WrapAngle(SISO):
    """Wrap an angle to the interval ]-pi, pi] or, with ``positiveRange``, [0, 2 pi[ (MSL
    Blocks.Math.WrapAngle, Modelica.Math.wrapAngle):

        y = mod(u, 2 pi),  less 2 pi where that exceeds pi (not positiveRange)

    The wraps are events (``mod`` and the comparison)."""

    positiveRange = ac.Parameter(False, structural=True,
                                 description="use only positive output range, if true")

    def equations(self):
        y = sp.Mod(self.u.signal, 2 * sp.pi)
        if not self.positiveRange:
            y = ac.if_else(y > sp.pi, y - 2 * sp.pi, y)
        return [ac.Eq(self.y, y)]
