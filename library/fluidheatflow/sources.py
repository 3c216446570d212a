"""Boundary conditions and flow sources of a coolant circuit
(Modelica.Thermal.FluidHeatFlow.Sources, MSL v4.0.0).

The MSL's optional signal inputs are conditional connectors (``ac.Conditional``) under
the MSL's structural flags: ``VolumeFlow(useVolumeFlowInput=True)`` has the input
``volumeFlow``, else the parameter ``constantVolumeFlow`` gives the internal value, as
the MSL writes ``if not useVolumeFlowInput then internalVolumeFlow =
constantVolumeFlow; end if``.
"""
import acausal as ac
from acausal.ports import RealInput, RotationalFlange

from .base_classes import SMALL, SinglePort, TwoPort

__all__ = ["Ambient", "AbsolutePressure", "VolumeFlow", "PressureIncrease", "IdealPump"]


def _input_or_constant(component, flag: str, port: str, internal, constant):
    """The MSL's ``RealInput port = internal if flag`` and ``if not flag then internal =
    constant; end if``."""
    if getattr(component, flag):
        return ac.Eq(getattr(component, port), internal)
    return ac.Eq(internal, constant)


class Ambient(SinglePort):
    """Ambient with constant or prescribed pressure and temperature
    (Modelica.Thermal.FluidHeatFlow.Sources.Ambient):

        flowPort.p = pAmbient,   T = TAmbient

    pAmbient = constantAmbientPressure, or the input ``ambientPressure`` with
    ``usePressureInput=True``; TAmbient = constantAmbientTemperature, or the input
    ``ambientTemperature`` with ``useTemperatureInput=True``.  Medium leaving the ambient
    has its temperature; medium entering it mixes into it (SinglePort).
    """

    usePressureInput = ac.Parameter(False, structural=True,
                                    description="enable / disable pressure input")
    constantAmbientPressure = ac.Parameter(0.0, unit="Pa", description="ambient pressure")
    useTemperatureInput = ac.Parameter(False, structural=True,
                                       description="enable / disable temperature input")
    constantAmbientTemperature = ac.Parameter(293.15, unit="K", min=0,
                                              description="ambient temperature")
    energy_role = "source"   # an environment outside the model

    ambientPressure = ac.Conditional(RealInput(), "usePressureInput")
    ambientTemperature = ac.Conditional(RealInput(), "useTemperatureInput")
    pAmbient = ac.Variable(unit="Pa", description="ambient pressure")
    TAmbient = ac.Variable(unit="K", nominal=300.0, description="ambient temperature")

    def equations(self):
        return [_input_or_constant(self, "usePressureInput", "ambientPressure",
                                   self.pAmbient, self.constantAmbientPressure),
                _input_or_constant(self, "useTemperatureInput", "ambientTemperature",
                                   self.TAmbient, self.constantAmbientTemperature),
                ac.Eq(self.flowPort.p, self.pAmbient),
                ac.Eq(self.T, self.TAmbient)]


class AbsolutePressure(SinglePort):
    """The pressure level of a closed circuit (Modelica.Thermal.FluidHeatFlow.Sources.
    AbsolutePressure): no medium passes it,

        flowPort.p = p,   flowPort.H_flow = 0,   h = flowPort.h
    """

    exchange = False
    p = ac.Parameter(0.0, unit="Pa", description="pressure ground")

    energy_role = "source"   # sets the pressure level from outside the model

    def equations(self):
        return [ac.Eq(self.flowPort.p, self.p), ac.Eq(self.flowPort.H_flow, 0)]


class _Source(TwoPort):
    """A two-port that exchanges no heat and whose outlet temperature is its T (the MSL's
    ``final tapT = 1``):  Q_flow = 0."""

    tapT = ac.Parameter(1.0, unit="1", min=1, max=1, description="the outlet temperature "
                                                                 "exchanges heat")

    energy_role = "source"   # imposes a flow or a pressure rise from outside the model
    stored_energy = None     # (its medium's m cv T is part of what it delivers)

    def equations(self):
        return [ac.Eq(self.Q_flow, 0)]


class VolumeFlow(_Source):
    """Imposed volume flow (Modelica.Thermal.FluidHeatFlow.Sources.VolumeFlow):

        V_flow = internalVolumeFlow = constantVolumeFlow,  or the input volumeFlow [m3/s]
        (``useVolumeFlowInput=True``)
    """

    useVolumeFlowInput = ac.Parameter(False, structural=True,
                                      description="enable / disable volume flow input")
    constantVolumeFlow = ac.Parameter(1.0, unit="m3/s", description="volume flow rate")
    volumeFlow = ac.Conditional(RealInput(), "useVolumeFlowInput")
    internalVolumeFlow = ac.Variable(unit="m3/s", description="volume flow rate")

    def equations(self):
        return [_input_or_constant(self, "useVolumeFlowInput", "volumeFlow",
                                   self.internalVolumeFlow, self.constantVolumeFlow),
                ac.Eq(self.V_flow, self.internalVolumeFlow)]


class PressureIncrease(_Source):
    """Imposed pressure increase (Modelica.Thermal.FluidHeatFlow.Sources.PressureIncrease):

        dp = -internalPressureIncrease,   internalPressureIncrease =
        constantPressureIncrease,  or the input pressureIncrease [Pa]
        (``usePressureIncreaseInput=True``)
    """

    usePressureIncreaseInput = ac.Parameter(False, structural=True, description="enable / "
                                            "disable pressure increase input")
    constantPressureIncrease = ac.Parameter(1.0, unit="Pa", description="pressure increase")
    pressureIncrease = ac.Conditional(RealInput(), "usePressureIncreaseInput")
    internalPressureIncrease = ac.Variable(unit="Pa", description="pressure increase")

    def equations(self):
        return [_input_or_constant(self, "usePressureIncreaseInput", "pressureIncrease",
                                   self.internalPressureIncrease,
                                   self.constantPressureIncrease),
                ac.Eq(self.dp, -self.internalPressureIncrease)]


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

    energy_role = None       # converts the shaft's power into hydraulic power, tau w =
    stored_energy = TwoPort.stored_energy     # -dp V_flow, and stores m cv T

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
