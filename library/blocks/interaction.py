"""Blocks that show a signal's value in a diagram (Modelica.Blocks.Interaction.Show, MSL
v4.0.0): BooleanValue, IntegerValue, RealValue.  Here they pass the value they are given
to an output (``showActive``, ``showNumber``), so that it appears in results under the
block's name."""
import acausal as ac
from acausal.ports import (BooleanInput, BooleanOutput, IntegerInput, IntegerOutput,
                           RealInput, RealOutput)

__all__ = ["BooleanValue", "IntegerValue", "RealValue"]


class BooleanValue(ac.Component):
    """Shows the Boolean ``activePort``:  showActive = activePort."""

    activePort = BooleanInput()
    showActive = BooleanOutput()

    def equations(self):
        return [ac.connect(self.activePort, self.showActive)]


class IntegerValue(ac.Component):
    """Shows the Integer ``numberPort``:  showNumber = numberPort."""

    numberPort = IntegerInput()
    showNumber = IntegerOutput()

    def equations(self):
        return [ac.connect(self.numberPort, self.showNumber)]


class RealValue(ac.Component):
    """Shows the Real ``numberPort``:  showNumber = numberPort."""

    numberPort = RealInput()
    showNumber = RealOutput()
    significantDigits = ac.Parameter(2, type=int, min=1,
                                     description="number of significant digits to be shown")

    def equations(self):
        return [ac.connect(self.numberPort, self.showNumber)]
