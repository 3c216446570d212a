"""Hydraulic port (incompressible-line convention of Egeland & Gravdahl ch. 4)."""
from ..components.declarations import Across, Through
from .base import Port

__all__ = ["FluidPort"]


class FluidPort(Port):
    """Hydraulic port: pressure p [Pa] (across), volume flow q [m3/s] into the port."""

    p = Across(unit="Pa", nominal=1e6, description="pressure at the port")
    q = Through(unit="m3/s", nominal=1e-4, description="volume flow into the port")
    effort, flow = "p", "q"
    hint = "a FixedPressure (tank) is missing, or a port is not connected"
