"""Temperature dependence and thermal ambients of electric machines
(Modelica.Electrical.Machines.Thermal, MSL v4.0.0).

A machine made without a thermal port (the MSL's default ``useThermalPort = false``)
holds its losses' heat ports at fixed temperatures: its ``thermalAmbient``, whose
armature (and excitation) temperatures are the machine's operational ones, and whose
other ports are at 20 degC.  With ``useThermalPort=True`` the machine has instead its
``thermalPort`` (``machines.interfaces``), which a model connects to a thermal network
or to a thermal ambient of its own; an ambient made with ``useTemperatureInputs=True``
takes the armature (and excitation) temperatures from its inputs.
"""
import acausal as ac
from acausal.ports import RealInput

from ...thermal import FixedTemperature, PrescribedTemperature
from ...blocks import Constant
from .interfaces import (PartialThermalPortDCMachines, ThermalPortDCEE, ThermalPortDCPM,
                         ThermalPortDCSE)

__all__ = ["convertAlpha", "convertResistance", "alpha20Zero", "alpha20Aluminium",
           "alpha20Brass", "alpha20Bronze", "alpha20Copper", "ThermalAmbientDCPM",
           "ThermalAmbientDCEE", "ThermalAmbientDCSE", "TDefault",
           "PartialThermalAmbientDCMachines"]

# Modelica.Electrical.Machines.Thermal.Constants: temperature coefficients at 20 degC [1/K]
alpha20Zero = 0.0
alpha20Aluminium = 4.000e-3
alpha20Brass = 1.100e-3
alpha20Bronze = 0.800e-3
alpha20Copper = 3.920e-3

TDefault = 293.15    # K, the ambients' default temperature


def convertAlpha(alpha1, T2, T1=293.15):
    """The temperature coefficient at T2 of one given at T1 (Thermal.convertAlpha):
    alpha2 = alpha1 / (1 + alpha1 (T2 - T1))."""
    return alpha1 / (1 + alpha1 * (T2 - T1))


def convertResistance(RRef, TRef, alpha20, T):
    """A resistance RRef at TRef, with the coefficient alpha20 at 20 degC, at T
    (Thermal.convertResistance):  R = RRef (1 + convertAlpha(alpha20, TRef) (T - TRef))."""
    return RRef * (1 + convertAlpha(alpha20, TRef) * (T - TRef))


class PartialThermalAmbientDCMachines(ac.Component):
    """Fixed temperatures at a DC machine's heat ports (Interfaces.DCMachines.
    PartialThermalAmbientDCMachines): the armature at Ta (or the input TArmature with
    ``useTemperatureInputs=True``), core, stray load, friction and brushes at 20 degC;
    Q_flowArmature, ... are the heat flows the machine delivers into each.
    """

    useTemperatureInputs = ac.Parameter(False, structural=True, description="if true, "
                                        "temperature inputs are used; else, temperatures "
                                        "are constant")
    Ta = ac.Parameter(TDefault, unit="K", min=0, description="temperature of armature")
    thermalPort = PartialThermalPortDCMachines()
    temperatureArmature = PrescribedTemperature()
    temperatureCore = FixedTemperature(T=TDefault)
    temperatureStrayLoad = FixedTemperature(T=TDefault)
    temperatureFriction = FixedTemperature(T=TDefault)
    temperatureBrush = FixedTemperature(T=TDefault)
    TArmature = ac.Conditional(RealInput(), "useTemperatureInputs")
    constTa = ac.Conditional(Constant(k=ac.ref("Ta")), "useTemperatureInputs", when=False)
    Q_flowArmature = ac.Variable(unit="W", description="heat flow rate of armature")
    Q_flowCore = ac.Variable(unit="W", description="heat flow rate of core losses")
    Q_flowStrayLoad = ac.Variable(unit="W", description="heat flow rate of stray load "
                                                        "losses")
    Q_flowFriction = ac.Variable(unit="W", description="heat flow rate of friction losses")
    Q_flowBrush = ac.Variable(unit="W", description="heat flow rate of brushes")

    def _temperature(self, signal: str, constant: str):
        """The temperature signal: the input, or the constant block's output."""
        return getattr(self, signal) if self.useTemperatureInputs \
            else getattr(self, constant).y

    def equations(self):
        tp = self.thermalPort
        return [ac.connect(self._temperature("TArmature", "constTa"),
                           self.temperatureArmature.T),
                ac.connect(self.temperatureArmature.port, tp.heatPortArmature),
                ac.connect(self.temperatureBrush.port, tp.heatPortBrush),
                ac.connect(self.temperatureCore.port, tp.heatPortCore),
                ac.connect(self.temperatureStrayLoad.port, tp.heatPortStrayLoad),
                ac.connect(self.temperatureFriction.port, tp.heatPortFriction),
                ac.Eq(self.Q_flowArmature, self.temperatureArmature.port.Q_flow),
                ac.Eq(self.Q_flowCore, self.temperatureCore.port.Q_flow),
                ac.Eq(self.Q_flowStrayLoad, self.temperatureStrayLoad.port.Q_flow),
                ac.Eq(self.Q_flowFriction, self.temperatureFriction.port.Q_flow),
                ac.Eq(self.Q_flowBrush, self.temperatureBrush.port.Q_flow)]

    def _total(self):
        return (self.Q_flowArmature + self.Q_flowCore + self.Q_flowStrayLoad
                + self.Q_flowFriction + self.Q_flowBrush)


