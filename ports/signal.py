"""Causal signal ports (Modelica.Blocks.Interfaces): Real, Boolean and Integer inputs
and outputs.

A Boolean or Integer signal is discrete: it changes only at events.  Ports of different
value types do not connect (a ``BooleanOutput`` drives ``BooleanInput`` ports only);
``library.blocks.conversions`` converts between them.
"""
from ..components.declarations import Signal
from .base import SignalPort

__all__ = ["RealInput", "RealOutput", "BooleanInput", "BooleanOutput", "IntegerInput",
           "IntegerOutput"]


class RealInput(SignalPort):
    """Input signal: its value is set by whatever output it is connected to."""

    signal = Signal(description="signal value")
    hint = "an input signal is not connected"


class RealOutput(SignalPort):
    """Output signal: its value is set by the equations of the block that owns it."""

    signal = Signal(description="signal value")


class BooleanInput(SignalPort):
    """Boolean input signal (Modelica.Blocks.Interfaces.BooleanInput): set by the
    BooleanOutput it is connected to; a condition in equations (``ac.if_else(self.u,
    ...)``, ``self.u1 & self.u2``)."""

    signal = Signal(type=bool, description="Boolean signal value")
    hint = "a Boolean input signal is not connected"


class BooleanOutput(SignalPort):
    """Boolean output signal (Modelica.Blocks.Interfaces.BooleanOutput): set by an
    equation ``ac.Eq(self.y, condition)`` of the block that owns it, or by a
    when-clause."""

    signal = Signal(type=bool, description="Boolean signal value")


class IntegerInput(SignalPort):
    """Integer input signal (Modelica.Blocks.Interfaces.IntegerInput)."""

    signal = Signal(type=int, description="Integer signal value")
    hint = "an Integer input signal is not connected"


class IntegerOutput(SignalPort):
    """Integer output signal (Modelica.Blocks.Interfaces.IntegerOutput)."""

    signal = Signal(type=int, description="Integer signal value")
