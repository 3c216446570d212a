"""Thermo-fluid port of simple incompressible coolant flows
(Modelica.Thermal.FluidHeatFlow.Interfaces.FlowPort, MSL v4.0.0)."""
from ..components.declarations import Across, Through
from .base import Port

__all__ = ["FlowPort"]


class FlowPort(Port):
    """Flow port: pressure p [Pa] and specific enthalpy h [J/kg] (across), mass flow
    m_flow [kg/s] and enthalpy flow H_flow [W] into the port (through).

    h is the mixing enthalpy of the connection: each component gives the enthalpy it
    receives as m_flow h and the enthalpy it delivers as m_flow times its own (the MSL's
    ``semiLinear``, ``acausal.library.fluidheatflow.interfaces.semi_linear``).  The MSL's
    FlowPort_a and FlowPort_b differ only in their icons; both are ``FlowPort`` here.
    p m_flow is not a power: the energy audit does not read these ports.
    """

    p = Across(unit="Pa", description="pressure at the port")
    m_flow = Through(unit="kg/s", description="mass flow rate into the port")
    h = Across(unit="J/kg", description="specific enthalpy of the medium at the port")
    H_flow = Through(unit="W", description="enthalpy flow rate into the port")
    effort, flow = "p", "m_flow"
    carries_power = False
    hint = ("an Ambient or AbsolutePressure (the pressure level) is missing, or a flow "
            "port is not connected")