class ThermalAmbientDCPM(PartialThermalAmbientDCMachines):
    """Thermal ambient of a permanent magnet DC machine (Thermal.DCMachines.
    ThermalAmbientDCPM): the permanent magnet at Tpm (or the input TPermanentMagnet)."""

    Tpm = ac.Parameter(TDefault, unit="K", min=0, description="temperature of permanent "
                                                              "magnet")
    thermalPort = ThermalPortDCPM()
    temperaturePermanentMagnet = PrescribedTemperature()
    TPermanentMagnet = ac.Conditional(RealInput(), "useTemperatureInputs")
    constTpm = ac.Conditional(Constant(k=ac.ref("Tpm")), "useTemperatureInputs", when=False)
    Q_flowPermanentMagnet = ac.Variable(unit="W", description="heat flow rate of permanent "
                                                              "magnets")
    Q_flowTotal = ac.Variable(unit="W", description="total heat flow rate")

    def equations(self):
        return [ac.connect(self._temperature("TPermanentMagnet", "constTpm"),
                           self.temperaturePermanentMagnet.T),
                ac.connect(self.temperaturePermanentMagnet.port,
                           self.thermalPort.heatPortPermanentMagnet),
                ac.Eq(self.Q_flowPermanentMagnet,
                      self.temperaturePermanentMagnet.port.Q_flow),
                ac.Eq(self.Q_flowTotal, self._total() + self.Q_flowPermanentMagnet)]


class ThermalAmbientDCEE(PartialThermalAmbientDCMachines):
    """Thermal ambient of an electrically excited DC machine (Thermal.DCMachines.
    ThermalAmbientDCEE): the (shunt) excitation at Te (or the input TExcitation)."""

    Te = ac.Parameter(TDefault, unit="K", min=0, description="temperature of (shunt) "
                                                             "excitation")
    thermalPort = ThermalPortDCEE()
    temperatureExcitation = PrescribedTemperature()
    TExcitation = ac.Conditional(RealInput(), "useTemperatureInputs")
    constTe = ac.Conditional(Constant(k=ac.ref("Te")), "useTemperatureInputs", when=False)
    Q_flowExcitation = ac.Variable(unit="W", description="heat flow rate of (shunt) "
                                                         "excitation")
    Q_flowTotal = ac.Variable(unit="W", description="total heat flow rate")

    def equations(self):
        return [ac.connect(self._temperature("TExcitation", "constTe"),
                           self.temperatureExcitation.T),
                ac.connect(self.temperatureExcitation.port,
                           self.thermalPort.heatPortExcitation),
                ac.Eq(self.Q_flowExcitation, self.temperatureExcitation.port.Q_flow),
                ac.Eq(self.Q_flowTotal, self._total() + self.Q_flowExcitation)]


class ThermalAmbientDCSE(PartialThermalAmbientDCMachines):
    """Thermal ambient of a series excited DC machine (Thermal.DCMachines.
    ThermalAmbientDCSE): the series excitation at Tse (or the input T_se)."""

    Tse = ac.Parameter(TDefault, unit="K", min=0, description="temperature of series "
                                                              "excitation")
    thermalPort = ThermalPortDCSE()
    temperatureSeriesExcitation = PrescribedTemperature()
    T_se = ac.Conditional(RealInput(), "useTemperatureInputs")
    constTse = ac.Conditional(Constant(k=ac.ref("Tse")), "useTemperatureInputs", when=False)
    Q_flowSeriesExcitation = ac.Variable(unit="W", description="heat flow rate of series "
                                                               "excitation")
    Q_flowTotal = ac.Variable(unit="W", description="total heat flow rate")

    def equations(self):
        return [ac.connect(self._temperature("T_se", "constTse"),
                           self.temperatureSeriesExcitation.T),
                ac.connect(self.temperatureSeriesExcitation.port,
                           self.thermalPort.heatPortSeriesExcitation),
                ac.Eq(self.Q_flowSeriesExcitation,
                      self.temperatureSeriesExcitation.port.Q_flow),
                ac.Eq(self.Q_flowTotal, self._total() + self.Q_flowSeriesExcitation)]
