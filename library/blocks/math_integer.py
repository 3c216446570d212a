"""Blocks with Integer signals (Modelica.Blocks.MathInteger, MSL v4.0.0).

The inputs ``u[0] ... u[nu-1]`` (the MSL's ``u[1] ... u[nu]``) are made for the
structural ``nu``; gains and the values of ``MultiSwitch`` are lists fixed when the block
is made.
"""
import acausal as ac
from acausal.ports import BooleanInput, IntegerInput

from .boolean_interfaces import IntegerMISO, IntegerSISO, output_start

__all__ = ["Sum", "Product", "TriggeredAdd", "MultiSwitch"]


class Sum(IntegerMISO):
    """y = k[1] u[1] + k[2] u[2] + ... + k[nu] u[nu]   (MathInteger.Sum)."""

    k = ac.Parameter((), structural=True, description="input gains (default all 1)")

    def build(self):
        super().build()
        self.gains = [int(g) for g in self.k] or [1] * len(self.u)
        if len(self.gains) != len(self.u):
            raise ac.ModelError(f"Sum: k has {len(self.gains)} gains for nu = {len(self.u)}")

    def equations(self):
        return [ac.Eq(self.y, sum((g * u.signal for g, u in zip(self.gains, self.u)), 0))]


class Product(IntegerMISO):
    """y = u[1] u[2] ... u[nu]   (MathInteger.Product; 0 for nu = 0, as the MSL)."""

    def equations(self):
        y = 0
        if self.u:
            y = self.u[0].signal
            for u in self.u[1:]:
                y = y * u.signal
        return [ac.Eq(self.y, y)]


class TriggeredAdd(IntegerSISO):
    """Add u to the output at each rising edge of ``trigger`` (MathInteger.TriggeredAdd):

        when trigger (or a rising reset):  y = if reset then set else pre(y) + u

    ``use_reset`` adds a Boolean ``reset`` input, ``use_set`` an Integer ``set`` input
    (the value taken at a reset; else ``y_start``); pre(y) = y_start at the start.
    """

    use_reset = ac.Parameter(False, structural=True, description="enable the reset port")
    use_set = ac.Parameter(False, structural=True,
                           description="enable the set port, the value at a reset")
    y_start = ac.Parameter(0, structural=True, description="initial and reset value of y")
    trigger = BooleanInput()

    def build(self):
        if self.use_reset:
            self.reset = BooleanInput()
            if self.use_set:
                self.set = IntegerInput()

    def __init__(self, **mods):
        super().__init__(**output_start(mods, "y_start", 0))

    def equations(self):
        added = ac.pre(self.y) + self.u
        if not self.use_reset:
            return [ac.when(self.trigger, ac.assign(self.y, added))]
        value = self.set.signal if self.use_set else int(self.y_start)
        return [ac.when([self.trigger, self.reset],
                        ac.assign(self.y, ac.if_else(self.reset, value, added)))]


class MultiSwitch(IntegerMISO):
    """y = expr[i] for the first i with u[i] true, else pre(y) (``use_pre_as_default``)
    or ``y_default`` (MathInteger.MultiSwitch); pre(y) = y_default at the start."""

    use_pre_as_default = ac.Parameter(True, structural=True,
                                      description="hold the last value if no u[i] is true")
    y_default = ac.Parameter(0, structural=True,
                             description="output if all u[i] are false (and pre(y) at t0)")
    expr = ac.Parameter((), structural=True,
                        description="y = expr[i] if u[i] is the first true input")

    def build(self):
        self.u = [BooleanInput() for _ in range(int(self.nu))]
        self.values = [int(x) for x in self.expr] or [0] * len(self.u)
        if len(self.values) != len(self.u):
            raise ac.ModelError(f"MultiSwitch: expr has {len(self.values)} values for "
                                f"nu = {len(self.u)} inputs")

    def __init__(self, **mods):
        super().__init__(**output_start(mods, "y_default", 0))

    def equations(self):
        y = ac.pre(self.y) if self.use_pre_as_default else int(self.y_default)
        for u, value in reversed(list(zip(self.u, self.values))):
            y = ac.if_else(u, value, y)
        return [ac.Eq(self.y, y)]
