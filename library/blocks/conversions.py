"""Conversions between Real, Boolean and Integer signals (Modelica.Blocks.Math, MSL
v4.0.0: BooleanToReal, BooleanToInteger, RealToBoolean, IntegerToBoolean, RealToInteger,
IntegerToReal)."""
import acausal as ac
from acausal.ports import BooleanInput, IntegerInput, IntegerOutput, RealInput, RealOutput

from .boolean_interfaces import BooleanSI, BooleanSO

__all__ = ["BooleanToReal", "BooleanToInteger", "RealToBoolean", "IntegerToBoolean",
           "RealToInteger", "IntegerToReal"]


class BooleanToReal(BooleanSI):
    """y = if u then realTrue else realFalse   (Modelica.Blocks.Math.BooleanToReal)."""

    realTrue = ac.Parameter(1.0, description="output signal for true Boolean input")
    realFalse = ac.Parameter(0.0, description="output signal for false Boolean input")
    y = RealOutput()

    def equations(self):
        return [ac.Eq(self.y, ac.if_else(self.u, self.realTrue, self.realFalse))]


class BooleanToInteger(BooleanSI):
    """y = if u then integerTrue else integerFalse   (Modelica.Blocks.Math.BooleanToInteger)."""

    integerTrue = ac.Parameter(1, type=int, description="output signal for true Boolean input")
    integerFalse = ac.Parameter(0, type=int, description="output signal for false Boolean input")
    y = IntegerOutput()

    def equations(self):
        return [ac.Eq(self.y, ac.if_else(self.u, self.integerTrue, self.integerFalse))]


class RealToBoolean(BooleanSO):
    """y = u >= threshold   (Modelica.Blocks.Math.RealToBoolean)."""

    u = RealInput()
    threshold = ac.Parameter(0.5, description="output y is true, if input u >= threshold")

    def equations(self):
        return [ac.Eq(self.y, self.u >= self.threshold)]


class IntegerToBoolean(BooleanSO):
    """y = u >= threshold   (Modelica.Blocks.Math.IntegerToBoolean)."""

    u = IntegerInput()
    threshold = ac.Parameter(1, type=int, description="output y is true, if input u >= threshold")

    def equations(self):
        return [ac.Eq(self.y, self.u >= self.threshold)]


class RealToInteger(ac.Component):
    """Rounding to the nearest whole number, halves away from zero
    (Modelica.Blocks.Math.RealToInteger):

        y = if u > 0 then integer(floor(u + 0.5)) else integer(ceil(u - 0.5))
    """

    u = RealInput()
    y = IntegerOutput()

    def equations(self):
        return [ac.Eq(self.y, ac.if_else(self.u > 0, ac.integer(self.u + 0.5),
                                         -ac.integer(0.5 - self.u)))]


class IntegerToReal(ac.Component):
    """y = u   (Modelica.Blocks.Math.IntegerToReal)."""

    u = IntegerInput()
    y = RealOutput()

    def equations(self):
        return [ac.Eq(self.y, self.u)]
