"""Gas ports: the dimensional one of pneumatics (Modelica.Fluid's p and m_flow) and the
normalized one of the Moore-Greitzer compression system (Egeland & Gravdahl 14.1.2)."""
from ..components.declarations import Across, Through
from .base import Port

__all__ = ["GasPort", "NormalizedGasPort"]


class GasPort(Port):
    """Gas port: pressure p [Pa] (across), mass flow m_flow [kg/s] into the port.

    Mass, not volume, is what is conserved at a node of a compressible gas, so the
    through variable is the mass flow (as in Modelica.Fluid).  p m_flow is not a power
    (the power is p m_flow / rho): the energy audit does not read these ports.
    """

    p = Across(unit="Pa", nominal=1e5, description="pressure at the port")
    m_flow = Through(unit="kg/s", nominal=1e-2, description="mass flow into the port")
    effort, flow = "p", "m_flow"
    carries_power = False
    hint = "a FixedPressure (ambient or supply) is missing, or a port is not connected"


class NormalizedGasPort(Port):
    """Port of the normalized compression system of Moore & Greitzer (Egeland & Gravdahl
    (14.1)-(14.4)): pressure coefficient psi (across; a pressure rise over the inlet's,
    divided by rho U^2) and flow coefficient phi (through, positive into the component;
    an axial velocity divided by the rotor speed U, i.e. a mass flow divided by
    rho A_c U for the one flow area A_c of the model)."""

    psi = Across(unit="1", nominal=1.0, description="pressure coefficient at the port")
    phi = Through(unit="1", nominal=1.0, description="flow coefficient into the port")
    effort, flow = "psi", "phi"
    carries_power = False
    hint = "an Ambient (the inlet or the throttle's outlet) is missing, or a port is "\
           "not connected"
