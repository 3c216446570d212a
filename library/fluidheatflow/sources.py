"""Boundary conditions and flow sources of a coolant circuit
(Modelica.Thermal.FluidHeatFlow.Sources, MSL v4.0.0).

The MSL's optional signal inputs are chosen where a source is made, as other ports that
exist or not (``useSupport``): ``VolumeFlow(useVolumeFlowInput=True)`` has the input
``volumeFlow``, else it imposes the parameter ``constantVolumeFlow``.
"""
import acausal as ac
from acausal.ports import RealInput, RotationalFlange

from .base_classes import SMALL, SinglePort, TwoPort, flag

__all__ = ["Ambient", "AbsolutePressure", "VolumeFlow", "PressureIncrease", "IdealPump"]


class _Optional:
    """The value of an optional input: the input when it exists, else the parameter."""

    def _input_or(self, choice: str, port: str, parameter: str):
        return getattr(self, port) if getattr(self, choice) else getattr(self, parameter)

    def _make_input(self, choice: str, port: str, value) -> None:
        object.__setattr__(self, choice, flag(type(self).__name__, choice, value))
        if value:
            setattr(self, port, RealInput())


class Ambient(_Optional, SinglePort):
    """Ambient with constant or prescribed pressure and temperature
    (Modelica.Thermal.FluidHeatFlow.Sources.Ambient):

        flowPort.p = pAmbient,   T = TAmbient

    pAmbient = constantAmbientPressure, or the input ``ambientPressure`` with
    ``usePressureInput=True``; TAmbient = constantAmbientTemperature, or the input
    ``ambientTemperature`` with ``useTemperatureInput=True``.  Medium leaving the ambient
    has its temperature; medium entering it mixes into it (SinglePort).
    """

    constantAmbientPressure = ac.Parameter(0.0, unit="Pa", description="ambient pressure")
    constantAmbientTemperature = ac.Parameter(293.15, unit="K", min=0,
                                              description="ambient temperature")

    def __init__(self, *, usePressureInput=False, useTemperatureInput=False,
                 **modifications):
        super().__init__(**modifications)
        self._make_input("usePressureInput", "ambientPressure", usePressureInput)
        self._make_input("useTemperatureInput", "ambientTemperature", useTemperatureInput)

    def equations(self):
        return [ac.Eq(self.flowPort.p, self._input_or("usePressureInput", "ambientPressure",
                                                      "constantAmbientPressure")),
                ac.Eq(self.T, self._input_or("useTemperatureInput", "ambientTemperature",
                                             "constantAmbientTemperature"))]


class AbsolutePressure(SinglePort):
    """The pressure level of a closed circuit (Modelica.Thermal.FluidHeatFlow.Sources.
    AbsolutePressure): no medium passes it,

        flowPort.p = p,   flowPort.H_flow = 0,   h = flowPort.h
    """

    exchange = False
    p = ac.Parameter(0.0, unit="Pa", description="pressure ground")

    def equations(self):
        return [ac.Eq(self.flowPort.p, self.p), ac.Eq(self.flowPort.H_flow, 0)]


class _Source(TwoPort):
    """A two-port that exchanges no heat and whose outlet temperature is its T (the MSL's
    ``final tapT = 1``):  Q_flow = 0."""

    tapT = ac.Parameter(1.0, unit="1", min=1, max=1, description="the outlet temperature "
                                                                 "exchanges heat")

    def equations(self):
        return [ac.Eq(self.Q_flow, 0)]


class VolumeFlow(_Optional, _Source):
    """Imposed volume flow (Modelica.Thermal.FluidHeatFlow.Sources.VolumeFlow):

        V_flow = constantVolumeFlow,  or the input volumeFlow [m3/s]
        (``useVolumeFlowInput=True``)
    """

    constantVolumeFlow = ac.Parameter(1.0, unit="m3/s", description="volume flow rate")

    def __init__(self, *, useVolumeFlowInput=False, **modifications):
        super().__init__(**modifications)
        self._make_input("useVolumeFlowInput", "volumeFlow", useVolumeFlowInput)

    def equations(self):
        return [ac.Eq(self.V_flow, self._input_or("useVolumeFlowInput", "volumeFlow",
                                                  "constantVolumeFlow"))]


class PressureIncrease(_Optional, _Source):
    """Imposed pressure increase (Modelica.Thermal.FluidHeatFlow.Sources.PressureIncrease):

        dp = -constantPressureIncrease,  or -the input pressureIncrease [Pa]
        (``usePressureIncreaseInput=True``)
    """

    constantPressureIncrease = ac.Parameter(1.0, unit="Pa", description="pressure increase")

    def __init__(self, *, usePressureIncreaseInput=False, **modifications):
        super().__init__(**modifications)
        self._make_input("usePressureIncreaseInput", "pressureIncrease",
                         usePressureIncreaseInput)

    def equations(self):
        return [ac.Eq(self.dp, -self._input_or("usePressureIncreaseInput",
                                               "pressureIncrease",
                                               "constantPressureIncrease"))]


class IdealPump(_Source):
    """Pump driven by a shaft, with a parabolic characteristic scaled with the speed
    (Modelica.Thermal.FluidHeatFlow.Sources.IdealPump):

        w = der(flange_a.phi)
        dp1 = dp0 sign(w/wNominal) (w/wNominal)^2,   V_flow1 = V_flow0 w/wNominal
        dp = -dp1 (1 - V_flow/V_flow1),   flange_a.tau w = -dp V_flow     (w != 0)
        dp = 0,   flange_a.tau = 0                                        (w = 0)

    dp0 is the pressure increase at zero flow, V_flow0 the flow at zero pressure
    increase, both at wNominal.  dp is written dp = -dp1 + dp0/V_flow0 |w/wNominal|
    V_flow (the same for w != 0, and 0 at w = 0 without a division by V_flow1 = 0).
    The pump has no housing flange: its stator is fixed.
    """

    wNominal = ac.Parameter(1.0, unit="rad/s", description="nominal speed")
    dp0 = ac.Parameter(2.0, unit="Pa", description="max. pressure increase @ V_flow = 0")
    V_flow0 = ac.Parameter(2.0, unit="m3/s", description="max. volume flow rate @ dp = 0")
    flange_a = RotationalFlange()
    w = ac.Variable(unit="rad/s", description="speed")
    dp1 = ac.Variable(unit="Pa", description="pressure increase at zero flow and speed w")
    V_flow1 = ac.Variable(unit="m3/s", description="flow at zero pressure increase and "
                                                   "speed w")

    def equations(self):
        x = self.w / self.wNominal
        stopped = ac.abs(self.w) < SMALL * self.wNominal
        return [ac.Eq(self.w, ac.der(self.flange_a.phi)),
                ac.Eq(self.dp1, self.dp0 * ac.no_event(ac.sign(x)) * x**2),
                ac.Eq(self.V_flow1, self.V_flow0 * x),
                ac.Eq(self.dp, -self.dp1 + self.dp0 / self.V_flow0 * ac.no_event(ac.abs(x))
                      * self.V_flow),
                # tau w = -dp V_flow; at w = 0, tau = 0 (written tau wNominal = 0)
                ac.Eq(self.flange_a.tau * ac.no_event(ac.if_else(stopped, self.wNominal,
                                                                 self.w)),
                      ac.no_event(ac.if_else(stopped, 0, -self.dp * self.V_flow)))]
