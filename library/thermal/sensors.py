"""Thermal sensors (Modelica.Thermal.HeatTransfer.Sensors)."""
import acausal as ac
from acausal.ports import HeatPort, RealOutput

from .interfaces import PartialElementaryOnePort

__all__ = ["TemperatureSensor", "HeatFlowSensor"]


class TemperatureSensor(PartialElementaryOnePort):
    """T = port.T, with no heat flow into the sensor."""

    T = RealOutput()

    energy_role = "lossless"  # an ideal sensor takes no heat

    def equations(self):
        return [ac.Eq(self.port.Q_flow, 0), ac.Eq(self.T, self.port.T)]


class HeatFlowSensor(ac.Component):
    """Heat flow from port_a to port_b through the sensor (in series, no temperature drop):

        port_a.T = port_b.T,   0 = port_a.Q_flow + port_b.Q_flow,   Q_flow = port_a.Q_flow
    """

    port_a = HeatPort()
    port_b = HeatPort()
    Q_flow = RealOutput()

    energy_role = "lossless"  # an ideal sensor takes no heat

    def equations(self):
        return [ac.Eq(self.port_a.T, self.port_b.T),
                ac.Eq(0, self.port_a.Q_flow + self.port_b.Q_flow),
                ac.Eq(self.Q_flow, self.port_a.Q_flow)]
