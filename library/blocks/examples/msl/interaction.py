"""Modelica.Blocks.Examples.Interaction1 (MSL v4.0.0): Integer, Real and Boolean tables
shown by the Interaction.Show blocks, and two radio buttons that reset each other."""
import acausal as ac
from acausal.library.blocks.boolean_sources import BooleanTable, RadioButtonSource
from acausal.library.blocks.integer_sources import IntegerTable
from acausal.library.blocks.interaction import BooleanValue, IntegerValue, RealValue
from acausal.library.blocks.tables import CombiTimeTable

from . import MSLNames

__all__ = ["Interaction1"]


class Interaction1(ac.Component):
    """integerTable -> integerValue, timeTable -> realValue, booleanTable ->
    booleanValue; radio buttons ``start`` (pressed at 1 and 3 s) and ``stop`` (2 and 4 s),
    each reset by the other's ``on``.  The MSL's ``Sources.TimeTable`` (linear
    interpolation, a repeated row a jump) is a ``CombiTimeTable`` here."""

    msl_name = "Modelica.Blocks.Examples.Interaction1"
    stop_time = 10.0
    tolerance = 1e-6
    msl_signals = MSLNames()

    integerValue = IntegerValue()
    integerTable = IntegerTable(table=((0, 0), (1, 2), (2, 4), (3, 6), (4, 4), (6, 2)))
    timeTable = CombiTimeTable(table=((0, 0), (1, 2.1), (2, 4.2), (3, 6.3), (4, 4.2),
                                      (6, 2.1), (6, 2.1)))
    realValue = RealValue()
    booleanTable = BooleanTable(table=(1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0))
    booleanValue = BooleanValue()
    start = RadioButtonSource(buttonTimeTable=(1.0, 3.0), nReset=1)
    stop = RadioButtonSource(buttonTimeTable=(2.0, 4.0), nReset=1)

    def equations(self):
        return [ac.connect(self.integerTable.y, self.integerValue.numberPort),
                ac.connect(self.timeTable.y[0], self.realValue.numberPort),
                ac.connect(self.booleanTable.y, self.booleanValue.activePort),
                ac.connect(self.stop.on, self.start.reset[0]),
                ac.connect(self.start.on, self.stop.reset[0])]
