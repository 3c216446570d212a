"""Sources of Integer signals (Modelica.Blocks.Sources, MSL v4.0.0: IntegerConstant,
IntegerStep, IntegerTable)."""
import acausal as ac

from .boolean_interfaces import IntegerSignalSource, IntegerSO
from .conversions import RealToInteger
from .tables import CombiTimeTable

__all__ = ["IntegerConstant", "IntegerStep", "IntegerTable"]


class IntegerConstant(IntegerSO):
    """y = k   (Modelica.Blocks.Sources.IntegerConstant)."""

    k = ac.Parameter(1, type=int, description="constant output value")

    def equations(self):
        return [ac.Eq(self.y, self.k)]


class IntegerStep(IntegerSignalSource):
    """y = offset + (if time < startTime then 0 else height)
    (Modelica.Blocks.Sources.IntegerStep)."""

    height = ac.Parameter(1, type=int, description="height of step")

    def equations(self):
        return [ac.Eq(self.y, self.offset + ac.if_else(ac.time < self.startTime, 0,
                                                       self.height))]


class IntegerTable(IntegerSO):
    """Integer signal from a table of rows (time, y) held constant between its times
    (Modelica.Blocks.Sources.IntegerTable): as the MSL builds it, a constant-segment
    ``CombiTimeTable`` behind a ``RealToInteger``.  The table is fixed when the block is
    made; its values must be whole numbers and its times increasing."""

    table = ac.Parameter(((0.0, 0.0),), structural=True,
                         description="table matrix (first column: time; second column: y)")
    shiftTime = ac.Parameter(0.0, unit="s", description="shift time of first table column")
    realToInteger = RealToInteger()

    def build(self):
        rows = [tuple(float(x) for x in row) for row in self.table]
        if not rows or any(len(r) != 2 for r in rows):
            raise ac.InvalidValue("IntegerTable: table must be rows (time, y)")
        bad = [y for _, y in rows if y != int(y)]
        if bad:
            raise ac.InvalidValue(f"IntegerTable: table value {bad[0]} is not an Integer")
        if any(b[0] <= a[0] for a, b in zip(rows, rows[1:])):
            raise ac.InvalidValue("IntegerTable: the times of table are not strictly "
                                  "increasing")
        self.combiTimeTable = CombiTimeTable(table=rows, columns=[2],
                                             smoothness="constant", extrapolation="hold",
                                             startTime=float("-inf"),
                                             shiftTime=ac.ref("shiftTime"))

    def equations(self):
        return [ac.connect(self.combiTimeTable.y[0], self.realToInteger.u),
                ac.connect(self.realToInteger.y, self.y)]
