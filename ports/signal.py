"""Causal signal ports (Modelica.Blocks.Interfaces.RealInput / RealOutput)."""
from ..components.declarations import Signal
from .base import SignalPort

__all__ = ["RealInput", "RealOutput"]


class RealInput(SignalPort):
    """Input signal: its value is set by whatever output it is connected to."""

    signal = Signal(description="signal value")
    hint = "an input signal is not connected"


class RealOutput(SignalPort):
    """Output signal: its value is set by the equations of the block that owns it."""

    signal = Signal(description="signal value")
