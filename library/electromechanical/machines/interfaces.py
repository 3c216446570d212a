"""The thermal ports of DC machines (Modelica.Electrical.Machines.Interfaces.DCMachines,
MSL v4.0.0): connectors made of one heat port per kind of loss (``ac.PortGroup``).

A machine made with ``useThermalPort=True`` has its ``thermalPort`` (every heat port
must be connected, a port without losses to a fixed temperature as the MSL says);
connecting it to a thermal ambient's ``thermalPort`` (``ac.connect(dcpm.thermalPort,
thermalAmbientDCPM.thermalPort)``) connects the heat ports of the same names, and each
member is a heat port of its own (``ac.connect(armature.port,
dcpm.thermalPort.heatPortArmature)``).
"""
from acausal.components.portgroups import PortGroup
from acausal.ports import HeatPort

__all__ = ["PartialThermalPortDCMachines", "ThermalPortDCPM", "ThermalPortDCEE",
           "ThermalPortDCSE"]


class PartialThermalPortDCMachines(PortGroup):
    """The heat ports every DC machine has (Interfaces.DCMachines.
    PartialThermalPortDCMachines): armature, core, stray load, friction and brushes."""

    heatPortArmature = HeatPort()
    heatPortCore = HeatPort()
    heatPortStrayLoad = HeatPort()
    heatPortFriction = HeatPort()
    heatPortBrush = HeatPort()


class ThermalPortDCPM(PartialThermalPortDCMachines):
    """Thermal port of a permanent magnet DC machine (Interfaces.DCMachines.
    ThermalPortDCPM): and the permanent magnet's heat port."""

    heatPortPermanentMagnet = HeatPort()


class ThermalPortDCEE(PartialThermalPortDCMachines):
    """Thermal port of an electrically excited DC machine (Interfaces.DCMachines.
    ThermalPortDCEE): and the (shunt) excitation's heat port."""

    heatPortExcitation = HeatPort()


class ThermalPortDCSE(PartialThermalPortDCMachines):
    """Thermal port of a series excited DC machine (Interfaces.DCMachines.
    ThermalPortDCSE): and the series excitation's heat port."""

    heatPortSeriesExcitation = HeatPort()
