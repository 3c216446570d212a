"""Lumped thermal elements (Modelica.Thermal.HeatTransfer.Components)."""
import acausal as ac

from .interfaces import Element1D, PartialElementaryOnePort

__all__ = ["HeatCapacitor", "ThermalConductor", "ThermalResistor", "Convection"]


class HeatCapacitor(PartialElementaryOnePort):
    """Lumped heat capacity at a uniform temperature:

        T = port.T,   C der(T) = port.Q_flow
    """

    C = ac.Parameter(1.0, unit="J/K", min=0, description="heat capacity")
    T = ac.Variable(start=293.15, unit="K", nominal=300.0, description="temperature")

    def stored_energy(self):
        """Internal energy C T (relative to T = 0 K)."""
        return self.C * self.T

    def equations(self):
        return [ac.Eq(self.T, self.port.T), ac.Eq(self.C * ac.der(self.T), self.port.Q_flow)]


class ThermalConductor(Element1D):
    """Lumped conduction:  Q_flow = G dT."""

    G = ac.Parameter(1.0, unit="W/K", min=0, description="thermal conductance")

    energy_role = "lossless"  # heat in at one port leaves at the other

    def equations(self):
        return [ac.Eq(self.Q_flow, self.G * self.dT)]


class ThermalResistor(Element1D):
    """Lumped thermal resistance:  dT = R Q_flow."""

    R = ac.Parameter(1.0, unit="K/W", min=0, description="thermal resistance")

    energy_role = "lossless"  # heat in at one port leaves at the other

    def equations(self):
        return [ac.Eq(self.dT, self.R * self.Q_flow)]


class Convection(Element1D):
    """Convective heat transfer from a solid surface (port_a) to a fluid (port_b):

        Q_flow = Gc dT,   Gc = h A  (heat transfer coefficient times area)
    """

    Gc = ac.Parameter(1.0, unit="W/K", min=0, description="convective thermal conductance")

    energy_role = "lossless"  # heat in at one port leaves at the other

    def equations(self):
        return [ac.Eq(self.Q_flow, self.Gc * self.dT)]
