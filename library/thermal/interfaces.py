"""Partial models of lumped heat transfer (Modelica.Thermal.HeatTransfer.Interfaces).

A HeatPort carries the temperature T [K] and the heat flow rate Q_flow [W], positive
into the component.  The MSL's HeatPort_a and HeatPort_b differ only in their icons; both
are ``HeatPort`` here.
"""
import acausal as ac
from acausal.ports import HeatPort

__all__ = ["Element1D", "PartialElementaryOnePort"]


class Element1D(ac.Component):
    """Heat flowing through an element that stores none, from port_a to port_b
    (Modelica.Thermal.HeatTransfer.Interfaces.Element1D, MSL v4.0.0):

        dT = port_a.T - port_b.T,   port_a.Q_flow = Q_flow,   port_b.Q_flow = -Q_flow
    """

    port_a = HeatPort()
    port_b = HeatPort()
    dT = ac.Variable(unit="K", description="temperature difference port_a.T - port_b.T")
    Q_flow = ac.Variable(unit="W", description="heat flow rate from port_a to port_b")

    def equations(self):
        return [ac.Eq(self.dT, self.port_a.T - self.port_b.T),
                ac.Eq(self.port_a.Q_flow, self.Q_flow),
                ac.Eq(self.port_b.Q_flow, -self.Q_flow)]


class PartialElementaryOnePort(ac.Component):
    """One heat port, named port."""

    port = HeatPort()

