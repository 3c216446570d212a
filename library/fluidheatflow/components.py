"""Pipes, valves and volumes of a coolant circuit (Modelica.Thermal.FluidHeatFlow.
Components, MSL v4.0.0)."""
import acausal as ac
from acausal.ports import FlowPort, HeatPort, RealInput, RealOutput

from ..translational.interfaces import PartialElementaryOneFlangeAndSupport
from .base_classes import SMALL, SimpleFriction, SinglePort, TwoPort, flag

__all__ = ["Pipe", "HeatedPipe", "Valve", "OneWayValve", "OpenTank", "Cylinder"]

G_N = 9.80665        # m/s2, Modelica.Constants.g_n


class Pipe(TwoPort, SimpleFriction):
    """Pipe with friction, a geodetic height and optional heat exchange
    (Modelica.Thermal.FluidHeatFlow.Components.Pipe):

        volumeFlow = V_flow,   dp = pressureDrop + rho g h_g
        Q_flow = Q_flowHeatPort + Q_friction

    ``Pipe(useHeatPort=True)`` has a ``heatPort`` at T_q (heatPort.T = T_q,
    heatPort.Q_flow = Q_flowHeatPort, the heat flowing into the medium); without it
    Q_flowHeatPort = 0.
    """

    h_g = ac.Parameter(0.0, unit="m", description="geodetic height (height difference "
                                                  "from flowPort_a to flowPort_b)")
    g = ac.Parameter(G_N, unit="m/s2", min=0, description="gravitation")
    Q_flowHeatPort = ac.Variable(unit="W", description="heat flow at the heat port")

    def __init__(self, *, useHeatPort=False, **modifications):
        super().__init__(**modifications)
        object.__setattr__(self, "useHeatPort", flag(type(self).__name__, "useHeatPort",
                                                      useHeatPort))
        if useHeatPort:
            self.heatPort = HeatPort()

    def equations(self):
        eqs = [ac.Eq(self.volumeFlow, self.V_flow),
               ac.Eq(self.dp, self.pressureDrop + self.medium.rho * self.g * self.h_g),
               ac.Eq(self.Q_flow, self.Q_flowHeatPort + self.Q_friction)]
        if self.useHeatPort:
            eqs += [ac.Eq(self.heatPort.T, self.T_q),
                    ac.Eq(self.heatPort.Q_flow, self.Q_flowHeatPort)]
        else:
            eqs.append(ac.Eq(self.Q_flowHeatPort, 0))
        return eqs


class HeatedPipe(Pipe):
    """A Pipe with its heat port (``Pipe(useHeatPort=True)``; the MSL 3's HeatedPipe)."""

    def __init__(self, **modifications):
        super().__init__(useHeatPort=True, **modifications)


