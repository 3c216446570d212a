"""Conditional heat ports through which components' losses leave
(Modelica.Thermal.HeatTransfer.Interfaces: PartialElementaryConditionalHeatPort,
PartialElementaryConditionalHeatPortWithoutT, PartialConditionalHeatPort).

``useHeatPort`` is a structural flag given where the component is made
(``Damper(useHeatPort=True)``); the port is an ``ac.Conditional`` and, without it, the
component's device temperature is the parameter ``T`` (or a ``FixedTemperature`` takes the
losses of a composite component).
"""
import acausal as ac
from acausal.ports import HeatPort

from .sources import FixedTemperature

__all__ = ["PartialElementaryConditionalHeatPort", "PartialElementaryConditionalHeatPortWithoutT",
           "PartialConditionalHeatPort"]


class PartialElementaryConditionalHeatPort(ac.Component):
    """A conditional heat port through which a component's losses leave
    (Modelica.Thermal.HeatTransfer.Interfaces.PartialElementaryConditionalHeatPort):

        useHeatPort:      heatPort.T = TheatPort,   heatPort.Q_flow = -lossPower
        not useHeatPort:  TheatPort = T   (the device at the fixed temperature T)

    The component gives ``lossPower`` (> 0 when heat flows out) by an equation and may
    read ``TheatPort``.  ``useHeatPort`` is fixed where the component is made
    (``ac.Conditional``).
    """

    useHeatPort = ac.Parameter(False, structural=True, description="enable the heat port")
    T = ac.Parameter(293.15, unit="K", description="fixed device temperature if "
                                                   "useHeatPort = false")
    heatPort = ac.Conditional(HeatPort(), "useHeatPort")
    lossPower = ac.Variable(unit="W", description="loss power leaving the component via "
                                                  "heatPort")
    TheatPort = ac.Variable(unit="K", description="temperature of heatPort")

    def equations(self):
        if self.useHeatPort:
            return [ac.Eq(self.heatPort.T, self.TheatPort),
                    ac.Eq(self.heatPort.Q_flow, -self.lossPower)]
        return [ac.Eq(self.TheatPort, self.T)]


class PartialElementaryConditionalHeatPortWithoutT(ac.Component):
    """A conditional heat port for a component whose equations do not read its temperature
    (Modelica.Thermal.HeatTransfer.Interfaces.PartialElementaryConditionalHeatPortWithoutT):

        useHeatPort:  heatPort.Q_flow = -lossPower   (else the losses leave unaccounted)
    """

    useHeatPort = ac.Parameter(False, structural=True, description="enable the heat port")
    heatPort = ac.Conditional(HeatPort(), "useHeatPort")
    lossPower = ac.Variable(unit="W", description="loss power leaving the component via "
                                                  "heatPort")

    def equations(self):
        if self.useHeatPort:
            return [ac.Eq(self.heatPort.Q_flow, -self.lossPower)]
        return []


class PartialConditionalHeatPort(ac.Component):
    """A conditional heat port for a component built of others
    (Modelica.Thermal.HeatTransfer.Interfaces.PartialConditionalHeatPort): the parts send
    their losses to ``internalHeatPort``, which is the ``heatPort`` with
    ``useHeatPort=True`` and held at the temperature T by a ``fixedTemperature`` source
    without it."""

    useHeatPort = ac.Parameter(False, structural=True, description="enable the heat port")
    T = ac.Parameter(293.15, unit="K", description="fixed device temperature if "
                                                   "useHeatPort = false")
    heatPort = ac.Conditional(HeatPort(), "useHeatPort")
    fixedTemperature = ac.Conditional(FixedTemperature(T=ac.ref("T")), "useHeatPort",
                                      when=False)
    internalHeatPort = HeatPort()

    def equations(self):
        if self.useHeatPort:
            return [ac.connect(self.heatPort, self.internalHeatPort)]
        return [ac.connect(self.fixedTemperature.port, self.internalHeatPort)]
