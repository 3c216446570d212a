"""Electrical pin (Modelica.Electrical.Analog.Interfaces.Pin)."""
from ..components.declarations import Across, Through
from .base import Port

__all__ = ["Pin", "PositivePin", "NegativePin"]


class Pin(Port):
    """Electrical pin: potential v [V] (across), current i [A] into the pin (through)."""

    v = Across(unit="V", description="potential at the pin")
    i = Through(unit="A", description="current flowing into the pin")
    effort, flow = "v", "i"
    hint = "a Ground component is missing, or a pin is not connected"


class PositivePin(Pin):
    """Pin of the positive terminal (same variables as Pin)."""


class NegativePin(Pin):
    """Pin of the negative terminal (same variables as Pin)."""
