"""Modelica.Blocks.Examples.BusUsage (MSL v4.0.0), with its BusUsage_Utilities: a Real, an
Integer and a Boolean signal put on a control bus, a part that puts two signals on its
sub-control bus, connected to the control bus's sub-bus, and a gain that reads a signal
off the bus.

The buses are expandable connectors (``ac.ExpandableConnector``, Modelica 3.5 section
9.1.3): what their classes declare are potential signals; ``controlBus.realSignal2`` is
declared and connected to nothing, so it is not in the model.
"""
import acausal as ac
from acausal.library.blocks import (BooleanExpression, BooleanStep, Gain, IntegerStep,
                                    RealExpression, Sine)

__all__ = ["SubControlBus", "ControlBus", "Part", "BusUsage"]


class SubControlBus(ac.ExpandableConnector):
    """Sub-control bus that is adapted to the signals connected to it
    (BusUsage_Utilities.Interfaces.SubControlBus)."""

    myRealSignal = ac.Variable()
    myBooleanSignal = ac.Variable(type=bool)


class ControlBus(ac.ExpandableConnector):
    """Control bus that is adapted to the signals connected to it
    (BusUsage_Utilities.Interfaces.ControlBus)."""

    realSignal1 = ac.Variable(unit="rad/s", description="first Real signal (angular "
                                                        "velocity)")
    realSignal2 = ac.Variable(unit="m/s", description="second Real signal")
    integerSignal = ac.Variable(type=int, description="Integer signal")
    booleanSignal = ac.Variable(type=bool, description="Boolean signal")
    subControlBus = SubControlBus()


class Part(ac.Component):
    """Component with sub-control bus (BusUsage_Utilities.Part): time and time >= 0.5 on
    the bus."""

    subControlBus = SubControlBus()
    realExpression = RealExpression()
    booleanExpression = BooleanExpression()

    def equations(self):
        return [ac.Eq(self.realExpression.y, ac.time),
                ac.Eq(self.booleanExpression.y, ac.time >= 0.5),
                ac.connect(self.realExpression.y, self.subControlBus.myRealSignal),
                ac.connect(self.booleanExpression.y, self.subControlBus.myBooleanSignal)]


class BusUsage(ac.Component):
    """Demonstrates the usage of a signal bus."""

    msl_name = "Modelica.Blocks.Examples.BusUsage"
    stop_time = 2.0
    tolerance = 1e-6

    integerStep = IntegerStep(height=1, offset=2, startTime=0.5)
    booleanStep = BooleanStep(startTime=0.5)
    sine = Sine(f=1.0)
    part = Part()
    gain = Gain(k=1.0)
    controlBus = ControlBus()

    def equations(self):
        return [ac.connect(self.sine.y, self.controlBus.realSignal1),
                ac.connect(self.booleanStep.y, self.controlBus.booleanSignal),
                ac.connect(self.integerStep.y, self.controlBus.integerSignal),
                ac.connect(self.part.subControlBus, self.controlBus.subControlBus),
                ac.connect(self.gain.u, self.controlBus.realSignal1)]


if __name__ == "__main__":
    res = ac.simulate(BusUsage(), t_end=BusUsage.stop_time, rtol=BusUsage.tolerance)
    print(f"controlBus.subControlBus.myRealSignal at {res.t[-1]:g} s: "
          f"{res['controlBus.subControlBus.myRealSignal'][-1]:g}")
