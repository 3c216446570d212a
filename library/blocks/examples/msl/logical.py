"""Modelica.Blocks.Examples.ShowLogicalSources and LogicalNetwork1 (MSL v4.0.0): the
Boolean sources, and a network of logical blocks with a Pre in a loop."""
import acausal as ac
from acausal.library.blocks.boolean_sources import (BooleanConstant, BooleanExpression,
                                                    BooleanPulse, BooleanStep, BooleanTable,
                                                    SampleTrigger)
from acausal.library.blocks.logical import And, Not, Or, Pre

__all__ = ["ShowLogicalSources", "LogicalNetwork1"]


class ShowLogicalSources(ac.Component):
    """The Boolean sources side by side; booleanExpression.y = pulse.y and step.y."""

    msl_name = "Modelica.Blocks.Examples.ShowLogicalSources"
    stop_time = 10.0
    tolerance = 1e-6

    table = BooleanTable(table=(2.0, 4.0, 6.0, 8.0))
    const = BooleanConstant()
    step = BooleanStep(startTime=4.0)
    pulse = BooleanPulse(period=1.5)
    sample = SampleTrigger(period=0.5)
    booleanExpression = BooleanExpression()

    def equations(self):
        return [ac.Eq(self.booleanExpression.y, self.pulse.y & self.step.y)]


class LogicalNetwork1(ac.Component):
    """table2 -> Not1 -> And1 -> Or1 -> Pre1 -> And1 (a loop broken by Pre1), table1 -> Or1."""

    msl_name = "Modelica.Blocks.Examples.LogicalNetwork1"
    stop_time = 10.0
    tolerance = 1e-6

    table2 = BooleanTable(table=(1.0, 3.0, 5.0, 7.0))
    table1 = BooleanTable(table=(2.0, 4.0, 6.0, 8.0))
    Not1 = Not()
    And1 = And()
    Or1 = Or()
    Pre1 = Pre()

    def equations(self):
        return [ac.connect(self.table2.y, self.Not1.u),
                ac.connect(self.And1.y, self.Or1.u2),
                ac.connect(self.table1.y, self.Or1.u1),
                ac.connect(self.Not1.y, self.And1.u1),
                ac.connect(self.Pre1.y, self.And1.u2),
                ac.connect(self.Or1.y, self.Pre1.u)]
