"""Voltage and current sources (Modelica.Electrical.Analog.Sources)."""
import sympy as sp

import acausal as ac

from .interfaces import OnePort

__all__ = ["ConstantVoltage", "StepVoltage", "SineVoltage", "ConstantCurrent"]


class ConstantVoltage(OnePort):
    """Ideal source of constant voltage:  v = V."""

    V = ac.Parameter(1.0, unit="V", description="source voltage")

    def equations(self):
        return [*super().equations(), ac.Eq(self.v, self.V)]


class StepVoltage(OnePort):
    """Voltage step:  v = offset + (V if time >= startTime else 0)  (an event at startTime)."""

    V = ac.Parameter(1.0, unit="V", description="height of the step")
    offset = ac.Parameter(0.0, unit="V", description="voltage before the step")
    startTime = ac.Parameter(0.0, unit="s", description="time of the step")

    def equations(self):
        step = ac.if_else(ac.time >= self.startTime, self.V, 0)
        return [*super().equations(), ac.Eq(self.v, self.offset + step)]


class SineVoltage(OnePort):
    """Sine voltage:  v = offset + V sin(2 pi f (time - startTime) + phase)."""

    V = ac.Parameter(1.0, unit="V", description="amplitude")
    f = ac.Parameter(1.0, unit="Hz", description="frequency")
    phase = ac.Parameter(0.0, unit="rad", description="phase")
    offset = ac.Parameter(0.0, unit="V", description="offset")

    def equations(self):
        return [*super().equations(),
                ac.Eq(self.v, self.offset + self.V * sp.sin(2 * sp.pi * self.f * ac.time + self.phase))]


class ConstantCurrent(OnePort):
    """Ideal source of constant current:  i = I."""

    I = ac.Parameter(1.0, unit="A", description="source current")

    def equations(self):
        return [*super().equations(), ac.Eq(self.i, self.I)]
