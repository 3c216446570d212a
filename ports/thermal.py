"""Thermal port (Modelica.Thermal.HeatTransfer.Interfaces.HeatPort)."""
from ..components.declarations import Across, Through
from .base import Port

__all__ = ["HeatPort"]


class HeatPort(Port):
    """Heat port: temperature T [K] (across), heat flow rate Q_flow [W] into the port."""

    T = Across(unit="K", nominal=300.0, description="port temperature")
    Q_flow = Through(unit="W", description="heat flow rate into the port")
    effort, flow = "T", "Q_flow"
    hint = "a FixedTemperature is missing, or a heat port is not connected"
