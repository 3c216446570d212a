"""Boundary conditions (Modelica.Thermal.HeatTransfer.Sources, MSL v4.0.0).

A heat-flow source delivers Q_flow into the component it is connected to, so its own
port has port.Q_flow = -Q_flow.
"""
import acausal as ac
from acausal.ports import RealInput

from .interfaces import PartialElementaryOnePort

__all__ = ["FixedTemperature", "PrescribedTemperature", "FixedHeatFlow", "PrescribedHeatFlow"]


class FixedTemperature(PartialElementaryOnePort):
    """Ideal heat sink/source at a fixed temperature
    (Modelica.Thermal.HeatTransfer.Sources.FixedTemperature):

        port.T = T
    """

    T = ac.Parameter(293.15, unit="K", min=0, description="fixed temperature at port")

    energy_role = "source"  # an environment outside the model

    def equations(self):
        return [ac.Eq(self.port.T, self.T)]


class PrescribedTemperature(PartialElementaryOnePort):
    """Temperature set by a signal [K]
    (Modelica.Thermal.HeatTransfer.Sources.PrescribedTemperature):

        port.T = T
    """

    T = RealInput()

    energy_role = "source"  # an environment outside the model

    def equations(self):
        return [ac.Eq(self.port.T, self.T)]


class _HeatFlowSource(PartialElementaryOnePort):
    """A heat flow delivered into the connected component, scaled linearly with the
    port's temperature:  port.Q_flow = -Q_flow (1 + alpha (port.T - T_ref))."""

    T_ref = ac.Parameter(293.15, unit="K", min=0, description="reference temperature")
    alpha = ac.Parameter(0.0, unit="1/K",
                         description="temperature coefficient of heat flow rate")

    energy_role = "source"  # an environment outside the model

    def equations(self):
        return [ac.Eq(self.port.Q_flow,
                      -self.Q_flow * (1 + self.alpha * (self.port.T - self.T_ref)))]


class FixedHeatFlow(_HeatFlowSource):
    """Fixed heat flow into the connected component
    (Modelica.Thermal.HeatTransfer.Sources.FixedHeatFlow):

        port.Q_flow = -Q_flow (1 + alpha (port.T - T_ref))
    """

    Q_flow = ac.Parameter(0.0, unit="W", description="fixed heat flow rate at port")


class PrescribedHeatFlow(_HeatFlowSource):
    """Heat flow set by a signal [W], into the connected component
    (Modelica.Thermal.HeatTransfer.Sources.PrescribedHeatFlow):

        port.Q_flow = -Q_flow (1 + alpha (port.T - T_ref))
    """

    Q_flow = RealInput()
