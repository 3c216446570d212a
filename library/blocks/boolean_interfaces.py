"""Partial blocks with Boolean and Integer signals (Modelica.Blocks.Interfaces, MSL v4.0.0:
partialBooleanSI, partialBooleanSO, partialBooleanSISO, partialBooleanSI2SO,
partialBooleanSI3SO, partialBooleanSource, partialBooleanThresholdComparison,
partialBooleanComparison, PartialBooleanMISO, IntegerSO, IntegerSignalSource,
PartialIntegerSISO, PartialIntegerMISO).

A Boolean or Integer output is set by one equation with the output alone on the left,
``ac.Eq(self.y, self.u1 & self.u2)``, evaluated at every event (relations in it are
events), or by ``ac.assign`` in a when-clause.  Vector inputs (``u[nu]``) are lists of
ports made in ``build()``, named from 0 as Python indexes them: ``and1.u[0]`` is the
MSL's ``and1.u[1]``.
"""
import acausal as ac
from acausal.ports import BooleanInput, BooleanOutput, IntegerInput, IntegerOutput, RealInput

__all__ = ["output_start", "BooleanSI", "BooleanSO", "BooleanSISO", "BooleanSI2SO", "BooleanSI3SO",
           "BooleanSource", "BooleanThresholdComparison", "BooleanComparison",
           "BooleanMISO", "IntegerSO", "IntegerSignalSource", "IntegerSISO", "IntegerMISO"]


def output_start(mods: dict, given: str, default, port: str = "y") -> dict:
    """``mods`` with the start value (the MSL's ``pre(y)`` at the start) of output
    ``port`` taken from the parameter ``given`` (its default ``default``), unless the
    output is modified itself: ``MultiSwitch(y_default=True)`` starts with pre(y) true."""
    mods.setdefault(port, {"signal": {"start": mods.get(given, default)}})
    return mods


class BooleanSI(ac.Component):
    """One Boolean input u (partialBooleanSI)."""

    u = BooleanInput()


class BooleanSO(ac.Component):
    """One Boolean output y (partialBooleanSO)."""

    y = BooleanOutput()


class BooleanSISO(BooleanSO):
    """Boolean input u, Boolean output y (partialBooleanSISO)."""

    u = BooleanInput()


class BooleanSI2SO(BooleanSO):
    """Boolean inputs u1, u2, Boolean output y (partialBooleanSI2SO)."""

    u1 = BooleanInput()
    u2 = BooleanInput()


class BooleanSI3SO(BooleanSO):
    """Boolean inputs u1, u2, u3, Boolean output y (partialBooleanSI3SO)."""

    u1 = BooleanInput()
    u2 = BooleanInput()
    u3 = BooleanInput()


class BooleanSource(BooleanSO):
    """A source of a Boolean signal (partialBooleanSource)."""


class BooleanThresholdComparison(BooleanSO):
    """Real input u compared with a threshold (partialBooleanThresholdComparison)."""

    u = RealInput()
    threshold = ac.Parameter(0.0, description="comparison with respect to threshold")


class BooleanComparison(BooleanSO):
    """Two Real inputs u1, u2 compared (partialBooleanComparison)."""

    u1 = RealInput()
    u2 = RealInput()


class BooleanMISO(BooleanSO):
    """``nu`` Boolean inputs ``u[0] ... u[nu-1]``, Boolean output y (PartialBooleanMISO);
    ``nu`` is structural (it sets the number of ports)."""

    nu = ac.Parameter(2, structural=True, min=0, description="number of input connections")

    def build(self):
        self.u = [BooleanInput() for _ in range(int(self.nu))]

    def inputs(self) -> list:
        """The inputs' values, in order."""
        return [port.signal for port in self.u]


class IntegerSO(ac.Component):
    """One Integer output y (IntegerSO)."""

    y = IntegerOutput()


class IntegerSignalSource(IntegerSO):
    """An Integer source with offset and startTime (IntegerSignalSource)."""

    offset = ac.Parameter(0, type=int, description="offset of output signal")
    startTime = ac.Parameter(0.0, unit="s", description="output = offset for time < startTime")


class IntegerSISO(IntegerSO):
    """Integer input u, Integer output y (PartialIntegerSISO)."""

    u = IntegerInput()


class IntegerMISO(IntegerSO):
    """``nu`` Integer inputs ``u[0] ... u[nu-1]``, Integer output y (PartialIntegerMISO)."""

    nu = ac.Parameter(2, structural=True, min=0, description="number of input connections")

    def build(self):
        self.u = [IntegerInput() for _ in range(int(self.nu))]

    def inputs(self) -> list:
        """The inputs' values, in order."""
        return [port.signal for port in self.u]