class Valve(TwoPort):
    """Valve with a linear or exponential characteristic
    (Modelica.Thermal.FluidHeatFlow.Components.Valve):

        yLim = max(min(y, y1), 0)
        Kv/Kv1 = kv0 + (1 - kv0) yLim/y1                (LinearCharacteristic)
        Kv/Kv1 = kv0 exp(log(1/kv0) yLim/y1)            (exponential)
        dp/dp0 = rho/rho0 (V_flow/Kv) |V_flow/Kv|,   Q_flow = frictionLoss V_flow dp

    Kv is the standard flow at the pressure drop dp0 of a medium of density rho0.
    ``LinearCharacteristic`` is chosen where the valve is made (True by default).
    """

    m = ac.Parameter(0.0, unit="kg", min=0, description="mass of medium")
    tapT = ac.Parameter(1.0, unit="1", min=1, max=1, description="the outlet temperature "
                                                                 "exchanges heat")
    y1 = ac.Parameter(1.0, unit="1", min=SMALL, description="max. valve opening")
    Kv1 = ac.Parameter(1.0, unit="m3/s", min=SMALL, description="max. flow @ y = y1")
    kv0 = ac.Parameter(0.01, unit="1", min=SMALL, max=1 - SMALL,
                       description="leakage flow / max. flow @ y = 0")
    dp0 = ac.Parameter(1.0, unit="Pa", description="standard pressure drop")
    rho0 = ac.Parameter(10.0, unit="kg/m3", description="standard medium's density")
    frictionLoss = ac.Parameter(0.0, unit="1", min=0, max=1,
                                description="part of friction losses fed to medium")
    y = RealInput()
    yLim = ac.Variable(unit="1", description="limited valve opening")
    Kv = ac.Variable(unit="m3/s", description="standard flow rate")

    def __init__(self, *, LinearCharacteristic=True, **modifications):
        super().__init__(**modifications)
        object.__setattr__(self, "LinearCharacteristic",
                           flag(type(self).__name__, "LinearCharacteristic",
                                 LinearCharacteristic))

    def equations(self):
        opening = self.yLim / self.y1
        if self.LinearCharacteristic:
            relative = self.kv0 + (1 - self.kv0) * opening
        else:
            relative = self.kv0 * ac.exp(ac.log(1 / self.kv0) * opening)
        ratio = self.V_flow / self.Kv
        return [ac.Eq(self.yLim, ac.max(ac.min(self.y, self.y1), 0)),
                ac.Eq(self.Kv / self.Kv1, relative),
                ac.Eq(self.dp / self.dp0, self.medium.rho / self.rho0 * ratio * ac.abs(ratio)),
                ac.Eq(self.Q_flow, self.frictionLoss * self.V_flow * self.dp)]


class OneWayValve(TwoPort):
    """Check valve (Modelica.Thermal.FluidHeatFlow.Components.OneWayValve), on a curve
    parameter s: backward (s < 0) a small leakage, forward a small pressure drop,

        backward:  dp = s [Pa],                       V_flow = s [Pa] V_flowBackward/dpNominal
        forward:   dp = s [m3/s] dpForward/V_flowNominal,   V_flow = s [m3/s]
        Q_flow = frictionLoss V_flow dp

    (s [Pa] and s [m3/s] are s times the MSL's unit constants unitPressureDrop = 1 Pa
    and unitVolumeFlowRate = 1 m3/s); the MSL's Boolean ``backward = s < 0`` is the
    relation of the switch.
    """

    m = ac.Parameter(0.0, unit="kg", min=0, description="mass of medium")
    tapT = ac.Parameter(1.0, unit="1", min=1, max=1, description="the outlet temperature "
                                                                 "exchanges heat")
    V_flowNominal = ac.Parameter(1.0, unit="m3/s",
                                 description="nominal volume flow rate (forward)")
    dpForward = ac.Parameter(1e-6, unit="Pa",
                             description="pressure drop at nominal flow (forward)")
    dpNominal = ac.Parameter(1e5, unit="Pa", description="nominal pressure (backward)")
    V_flowBackward = ac.Parameter(1e-6, unit="m3/s",
                                  description="leakage volume flow rate (backward)")
    frictionLoss = ac.Parameter(0.0, unit="1", min=0, max=1,
                                description="part of friction losses fed to medium")
    unitVolumeFlowRate = ac.Parameter(1.0, unit="m3/s", description="unit of s, forward")
    unitPressureDrop = ac.Parameter(1.0, unit="Pa", description="unit of s, backward")
    s = ac.Variable(start=0.0, unit="1", description="position on the valve "
                                                     "characteristic")

    def equations(self):
        backward = self.s < 0
        forward_dp = self.unitVolumeFlowRate * self.dpForward / self.V_flowNominal
        backward_flow = self.unitPressureDrop * self.V_flowBackward / self.dpNominal
        return [ac.Eq(self.dp, self.s * ac.if_else(backward, self.unitPressureDrop,
                                                   forward_dp)),
                ac.Eq(self.V_flow, self.s * ac.if_else(backward, backward_flow,
                                                       self.unitVolumeFlowRate)),
                ac.Eq(self.Q_flow, self.frictionLoss * self.V_flow * self.dp)]


