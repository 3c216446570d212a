"""Thermal sensors (Modelica.Thermal.HeatTransfer.Sensors, MSL v4.0.0)."""
import acausal as ac
from acausal.ports import HeatPort, RealOutput

from .interfaces import PartialElementaryOnePort

__all__ = ["TemperatureSensor", "RelTemperatureSensor", "HeatFlowSensor"]


class TemperatureSensor(PartialElementaryOnePort):
    """Absolute temperature [K] (Modelica.Thermal.HeatTransfer.Sensors.TemperatureSensor):

        T = port.T,   port.Q_flow = 0
    """

    T = RealOutput()

    energy_role = "lossless"  # an ideal sensor takes no heat

    def equations(self):
        return [ac.Eq(self.port.Q_flow, 0), ac.Eq(self.T, self.port.T)]


class RelTemperatureSensor(ac.Component):
    """Temperature difference [K] (Modelica.Thermal.HeatTransfer.Sensors.
    RelTemperatureSensor):

        T_rel = port_a.T - port_b.T,   port_a.Q_flow = port_b.Q_flow = 0
    """

    port_a = HeatPort()
    port_b = HeatPort()
    T_rel = RealOutput()

    energy_role = "lossless"  # an ideal sensor takes no heat

    def equations(self):
        return [ac.Eq(self.T_rel, self.port_a.T - self.port_b.T),
                ac.Eq(self.port_a.Q_flow, 0), ac.Eq(self.port_b.Q_flow, 0)]


class HeatFlowSensor(ac.Component):
    """Heat flow [W] from port_a to port_b through the sensor, in series, with no
    temperature drop (Modelica.Thermal.HeatTransfer.Sensors.HeatFlowSensor):

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
