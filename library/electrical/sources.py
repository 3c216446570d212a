"""Voltage and current sources (Modelica.Electrical.Analog.Sources, MSL v4.0.0).

A source's v (or i) follows the OnePort convention: v = p.v - n.v, and i flows from p
to n *through the source*, so a source delivering power has v i < 0.  The signal
sources (the MSL's ``VoltageSource``/``CurrentSource`` with their ``signalSource``) are
v = offset + signal(time) or i = offset + signal(time), the signal 0 before
``startTime``; their signals are ``blocks.signals`` (every edge an exact time event).
The sources with a variable frequency and amplitude, :class:`SupplyVoltage` and the
signal-driven sources are in :mod:`.variable_sources`.
"""
from acausal._sympy import sympy as sp

import acausal as ac

from ..blocks import signals
from .interfaces import OnePort

__all__ = ["ConstantVoltage", "StepVoltage", "RampVoltage", "SineVoltage", "CosineVoltage",
           "ExpSineVoltage", "PulseVoltage", "TrapezoidVoltage", "ConstantCurrent",
           "StepCurrent", "RampCurrent", "SineCurrent", "CosineCurrent", "ExpSineCurrent",
           "PulseCurrent", "TrapezoidCurrent"]


class ConstantVoltage(OnePort):
    """Ideal source of constant voltage (MSL ConstantVoltage):  v = V."""

    V = ac.Parameter(1.0, unit="V", description="value of constant voltage")

    energy_role = "source"  # delivers -v i

    def equations(self):
        return [ac.Eq(self.v, self.V)]


class ConstantCurrent(OnePort):
    """Ideal source of constant current (MSL ConstantCurrent):  i = I."""

    I = ac.Parameter(1.0, unit="A", description="value of constant current")

    energy_role = "source"  # delivers -v i

    def equations(self):
        return [ac.Eq(self.i, self.I)]


class _VoltageSource(OnePort):
    """v = offset + signal(time), the signal 0 before startTime (MSL
    Interfaces.VoltageSource)."""

    offset = ac.Parameter(0.0, unit="V", description="voltage offset")
    startTime = ac.Parameter(0.0, unit="s", description="time offset")

    energy_role = "source"  # delivers -v i

    def signal(self):
        raise NotImplementedError

    def equations(self):
        return [ac.Eq(self.v, self.offset + self.signal())]


class _CurrentSource(OnePort):
    """i = offset + signal(time), the signal 0 before startTime (MSL
    Interfaces.CurrentSource)."""

    offset = ac.Parameter(0.0, unit="A", description="current offset")
    startTime = ac.Parameter(0.0, unit="s", description="time offset")

    energy_role = "source"  # delivers -v i

    def signal(self):
        raise NotImplementedError

    def equations(self):
        return [ac.Eq(self.i, self.offset + self.signal())]


def _exp_sine(amplitude, f, phase, damping, start):
    tau = ac.time - start
    wave = amplitude * ac.exp(-damping * tau) * sp.sin(2 * sp.pi * f * tau + phase)
    # gated as a whole: exp(-damping tau) before startTime may overflow
    return ac.if_else(tau >= 0, wave, 0)


def _pulse(component, amplitude):
    """The MSL's Pulse: ``width`` in % of ``period``."""
    return signals.pulse(amplitude, component.width / 100, component.period,
                         component.startTime)


def _trapezoid(component, amplitude):
    """The MSL's Trapezoid, for ``nperiod`` periods (endless if negative)."""
    for name in ("rising", "falling", "period"):
        if component.parameter_value(name) == 0:
            # a zero would divide the edge's slope by a structural zero
            raise ac.ModelError(f"{component._describe()}: {name} must be > 0 (a pulse "
                                "source has vertical edges)")
    shape = signals.trapezoid(amplitude, component.rising, component.width,
                              component.falling, component.period, component.startTime)
    if component.nperiod < 0:
        return shape
    end = component.startTime + component.nperiod * component.period
    return ac.if_else(ac.time < end, shape, 0)