class OpenTank(SinglePort):
    """Tank under ambient pressure (Modelica.Thermal.FluidHeatFlow.Components.OpenTank):

        m = rho ATank level,   der(m) = flowPort.m_flow                 (mass)
        H = m h,   der(H) = flowPort.H_flow + Q_flow                    (energy)
        flowPort.p = pAmbient + m g / ATank,   TTank = T

    ``OpenTank(useHeatPort=True)`` has a ``heatPort`` at T that heats the medium
    (heatPort.Q_flow = Q_flow); without it Q_flow = 0.  The MSL asserts 0 <= level <=
    hTank (the tank got empty, or full); here the level is not bounded.
    """

    ATank = ac.Parameter(1.0, unit="m2", description="cross section of tank")
    hTank = ac.Parameter(1.0, unit="m", description="height of tank")
    pAmbient = ac.Parameter(0.0, unit="Pa", description="ambient pressure")
    g = ac.Parameter(G_N, unit="m/s2", min=0, description="gravitation")
    m = ac.Variable(unit="kg", description="mass of medium in tank")
    H = ac.Variable(unit="J", description="enthalpy of medium")
    Q_flow = ac.Variable(unit="W", description="heat flow at the optional heatPort")
    level = RealOutput()
    TTank = RealOutput()

    def __init__(self, *, useHeatPort=False, **modifications):
        super().__init__(**modifications)
        object.__setattr__(self, "useHeatPort", flag(type(self).__name__, "useHeatPort",
                                                      useHeatPort))
        if useHeatPort:
            self.heatPort = HeatPort()

    def equations(self):
        port, md = self.flowPort, self.medium
        eqs = [ac.Eq(self.TTank, self.T),
               ac.Eq(self.m, md.rho * self.ATank * self.level),
               ac.Eq(ac.der(self.m), port.m_flow, label="mass balance"),
               ac.Eq(self.H, self.m * self.h),
               ac.Eq(ac.der(self.H), port.H_flow + self.Q_flow, label="energy balance"),
               ac.Eq(port.p, self.pAmbient + self.m * self.g / self.ATank)]
        if self.useHeatPort:
            eqs += [ac.Eq(self.heatPort.T, self.T), ac.Eq(self.heatPort.Q_flow, self.Q_flow)]
        else:
            eqs.append(ac.Eq(self.Q_flow, 0))
        return eqs


class Cylinder(SinglePort, PartialElementaryOneFlangeAndSupport):
    """Piston in a cylinder (Modelica.Thermal.FluidHeatFlow.Components.Cylinder): the
    medium fills the cylinder up to the piston at s,

        s = flange.s - s_support,   flowPort.p A = -f,   f = flange.f
        m = rho A s,   der(m) = flowPort.m_flow                  (mass)
        H = m h,   der(H) = flowPort.H_flow                      (energy)

    The MSL asserts 0 < s <= L (the piston hit the bottom or the top); here s is not
    bounded.
    """

    A = ac.Parameter(1.0, unit="m2", description="cross section of cylinder/piston")
    L = ac.Parameter(1.0, unit="m", description="length of cylinder")
    s = ac.Variable(start=SMALL, unit="m", description="distance between flange and "
                                                       "support")
    f = ac.Variable(unit="N", description="force at piston")
    m = ac.Variable(unit="kg", description="mass of medium")
    H = ac.Variable(unit="J", description="enthalpy of medium")

    def equations(self):
        port, md = self.flowPort, self.medium
        return [ac.Eq(self.s, self.flange.s - self.s_support()),
                ac.Eq(self.f, self.flange.f),
                ac.Eq(port.p * self.A, -self.f),
                ac.Eq(self.m, md.rho * self.A * self.s),
                ac.Eq(ac.der(self.m), port.m_flow, label="mass balance"),
                ac.Eq(self.H, self.m * self.h),
                ac.Eq(ac.der(self.H), port.H_flow, label="energy balance")]
