"""Blocks with a vector of Boolean inputs (Modelica.Blocks.MathBoolean, MSL v4.0.0).

The inputs ``u[0] ... u[nu-1]`` (the MSL's ``u[1] ... u[nu]``) are made for the
structural ``nu``.  The MSL's ``MultiSwitch`` takes ``expr`` as a time-varying input;
here it is a list of constant values fixed when the block is made (the MSL's examples
give constants).
"""
import operator
from functools import reduce

import acausal as ac

from .boolean_interfaces import BooleanMISO, BooleanSISO, output_start
from .logical import _PreOfInput

__all__ = ["And", "Or", "Xor", "Nand", "Nor", "Not", "OnDelay", "RisingEdge",
           "FallingEdge", "ChangingEdge", "MultiSwitch"]


def _all(inputs):
    """u[1] and ... and u[nu] (true for none)."""
    return reduce(operator.and_, inputs) if inputs else True


def _any(inputs):
    """u[1] or ... or u[nu] (false for none)."""
    return reduce(operator.or_, inputs) if inputs else False


def _not(x):
    return (not x) if isinstance(x, bool) else ~x


class And(BooleanMISO):
    """y = u[1] and u[2] and ... and u[nu]   (MathBoolean.And, andTrue(u))."""

    def equations(self):
        return [ac.Eq(self.y, _all(self.u))]


class Or(BooleanMISO):
    """y = u[1] or u[2] or ... or u[nu]   (MathBoolean.Or, anyTrue(u))."""

    def equations(self):
        return [ac.Eq(self.y, _any(self.u))]


class Xor(BooleanMISO):
    """y is true if exactly one element of u is true (MathBoolean.Xor, oneTrue(u))."""

    def equations(self):
        ones = sum(ac.if_else(u, 1, 0) for u in self.u)
        return [ac.Eq(self.y, (ones > 0.5) & (ones < 1.5))]


class Nand(BooleanMISO):
    """y = not (u[1] and ... and u[nu])   (MathBoolean.Nand)."""

    def equations(self):
        return [ac.Eq(self.y, _not(_all(self.u)))]


class Nor(BooleanMISO):
    """y = not (u[1] or ... or u[nu])   (MathBoolean.Nor)."""

    def equations(self):
        return [ac.Eq(self.y, _not(_any(self.u)))]


class Not(BooleanSISO):
    """y = not u   (MathBoolean.Not)."""

    def equations(self):
        return [ac.Eq(self.y, ~self.u)]


class OnDelay(BooleanSISO):
    """Delay a rising edge of u by delayTime, a falling edge not at all
    (MathBoolean.OnDelay):

        when {initial(), u, not u}:  delaySignal = u,
                                     t_next = time + delayTime if u rose, else time - 1
        y = delaySignal and time >= t_next
    """

    delayTime = ac.Parameter(1.0, unit="s", description="delay time")
    delaySignal = ac.Variable(type=bool, description="u, held from its last edge")
    t_next = ac.Variable(discrete=True, start=-1.0, unit="s",
                         description="time when a rising edge reaches the output")

    def equations(self):
        u, t = self.u, ac.time
        rose = u & ~ac.initial()
        return [ac.when([ac.initial(), u, ~u],
                        ac.assign(self.delaySignal, u),
                        ac.assign(self.t_next, ac.if_else(rose, t + self.delayTime, t - 1))),
                ac.Eq(self.y, self.delaySignal & (t >= self.t_next))]


class RisingEdge(_PreOfInput):
    """y = edge(u): u became true   (MathBoolean.RisingEdge)."""

    def equations(self):
        return [ac.Eq(self.y, ac.edge(self.u_))]


class FallingEdge(_PreOfInput):
    """y = edge(not u): u became false   (MathBoolean.FallingEdge)."""

    def equations(self):
        return [ac.Eq(self.y, ~self.u_ & ac.pre(self.u_))]


class ChangingEdge(_PreOfInput):
    """y = change(u): u changed   (MathBoolean.ChangingEdge)."""

    def equations(self):
        return [ac.Eq(self.y, ac.change(self.u_))]


class MultiSwitch(BooleanMISO):
    """y = expr[i] for the first i with u[i] true, else pre(y) (``use_pre_as_default``)
    or ``y_default`` (MathBoolean.MultiSwitch); pre(y) = y_default at the start."""

    use_pre_as_default = ac.Parameter(True, structural=True,
                                      description="hold the last value if no u[i] is true")
    y_default = ac.Parameter(False, structural=True,
                             description="output if all u[i] are false (and pre(y) at t0)")
    expr = ac.Parameter((), structural=True,
                        description="y = expr[i] if u[i] is the first true input")

    def build(self):
        super().build()
        self.values = [bool(x) for x in self.expr] or [False] * len(self.u)
        if len(self.values) != len(self.u):
            raise ac.ModelError(f"MultiSwitch: expr has {len(self.values)} values for "
                                f"nu = {len(self.u)} inputs")

    def __init__(self, **mods):
        super().__init__(**output_start(mods, "y_default", False))

    def equations(self):
        y = ac.pre(self.y) if self.use_pre_as_default else bool(self.y_default)
        for u, value in reversed(list(zip(self.u, self.values))):
            y = ac.if_else(u, value, y)
        return [ac.Eq(self.y, y)]
