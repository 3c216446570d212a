"""Hydraulic sensors: ideal, they take no flow and drop no pressure."""
import acausal as ac
from acausal.ports import FluidPort, RealOutput

from .interfaces import PartialOnePort

__all__ = ["PressureSensor", "RelativePressureSensor", "FlowSensor"]


class PressureSensor(PartialOnePort):
    """p = port.p,  port.q = 0."""

    p = RealOutput()

    energy_role = "lossless"  # an ideal sensor takes no power

    def equations(self):
        return [ac.Eq(self.port.q, 0), ac.Eq(self.p, self.port.p)]


class RelativePressureSensor(ac.Component):
    """p_rel = port_a.p - port_b.p, with no flow through either port."""

    port_a = FluidPort()
    port_b = FluidPort()
    p_rel = RealOutput()

    energy_role = "lossless"  # an ideal sensor takes no power

    def equations(self):
        return [ac.Eq(self.port_a.q, 0), ac.Eq(self.port_b.q, 0),
                ac.Eq(self.p_rel, self.port_a.p - self.port_b.p)]


class FlowSensor(ac.Component):
    """q = port_a.q, the flow from port_a to port_b, in series, without pressure drop."""

    port_a = FluidPort()
    port_b = FluidPort()
    q = RealOutput()

    energy_role = "lossless"  # an ideal sensor takes no power

    def equations(self):
        return [ac.Eq(self.port_a.p, self.port_b.p), ac.Eq(0, self.port_a.q + self.port_b.q),
                ac.Eq(self.q, self.port_a.q)]
