"""Boundary conditions (Modelica.Thermal.HeatTransfer.Sources).

A heat-flow source delivers Q_flow into the component it is connected to, so its own
port has port.Q_flow = -Q_flow.
"""
import acausal as ac
from acausal.ports import RealInput

from .interfaces import PartialElementaryOnePort

__all__ = ["FixedTemperature", "PrescribedTemperature", "FixedHeatFlow", "PrescribedHeatFlow"]


class FixedTemperature(PartialElementaryOnePort):
    """Ideal heat sink/source at a fixed temperature:  port.T = T."""

    T = ac.Parameter(293.15, unit="K", description="fixed temperature")

    energy_role = "source"  # an environment outside the model

    def equations(self):
        return [ac.Eq(self.port.T, self.T)]


class PrescribedTemperature(PartialElementaryOnePort):
    """Temperature set by a signal:  port.T = T."""

    T = RealInput()

    energy_role = "source"  # an environment outside the model

    def equations(self):
        return [ac.Eq(self.port.T, self.T)]


class FixedHeatFlow(PartialElementaryOnePort):
    """Fixed heat flow into the connected component:  port.Q_flow = -Q_flow."""

    Q_flow = ac.Parameter(0.0, unit="W", description="heat flow rate delivered")

    energy_role = "source"  # an environment outside the model

    def equations(self):
        return [ac.Eq(self.port.Q_flow, -self.Q_flow)]


class PrescribedHeatFlow(PartialElementaryOnePort):
    """Heat flow set by a signal, into the connected component:  port.Q_flow = -Q_flow."""

    Q_flow = RealInput()

    energy_role = "source"  # an environment outside the model

    def equations(self):
        return [ac.Eq(self.port.Q_flow, -self.Q_flow)]
