"""Voltage and current sources (Modelica.Electrical.Analog.Sources).

A source's v (or i) follows the OnePort convention: v = p.v - n.v, and i flows from p
to n *through the source*, so a source delivering power has v i < 0.
"""
from acausal._sympy import sympy as sp

import acausal as ac
from acausal.ports import RealInput

from ..blocks import signals
from .interfaces import OnePort

__all__ = ["ConstantVoltage", "StepVoltage", "RampVoltage", "SineVoltage", "CosineVoltage",
           "ExpSineVoltage", "PulseVoltage", "TrapezoidVoltage",
           "SignalVoltage", "ConstantCurrent", "StepCurrent", "RampCurrent", "SineCurrent",
           "PulseCurrent", "SignalCurrent"]


class ConstantVoltage(OnePort):
    """Ideal source of constant voltage:  v = V."""

    V = ac.Parameter(1.0, unit="V", description="source voltage")

    energy_role = "source"  # delivers -v i

    def equations(self):
        return [ac.Eq(self.v, self.V)]


class _VoltageSource(OnePort):
    """v = offset + signal(time), the signal starting at startTime."""

    offset = ac.Parameter(0.0, unit="V", description="voltage before startTime")
    startTime = ac.Parameter(0.0, unit="s", description="time the signal starts")

    energy_role = "source"  # delivers -v i

    def signal(self):
        raise NotImplementedError

    def equations(self):
        return [ac.Eq(self.v, self.offset + self.signal())]


class _CurrentSource(OnePort):
    """i = offset + signal(time), the signal starting at startTime."""

    offset = ac.Parameter(0.0, unit="A", description="current before startTime")
    startTime = ac.Parameter(0.0, unit="s", description="time the signal starts")

    energy_role = "source"  # delivers -v i

    def signal(self):
        raise NotImplementedError

    def equations(self):
        return [ac.Eq(self.i, self.offset + self.signal())]


class StepVoltage(_VoltageSource):
    """Voltage step:  v = offset + (V if time >= startTime else 0)  (an event at startTime)."""

    V = ac.Parameter(1.0, unit="V", description="height of the step")

    def signal(self):
        return signals.step(self.V, self.startTime)


class RampVoltage(_VoltageSource):
    """Voltage ramp from offset to offset + V between startTime and startTime + duration."""

    V = ac.Parameter(1.0, unit="V", description="height of the ramp")
    duration = ac.Parameter(1.0, unit="s", min=0, description="duration of the ramp")

    def signal(self):
        return signals.ramp(self.V, self.duration, self.startTime)


class SineVoltage(OnePort):
    """Sine voltage:  v = offset + V sin(2 pi f time + phase)."""

    V = ac.Parameter(1.0, unit="V", description="amplitude")
    f = ac.Parameter(1.0, unit="Hz", description="frequency")
    phase = ac.Parameter(0.0, unit="rad", description="phase")
    offset = ac.Parameter(0.0, unit="V", description="offset")

    energy_role = "source"  # delivers -v i

    def equations(self):
        wave = self.V * sp.sin(2 * sp.pi * self.f * ac.time + self.phase)
        return [ac.Eq(self.v, self.offset + wave)]


class CosineVoltage(OnePort):
    """Cosine voltage (MSL CosineVoltage):  v = offset + V cos(2 pi f time + phase)."""

    V = ac.Parameter(1.0, unit="V", description="amplitude")
    f = ac.Parameter(1.0, unit="Hz", description="frequency")
    phase = ac.Parameter(0.0, unit="rad", description="phase")
    offset = ac.Parameter(0.0, unit="V", description="offset")

    energy_role = "source"  # delivers -v i

    def equations(self):
        wave = self.V * sp.cos(2 * sp.pi * self.f * ac.time + self.phase)
        return [ac.Eq(self.v, self.offset + wave)]


class ExpSineVoltage(_VoltageSource):
    """Exponentially damped sine voltage (MSL ExpSineVoltage), after startTime:

        v = offset + V exp(-damping (time - startTime)) sin(2 pi f (time - startTime) + phase)
    """

    V = ac.Parameter(1.0, unit="V", description="amplitude at startTime")
    f = ac.Parameter(1.0, unit="Hz", description="frequency")
    phase = ac.Parameter(0.0, unit="rad", description="phase at startTime")
    damping = ac.Parameter(1.0, unit="1/s", description="damping coefficient")

    def signal(self):
        tau = ac.time - self.startTime
        wave = (self.V * ac.exp(-self.damping * tau)
                * sp.sin(2 * sp.pi * self.f * tau + self.phase))
        # gated as a whole: exp(-damping tau) before startTime may overflow
        return ac.if_else(tau >= 0, wave, 0)