class StepVoltage(_VoltageSource):
    """Voltage step (MSL StepVoltage):  v = offset + (V if time >= startTime else 0)."""

    V = ac.Parameter(1.0, unit="V", description="height of step")

    def signal(self):
        return signals.step(self.V, self.startTime)


class StepCurrent(_CurrentSource):
    """Current step (MSL StepCurrent):  i = offset + (I if time >= startTime else 0)."""

    I = ac.Parameter(1.0, unit="A", description="height of step")

    def signal(self):
        return signals.step(self.I, self.startTime)


class RampVoltage(_VoltageSource):
    """Voltage ramp (MSL RampVoltage) from offset to offset + V between startTime and
    startTime + duration."""

    V = ac.Parameter(1.0, unit="V", description="height of ramp")
    duration = ac.Parameter(1.0, unit="s", min=1e-60, description="duration of ramp")

    def signal(self):
        return signals.ramp(self.V, self.duration, self.startTime)


class RampCurrent(_CurrentSource):
    """Current ramp (MSL RampCurrent) from offset to offset + I between startTime and
    startTime + duration."""

    I = ac.Parameter(1.0, unit="A", description="height of ramp")
    duration = ac.Parameter(1.0, unit="s", min=1e-60, description="duration of ramp")

    def signal(self):
        return signals.ramp(self.I, self.duration, self.startTime)


class SineVoltage(_VoltageSource):
    """Sine voltage (MSL SineVoltage):
    v = offset + V sin(2 pi f (time - startTime) + phase) after startTime."""

    V = ac.Parameter(1.0, unit="V", description="amplitude of sine wave")
    phase = ac.Parameter(0.0, unit="rad", description="phase of sine wave")
    f = ac.Parameter(1.0, unit="Hz", description="frequency of sine wave")

    def signal(self):
        return signals.sine(self.V, self.f, self.phase, self.startTime)


class SineCurrent(_CurrentSource):
    """Sine current (MSL SineCurrent):
    i = offset + I sin(2 pi f (time - startTime) + phase) after startTime."""

    I = ac.Parameter(1.0, unit="A", description="amplitude of sine wave")
    phase = ac.Parameter(0.0, unit="rad", description="phase of sine wave")
    f = ac.Parameter(1.0, unit="Hz", description="frequency of sine wave")

    def signal(self):
        return signals.sine(self.I, self.f, self.phase, self.startTime)


class CosineVoltage(_VoltageSource):
    """Cosine voltage (MSL CosineVoltage):
    v = offset + V cos(2 pi f (time - startTime) + phase) after startTime."""

    V = ac.Parameter(1.0, unit="V", description="amplitude of cosine wave")
    phase = ac.Parameter(0.0, unit="rad", description="phase of cosine wave")
    f = ac.Parameter(1.0, unit="Hz", description="frequency of cosine wave")

    def signal(self):
        return signals.sine(self.V, self.f, self.phase + sp.pi / 2, self.startTime)


class CosineCurrent(_CurrentSource):
    """Cosine current (MSL CosineCurrent):
    i = offset + I cos(2 pi f (time - startTime) + phase) after startTime."""

    I = ac.Parameter(1.0, unit="A", description="amplitude of cosine wave")
    phase = ac.Parameter(0.0, unit="rad", description="phase of cosine wave")
    f = ac.Parameter(1.0, unit="Hz", description="frequency of cosine wave")

    def signal(self):
        return signals.sine(self.I, self.f, self.phase + sp.pi / 2, self.startTime)


class ExpSineVoltage(_VoltageSource):
    """Exponentially damped sine voltage (MSL ExpSineVoltage), after startTime:

        v = offset + V exp(-damping (time - startTime)) sin(2 pi f (time - startTime) + phase)
    """

    V = ac.Parameter(1.0, unit="V", description="amplitude of sine wave")
    f = ac.Parameter(1.0, unit="Hz", description="frequency of sine wave")
    phase = ac.Parameter(0.0, unit="rad", description="phase of sine wave")
    damping = ac.Parameter(1.0, unit="1/s", description="damping coefficient of sine wave")

    def signal(self):
        return _exp_sine(self.V, self.f, self.phase, self.damping, self.startTime)


