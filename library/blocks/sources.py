"""Signal sources (Modelica.Blocks.Sources)."""
from acausal._sympy import sympy as sp

import acausal as ac

from . import signals
from .interfaces import SO, SignalSource

__all__ = ["Constant", "Step", "Ramp", "Sine", "Cosine", "ExpSine", "Pulse", "Trapezoid"]


class Constant(SO):
    """Constant output:  y = k."""

    k = ac.Parameter(1.0, description="constant output value")

    def equations(self):
        return [ac.Eq(self.y, self.k)]


class Step(SignalSource):
    """Step:  y = offset + (height if time >= startTime else 0)."""

    height = ac.Parameter(1.0, description="height of the step")

    def equations(self):
        return [ac.Eq(self.y, self.offset + signals.step(self.height, self.startTime))]


class Ramp(SignalSource):
    """Ramp from offset to offset + height between startTime and startTime + duration."""

    height = ac.Parameter(1.0, description="height of the ramp")
    duration = ac.Parameter(1.0, unit="s", min=0, description="duration of the ramp")

    def equations(self):
        r = signals.ramp(self.height, self.duration, self.startTime)
        return [ac.Eq(self.y, self.offset + r)]


class Sine(SignalSource):
    """Sine:  y = offset + amplitude sin(2 pi f (time - startTime) + phase) after startTime."""

    amplitude = ac.Parameter(1.0, description="amplitude")
    f = ac.Parameter(1.0, unit="Hz", description="frequency")
    phase = ac.Parameter(0.0, unit="rad", description="phase at startTime")

    def equations(self):
        s = signals.sine(self.amplitude, self.f, self.phase, self.startTime)
        return [ac.Eq(self.y, self.offset + s)]


class Cosine(SignalSource):
    """Cosine:  y = offset + amplitude cos(2 pi f (time - startTime) + phase) after
    startTime (the MSL's Cosine: a Sine with a quarter period more phase)."""

    amplitude = ac.Parameter(1.0, description="amplitude")
    f = ac.Parameter(1.0, unit="Hz", description="frequency")
    phase = ac.Parameter(0.0, unit="rad", description="phase at startTime")

    def equations(self):
        s = signals.sine(self.amplitude, self.f, self.phase + sp.pi / 2, self.startTime)
        return [ac.Eq(self.y, self.offset + s)]


class ExpSine(SignalSource):
    """Exponentially damped sine (MSL ExpSine), after startTime:

        y = offset + amplitude exp(-damping (time - startTime))
                     sin(2 pi f (time - startTime) + phase)
    """

    amplitude = ac.Parameter(1.0, description="amplitude at startTime")
    f = ac.Parameter(1.0, unit="Hz", description="frequency")
    phase = ac.Parameter(0.0, unit="rad", description="phase at startTime")
    damping = ac.Parameter(1.0, unit="1/s", description="damping coefficient")

    def equations(self):
        tau = ac.time - self.startTime
        wave = (self.amplitude * ac.exp(-self.damping * tau)
                * ac.sin(2 * sp.pi * self.f * tau + self.phase))
        # gated as a whole: exp(-damping tau) before startTime may overflow
        return [ac.Eq(self.y, self.offset + ac.if_else(tau >= 0, wave, 0))]


class Pulse(SignalSource):
    """Rectangular pulse train:  y = offset + amplitude during the first fraction
    ``width`` of each ``period`` after startTime, y = offset otherwise.

    The edges are zero crossings; simulate with ``max_step`` below the pulse width, or
    a long step can jump over a whole pulse.
    """

    amplitude = ac.Parameter(1.0, description="pulse height")
    width = ac.Parameter(0.5, min=0, max=1, description="fraction of the period that is high")
    period = ac.Parameter(1.0, unit="s", min=0, description="period")

    def equations(self):
        p = signals.pulse(self.amplitude, self.width, self.period, self.startTime)
        return [ac.Eq(self.y, self.offset + p)]


class Trapezoid(SignalSource):
    """Periodic trapezoid (MSL Blocks.Sources.Trapezoid, endless):  y = offset +
    amplitude times a rise over ``rising``, ``width`` at the top and a fall over
    ``falling`` in every ``period`` after startTime (see ``signals.trapezoid``)."""

    amplitude = ac.Parameter(1.0, description="height of the trapezoid")
    rising = ac.Parameter(0.1, unit="s", min=0, description="rise time (> 0)")
    width = ac.Parameter(0.5, unit="s", min=0, description="time at the top")
    falling = ac.Parameter(0.1, unit="s", min=0, description="fall time (> 0)")
    period = ac.Parameter(1.0, unit="s", min=0, description="period")

    def equations(self):
        for name in ("rising", "falling", "period"):
            if self.parameter_value(name) == 0:
                # a zero would divide the edge's slope by a structural zero
                raise ac.ModelError(f"{self._describe()}: {name} must be > 0 (a Pulse "
                                    "has vertical edges)")
        y = signals.trapezoid(self.amplitude, self.rising, self.width, self.falling,
                              self.period, self.startTime)
        return [ac.Eq(self.y, self.offset + y)]
