"""Pressure and mass flow sources for gas circuits (Modelica.Fluid.Sources).  A flow
source delivers its mass flow into what it is connected to: ``port.m_flow = -m_flow``."""
import acausal as ac
from acausal.ports import RealInput

from .interfaces import PartialOnePort

__all__ = ["FixedPressure", "PressureSource", "ConstantMassFlow", "MassFlowSource"]


class FixedPressure(PartialOnePort):
    """Ambient or an ideal supply at constant pressure:  port.p = p."""

    p = ac.Parameter(1e5, unit="Pa", min=0, description="pressure (absolute)")

    energy_role = "source"  # a reservoir outside the model

    def equations(self):
        return [ac.Eq(self.port.p, self.p)]


class PressureSource(PartialOnePort):
    """Pressure set by a signal:  port.p = p_ref."""

    p_ref = RealInput()

    energy_role = "source"  # a reservoir outside the model

    def equations(self):
        return [ac.Eq(self.port.p, self.p_ref)]


class ConstantMassFlow(PartialOnePort):
    """Constant mass flow delivered into the connected circuit:  port.m_flow = -m_flow."""

    m_flow = ac.Parameter(1e-3, unit="kg/s", description="delivered mass flow")

    energy_role = "source"  # a reservoir outside the model

    def equations(self):
        return [ac.Eq(self.port.m_flow, -self.m_flow)]


class MassFlowSource(PartialOnePort):
    """Mass flow set by a signal, delivered into the circuit:  port.m_flow = -m_flow_ref."""

    m_flow_ref = RealInput()

    energy_role = "source"  # a reservoir outside the model

    def equations(self):
        return [ac.Eq(self.port.m_flow, -self.m_flow_ref)]
