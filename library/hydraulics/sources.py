"""Pressure and flow sources (Modelica.Fluid.Sources, for the incompressible lines of
Egeland & Gravdahl ch. 4).  A flow source delivers its flow into what it is connected
to: ``port.q = -q``."""
import acausal as ac
from acausal.ports import RealInput

from .interfaces import PartialOnePort

__all__ = ["FixedPressure", "PressureSource", "ConstantFlow", "FlowSource"]


class FixedPressure(PartialOnePort):
    """Tank or ideal supply at constant pressure:  port.p = p."""

    p = ac.Parameter(0.0, unit="Pa", description="pressure (0 for a return tank)")

    energy_role = "source"  # a supply or tank outside the model

    def equations(self):
        return [ac.Eq(self.port.p, self.p)]


class PressureSource(PartialOnePort):
    """Pressure set by a signal:  port.p = p_ref."""

    p_ref = RealInput()

    energy_role = "source"  # a supply or tank outside the model

    def equations(self):
        return [ac.Eq(self.port.p, self.p_ref)]


class ConstantFlow(PartialOnePort):
    """Constant flow delivered into the connected circuit:  port.q = -q0."""

    q0 = ac.Parameter(1e-4, unit="m3/s", description="delivered flow")

    energy_role = "source"  # a supply or tank outside the model

    def equations(self):
        return [ac.Eq(self.port.q, -self.q0)]


class FlowSource(PartialOnePort):
    """Flow set by a signal, delivered into the connected circuit:  port.q = -q_ref."""

    q_ref = RealInput()

    energy_role = "source"  # a supply or tank outside the model

    def equations(self):
        return [ac.Eq(self.port.q, -self.q_ref)]
