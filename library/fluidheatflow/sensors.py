"""Sensors of a coolant circuit (Modelica.Thermal.FluidHeatFlow.Sensors, MSL v4.0.0):
absolute sensors take no medium and no enthalpy; flow sensors are two-ports in series
without pressure drop, heat exchange or mass."""
import acausal as ac
from acausal.ports import FlowPort, RealOutput

from .base_classes import TwoPort, WithMedium

__all__ = ["PressureSensor", "TemperatureSensor", "RelPressureSensor",
           "RelTemperatureSensor", "MassFlowSensor", "VolumeFlowSensor",
           "EnthalpyFlowSensor"]


class AbsoluteSensor(WithMedium):
    """One port that takes nothing (Interfaces.AbsoluteSensor):
    flowPort.m_flow = 0, flowPort.H_flow = 0."""

    flowPort = FlowPort()
    y = RealOutput()

    def equations(self):
        return [ac.Eq(self.flowPort.m_flow, 0), ac.Eq(self.flowPort.H_flow, 0)]


class RelativeSensor(WithMedium):
    """Two ports that take nothing (Interfaces.RelativeSensor):
    flowPort_x.m_flow = 0, flowPort_x.H_flow = 0."""

    flowPort_a = FlowPort()
    flowPort_b = FlowPort()
    y = RealOutput()

    def equations(self):
        a, b = self.flowPort_a, self.flowPort_b
        return [ac.Eq(a.m_flow, 0), ac.Eq(b.m_flow, 0),
                ac.Eq(a.H_flow, 0), ac.Eq(b.H_flow, 0)]


class FlowSensor(TwoPort):
    """A two-port without mass, pressure drop or heat exchange (Interfaces.FlowSensor):
    dp = 0, Q_flow = 0 (m = 0, tapT = 1)."""

    m = ac.Parameter(0.0, unit="kg", min=0, max=0, description="no medium is stored")
    tapT = ac.Parameter(1.0, unit="1", min=1, max=1, description="the outlet temperature "
                                                                 "exchanges heat")
    y = RealOutput()

    def equations(self):
        return [ac.Eq(self.dp, 0), ac.Eq(self.Q_flow, 0)]


class PressureSensor(AbsoluteSensor):
    """Absolute pressure [Pa] (Sensors.PressureSensor):  y = flowPort.p."""

    def equations(self):
        return [ac.Eq(self.y, self.flowPort.p)]


class TemperatureSensor(AbsoluteSensor):
    """Absolute temperature [K] (Sensors.TemperatureSensor):  cp y = flowPort.h."""

    def equations(self):
        return [ac.Eq(self.medium.cp * self.y, self.flowPort.h)]


class RelPressureSensor(RelativeSensor):
    """Pressure difference [Pa] (Sensors.RelPressureSensor):
    y = flowPort_a.p - flowPort_b.p."""

    def equations(self):
        return [ac.Eq(self.y, self.flowPort_a.p - self.flowPort_b.p)]


class RelTemperatureSensor(RelativeSensor):
    """Temperature difference [K] (Sensors.RelTemperatureSensor):
    cp y = flowPort_a.h - flowPort_b.h."""

    def equations(self):
        return [ac.Eq(self.medium.cp * self.y, self.flowPort_a.h - self.flowPort_b.h)]


class MassFlowSensor(FlowSensor):
    """Mass flow [kg/s] from a to b (Sensors.MassFlowSensor):  y = V_flow rho."""

    def equations(self):
        return [ac.Eq(self.y, self.V_flow * self.medium.rho)]


class VolumeFlowSensor(FlowSensor):
    """Volume flow [m3/s] from a to b (Sensors.VolumeFlowSensor):  y = V_flow."""

    def equations(self):
        return [ac.Eq(self.y, self.V_flow)]


class EnthalpyFlowSensor(FlowSensor):
    """Enthalpy flow [W] into flowPort_a (Sensors.EnthalpyFlowSensor):
    y = flowPort_a.H_flow."""

    def equations(self):
        return [ac.Eq(self.y, self.flowPort_a.H_flow)]
