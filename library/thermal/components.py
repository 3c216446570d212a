"""Lumped thermal elements (Modelica.Thermal.HeatTransfer.Components, MSL v4.0.0)."""
import acausal as ac
from acausal.ports import HeatPort, RealInput

from .interfaces import Element1D, PartialElementaryOnePort

__all__ = ["HeatCapacitor", "ThermalConductor", "ThermalResistor", "Convection",
           "ConvectiveResistor", "ThermalCollector"]

class HeatCapacitor(PartialElementaryOnePort):
    """Lumped heat capacity at a uniform temperature
    (Modelica.Thermal.HeatTransfer.Components.HeatCapacitor):

        T = port.T,   der_T = der(T),   C der(T) = port.Q_flow
    """

    C = ac.Parameter(1.0, unit="J/K", description="heat capacity of element (= cp m)")
    T = ac.Variable(start=293.15, unit="K", nominal=300.0, description="temperature")
    der_T = ac.Variable(unit="K/s", description="time derivative of temperature")

    def stored_energy(self):
        """Internal energy C T (relative to T = 0 K)."""
        return self.C * self.T

    def equations(self):
        return [ac.Eq(self.T, self.port.T),
                ac.Eq(self.der_T, ac.der(self.T)),
                ac.Eq(self.C * ac.der(self.T), self.port.Q_flow)]


class ThermalConductor(Element1D):
    """Lumped conduction (Modelica.Thermal.HeatTransfer.Components.ThermalConductor):

        Q_flow = G dT
    """

    G = ac.Parameter(1.0, unit="W/K", description="constant thermal conductance")

    energy_role = "lossless"  # heat in at one port leaves at the other

    def equations(self):
        return [ac.Eq(self.Q_flow, self.G * self.dT)]


class ThermalResistor(Element1D):
    """Lumped thermal resistance (Modelica.Thermal.HeatTransfer.Components.ThermalResistor):

        dT = R Q_flow
    """

    R = ac.Parameter(1.0, unit="K/W", description="constant thermal resistance")

    energy_role = "lossless"  # heat in at one port leaves at the other

    def equations(self):
        return [ac.Eq(self.dT, self.R * self.Q_flow)]


class _SolidFluid(ac.Component):
    """The ports of convection: heat flows from the solid to the fluid,

        dT = solid.T - fluid.T,   solid.Q_flow = Q_flow,   fluid.Q_flow = -Q_flow
    """

    solid = HeatPort()
    fluid = HeatPort()
    Q_flow = ac.Variable(unit="W", description="heat flow rate from solid to fluid")
    dT = ac.Variable(unit="K", description="solid.T - fluid.T")

    energy_role = "lossless"  # heat in at one port leaves at the other

    def equations(self):
        return [ac.Eq(self.dT, self.solid.T - self.fluid.T),
                ac.Eq(self.solid.Q_flow, self.Q_flow),
                ac.Eq(self.fluid.Q_flow, -self.Q_flow)]


class Convection(_SolidFluid):
    """Convective heat transfer with a conductance set by a signal
    (Modelica.Thermal.HeatTransfer.Components.Convection):

        Q_flow = Gc dT,   Gc [W/K] = h A, the input (heat transfer coefficient times area)
    """

    Gc = RealInput()

    def equations(self):
        return [ac.Eq(self.Q_flow, self.Gc * self.dT)]


class ConvectiveResistor(_SolidFluid):
    """Convection with a resistance set by a signal
    (Modelica.Thermal.HeatTransfer.Components.ConvectiveResistor):

        dT = Rc Q_flow,   Rc [K/W] the input
    """

    Rc = RealInput()

    def equations(self):
        return [ac.Eq(self.dT, self.Rc * self.Q_flow)]


class ThermalCollector(ac.Component):
    """Collects m heat flows into one port
    (Modelica.Thermal.HeatTransfer.Components.ThermalCollector):

        port_b.Q_flow + sum(port_a[k].Q_flow) = 0,   port_a[k].T = port_b.T

    ``ThermalCollector(m=3)``: ``port_a`` is a list of m heat ports (``port_a[0]`` ...,
    numbered from 0).
    """

    m = ac.Parameter(3, structural=True, min=1, description="number of collected heat "
                                                              "flows")
    port_b = HeatPort()

    energy_role = "lossless"  # heat in at the m ports leaves at port_b

    def build(self):
        self.port_a = [HeatPort() for _ in range(int(self.m))]

    def equations(self):
        return [ac.Eq(self.port_b.Q_flow + sum(p.Q_flow for p in self.port_a), 0),
                *(ac.Eq(p.T, self.port_b.T) for p in self.port_a)]
