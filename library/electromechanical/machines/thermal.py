"""Temperature dependence and thermal ambients of electric machines
(Modelica.Electrical.Machines.Thermal, MSL v4.0.0).

A machine made without a thermal port (the MSL's default ``useThermalPort = false``)
holds its losses' heat ports at fixed temperatures: its ``thermalAmbient``, whose
armature (and excitation) temperatures are the machine's operational ones, and whose
other ports are at 20 degC.  The MSL's machine thermal port, a connector of several heat
ports that exists with ``useThermalPort = true``, is not here yet: an ambient has the
heat ports of that connector (``heatPortArmature``, ``heatPortCore``, ...) as its own.
"""
import acausal as ac
from acausal.ports import HeatPort, RealInput

from ...thermal import FixedTemperature, PrescribedTemperature
from ...blocks import Constant

__all__ = ["convertAlpha", "convertResistance", "alpha20Zero", "alpha20Aluminium",
           "alpha20Brass", "alpha20Bronze", "alpha20Copper", "ThermalAmbientDCPM",
           "ThermalAmbientDCEE", "ThermalAmbientDCSE", "TDefault"]

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


class _ThermalAmbient(ac.Component):
    """Fixed temperatures at a DC machine's heat ports (Interfaces.DCMachines.
    PartialThermalAmbientDCMachines): the armature at Ta (or the input TArmature with
    ``useTemperatureInputs=True``), core, stray load, friction and brushes at 20 degC.
    Its heat ports are those of the MSL's thermal port (Interfaces.DCMachines.
    PartialThermalPortDCMachines)."""

    Ta = ac.Parameter(TDefault, unit="K", min=0, description="temperature of armature")
    heatPortArmature = HeatPort()
    heatPortCore = HeatPort()
    heatPortStrayLoad = HeatPort()
    heatPortFriction = HeatPort()
    heatPortBrush = HeatPort()
    temperatureArmature = PrescribedTemperature()
    temperatureCore = FixedTemperature(T=TDefault)
    temperatureStrayLoad = FixedTemperature(T=TDefault)
    temperatureFriction = FixedTemperature(T=TDefault)
    temperatureBrush = FixedTemperature(T=TDefault)
    _prescribed = (("temperatureArmature", "TArmature", "Ta"),)

    def __init__(self, *, useTemperatureInputs=False, **modifications):
        super().__init__(**modifications)
        if not isinstance(useTemperatureInputs, bool):
            raise ac.ModelError(f"{type(self).__name__}: useTemperatureInputs must be True "
                                f"or False, not {useTemperatureInputs!r}")
        object.__setattr__(self, "useTemperatureInputs", useTemperatureInputs)
        for source, signal, parameter in self._prescribed:
            if useTemperatureInputs:
                setattr(self, signal, RealInput())
            else:           # the MSL's constTa, constTpm, ...: a Constant block
                setattr(self, "const" + parameter, Constant(k=ac.ref(parameter)))

    def _temperature_signal(self, signal, parameter):
        return getattr(self, signal) if self.useTemperatureInputs \
            else getattr(self, "const" + parameter).y

    def equations(self):
        eqs = [ac.connect(self.temperatureArmature.port, self.heatPortArmature),
               ac.connect(self.temperatureBrush.port, self.heatPortBrush),
               ac.connect(self.temperatureCore.port, self.heatPortCore),
               ac.connect(self.temperatureStrayLoad.port, self.heatPortStrayLoad),
               ac.connect(self.temperatureFriction.port, self.heatPortFriction)]
        for source, signal, parameter in self._prescribed:
            eqs.append(ac.connect(self._temperature_signal(signal, parameter),
                                  getattr(self, source).T))
        return eqs


class ThermalAmbientDCPM(_ThermalAmbient):
    """Thermal ambient of a permanent magnet DC machine (Thermal.DCMachines.
    ThermalAmbientDCPM): the permanent magnet at Tpm (or the input TPermanentMagnet)."""

    Tpm = ac.Parameter(TDefault, unit="K", min=0, description="temperature of permanent "
                                                              "magnet")
    heatPortPermanentMagnet = HeatPort()
    temperaturePermanentMagnet = PrescribedTemperature()
    _prescribed = (("temperatureArmature", "TArmature", "Ta"),
                   ("temperaturePermanentMagnet", "TPermanentMagnet", "Tpm"))

    def equations(self):
        return [ac.connect(self.temperaturePermanentMagnet.port,
                           self.heatPortPermanentMagnet)]


class ThermalAmbientDCEE(_ThermalAmbient):
    """Thermal ambient of an electrically excited DC machine (Thermal.DCMachines.
    ThermalAmbientDCEE): the (shunt) excitation at Te (or the input TExcitation)."""

    Te = ac.Parameter(TDefault, unit="K", min=0, description="temperature of (shunt) "
                                                             "excitation")
    heatPortExcitation = HeatPort()
    temperatureExcitation = PrescribedTemperature()
    _prescribed = (("temperatureArmature", "TArmature", "Ta"),
                   ("temperatureExcitation", "TExcitation", "Te"))

    def equations(self):
        return [ac.connect(self.temperatureExcitation.port,
                           self.heatPortExcitation)]


class ThermalAmbientDCSE(_ThermalAmbient):
    """Thermal ambient of a series excited DC machine (Thermal.DCMachines.
    ThermalAmbientDCSE): the series excitation at Tse (or the input T_se)."""

    Tse = ac.Parameter(TDefault, unit="K", min=0, description="temperature of series "
                                                              "excitation")
    heatPortSeriesExcitation = HeatPort()
    temperatureSeriesExcitation = PrescribedTemperature()
    _prescribed = (("temperatureArmature", "TArmature", "Ta"),
                   ("temperatureSeriesExcitation", "T_se", "Tse"))

    def equations(self):
        return [ac.connect(self.temperatureSeriesExcitation.port,
                           self.heatPortSeriesExcitation)]
