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
    ``semiLinear``, ``acausal.library.fluidheatflow.base_classes.semi_linear``).  The MSL's
    FlowPort_a and FlowPort_b differ only in their icons; both are ``FlowPort`` here.
    p m_flow is not a power: the energy audit does not read these ports.

    H_flow has the nominal 1e3 W, its scale in the error test: H_flow = m_flow h passes
    through 0 at every reversal of the flow, at a rate of h (3e2 J/kg for the MSL's
    default medium, 1.2e6 J/kg for water at 20 degC) times that of m_flow, and held to
    an absolute tolerance of atol W the steps after the reversal would have to be far
    below the resolution of time.
    """

    p = Across(unit="Pa", description="pressure at the port")
    m_flow = Through(unit="kg/s", description="mass flow rate into the port")
    h = Across(unit="J/kg", description="specific enthalpy of the medium at the port")
    H_flow = Through(unit="W", nominal=1e3, description="enthalpy flow rate into the port")
    effort, flow = "p", "m_flow"
    carries_power = False
    hint = ("an Ambient or AbsolutePressure (the pressure level) is missing, or a flow "
            "port is not connected")