class PulseVoltage(_VoltageSource):
    """Pulse train:  v = offset + V during the first fraction ``width`` of each period."""

    V = ac.Parameter(1.0, unit="V", description="pulse height")
    width = ac.Parameter(0.5, min=0, max=1, description="fraction of the period that is high")
    period = ac.Parameter(1.0, unit="s", min=0, description="period")

    def signal(self):
        return signals.pulse(self.V, self.width, self.period, self.startTime)


class TrapezoidVoltage(_VoltageSource):
    """Periodic trapezoid voltage (MSL TrapezoidVoltage, endless):  v = offset + V times
    a rise over ``rising``, ``width`` at the top and a fall over ``falling`` in every
    ``period`` after startTime (``blocks.signals.trapezoid``)."""

    V = ac.Parameter(1.0, unit="V", description="height of the trapezoid")
    rising = ac.Parameter(0.1, unit="s", min=0, description="rise time (> 0)")
    width = ac.Parameter(0.5, unit="s", min=0, description="time at the top")
    falling = ac.Parameter(0.1, unit="s", min=0, description="fall time (> 0)")
    period = ac.Parameter(1.0, unit="s", min=0, description="period")

    def signal(self):
        for name in ("rising", "falling", "period"):
            if self.parameter_value(name) == 0:
                # a zero would divide the edge's slope by a structural zero
                raise ac.ModelError(f"{self._describe()}: {name} must be > 0 (a "
                                    "PulseVoltage has vertical edges)")
        return signals.trapezoid(self.V, self.rising, self.width, self.falling,
                                 self.period, self.startTime)


class SignalVoltage(OnePort):
    """Voltage set by a signal:  v = v_ref."""

    v_ref = RealInput()

    energy_role = "source"  # delivers -v i

    def equations(self):
        return [ac.Eq(self.v, self.v_ref)]


class ConstantCurrent(OnePort):
    """Ideal source of constant current:  i = I."""

    I = ac.Parameter(1.0, unit="A", description="source current")

    energy_role = "source"  # delivers -v i

    def equations(self):
        return [ac.Eq(self.i, self.I)]


class StepCurrent(_CurrentSource):
    """Current step:  i = offset + (I if time >= startTime else 0)."""

    I = ac.Parameter(1.0, unit="A", description="height of the step")

    def signal(self):
        return signals.step(self.I, self.startTime)


class RampCurrent(_CurrentSource):
    """Current ramp from offset to offset + I between startTime and startTime + duration."""

    I = ac.Parameter(1.0, unit="A", description="height of the ramp")
    duration = ac.Parameter(1.0, unit="s", min=0, description="duration of the ramp")

    def signal(self):
        return signals.ramp(self.I, self.duration, self.startTime)


class SineCurrent(_CurrentSource):
    """Sine current:  i = offset + I sin(2 pi f (time - startTime) + phase) after startTime."""

    I = ac.Parameter(1.0, unit="A", description="amplitude")
    f = ac.Parameter(1.0, unit="Hz", description="frequency")
    phase = ac.Parameter(0.0, unit="rad", description="phase at startTime")

    def signal(self):
        return signals.sine(self.I, self.f, self.phase, self.startTime)


class PulseCurrent(_CurrentSource):
    """Pulse train:  i = offset + I during the first fraction ``width`` of each period."""

    I = ac.Parameter(1.0, unit="A", description="pulse height")
    width = ac.Parameter(0.5, min=0, max=1, description="fraction of the period that is high")
    period = ac.Parameter(1.0, unit="s", min=0, description="period")

    def signal(self):
        return signals.pulse(self.I, self.width, self.period, self.startTime)


class SignalCurrent(OnePort):
    """Current set by a signal:  i = i_ref (flowing from p to n through the source)."""

    i_ref = RealInput()

    energy_role = "source"  # delivers -v i

    def equations(self):
        return [ac.Eq(self.i, self.i_ref)]