class ExpSineCurrent(_CurrentSource):
    """Exponentially damped sine current (MSL ExpSineCurrent), after startTime:

        i = offset + I exp(-damping (time - startTime)) sin(2 pi f (time - startTime) + phase)
    """

    I = ac.Parameter(1.0, unit="A", description="amplitude of sine wave")
    f = ac.Parameter(1.0, unit="Hz", description="frequency of sine wave")
    phase = ac.Parameter(0.0, unit="rad", description="phase of sine wave")
    damping = ac.Parameter(1.0, unit="1/s", description="damping coefficient of sine wave")

    def signal(self):
        return _exp_sine(self.I, self.f, self.phase, self.damping, self.startTime)


class PulseVoltage(_VoltageSource):
    """Pulse train (MSL PulseVoltage):  v = offset + V during the first ``width`` percent
    of each period after startTime."""

    V = ac.Parameter(1.0, unit="V", description="amplitude of pulse")
    width = ac.Parameter(50.0, min=1e-60, max=100, description="width of pulse in % of period")
    period = ac.Parameter(1.0, unit="s", min=1e-60, description="time for one period")

    def signal(self):
        return _pulse(self, self.V)


class PulseCurrent(_CurrentSource):
    """Pulse train (MSL PulseCurrent):  i = offset + I during the first ``width`` percent
    of each period after startTime."""

    I = ac.Parameter(1.0, unit="A", description="amplitude of pulse")
    width = ac.Parameter(50.0, min=1e-60, max=100, description="width of pulse in % of period")
    period = ac.Parameter(1.0, unit="s", min=1e-60, description="time for one period")

    def signal(self):
        return _pulse(self, self.I)


class TrapezoidVoltage(_VoltageSource):
    """Trapezoidal voltage (MSL TrapezoidVoltage):  v = offset + V times, in every
    ``period`` after startTime, a rise over ``rising``, ``width`` at the top and a fall
    over ``falling``, for ``nperiod`` periods (structural; endless if negative)."""

    V = ac.Parameter(1.0, unit="V", description="amplitude of trapezoid")
    rising = ac.Parameter(0.1, unit="s", min=0, description="rising duration of trapezoid")
    width = ac.Parameter(0.5, unit="s", min=0, description="width duration of trapezoid")
    falling = ac.Parameter(0.1, unit="s", min=0, description="falling duration of trapezoid")
    period = ac.Parameter(1.0, unit="s", min=1e-60, description="time for one period")
    nperiod = ac.Parameter(-1, structural=True,
                           description="number of periods (< 0 means infinite number of periods)")

    def signal(self):
        return _trapezoid(self, self.V)


class TrapezoidCurrent(_CurrentSource):
    """Trapezoidal current (MSL TrapezoidCurrent):  i = offset + I times, in every
    ``period`` after startTime, a rise over ``rising``, ``width`` at the top and a fall
    over ``falling``, for ``nperiod`` periods (structural; endless if negative)."""

    I = ac.Parameter(1.0, unit="A", description="amplitude of trapezoid")
    rising = ac.Parameter(0.1, unit="s", min=0, description="rising duration of trapezoid")
    width = ac.Parameter(0.5, unit="s", min=0, description="width duration of trapezoid")
    falling = ac.Parameter(0.1, unit="s", min=0, description="falling duration of trapezoid")
    period = ac.Parameter(1.0, unit="s", min=1e-60, description="time for one period")
    nperiod = ac.Parameter(-1, structural=True,
                           description="number of periods (< 0 means infinite number of periods)")

    def signal(self):
        return _trapezoid(self, self.I)
