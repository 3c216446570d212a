"""Modelica.Thermal.FluidHeatFlow.Examples.Utilities (MSL v4.0.0): the signal sources
the examples share."""
import acausal as ac
from acausal.library.blocks import Add, Ramp
from acausal.library.blocks.interfaces import SO

__all__ = ["DoubleRamp"]


class DoubleRamp(SO):
    """A ramp going up and down (Utilities.DoubleRamp):  y = ramp1 + ramp2, ramp1 from
    offset by height_1 over duration_1 from startTime, ramp2 by height_2 over duration_2
    from startTime + duration_1 + interval."""

    offset = ac.Parameter(1.0, description="offset of ramps")
    startTime = ac.Parameter(0.2, unit="s", description="start time of 1st ramp")
    interval = ac.Parameter(0.2, unit="s", description="interval between end of 1st and "
                                                       "beginning of 2nd ramp")
    height_1 = ac.Parameter(-1.0, description="height of ramp 1")
    duration_1 = ac.Parameter(0.2, unit="s", min=1e-60, description="duration of ramp 1")
    height_2 = ac.Parameter(1.0, description="height of ramp 2")
    duration_2 = ac.Parameter(0.2, unit="s", min=1e-60, description="duration of ramp 2")
    startTime_2 = ac.Parameter(lambda c: c.startTime + c.duration_1 + c.interval, unit="s",
                               description="start time of 2nd ramp")
    add = Add()
    ramp1 = Ramp(height=ac.ref("height_1"), duration=ac.ref("duration_1"),
                 startTime=ac.ref("startTime"), offset=ac.ref("offset"))
    ramp2 = Ramp(height=ac.ref("height_2"), duration=ac.ref("duration_2"),
                 startTime=ac.ref("startTime_2"), offset=0.0)

    def equations(self):
        return [ac.connect(self.ramp1.y, self.add.u1),
                ac.connect(self.ramp2.y, self.add.u2),
                ac.connect(self.add.y, self.y)]
