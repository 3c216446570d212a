"""Partial models of the coolant flow (Modelica.Thermal.FluidHeatFlow.BaseClasses and
Interfaces, MSL v4.0.0): the two-port with its mass and energy balance, the single port
of a volume, the simple friction law, and the enthalpy carried by a flow.

Enthalpy at a port (the MSL's ``semiLinear``): a port's enthalpy flow is

    H_flow = semiLinear(m_flow, h_port, h) = m_flow h_port   if m_flow >= 0 (inflow)
                                             m_flow h        if m_flow <  0 (outflow)

with h_port the mixing enthalpy of the connection (an across variable of the port) and
h the component's own.  Written as m_flow (h_port + h)/2 + |m_flow| (h_port - h)/2, it
leaves h_port undetermined where every flow into a connection is zero (0 h_port = 0):
the MSL relies on the tool's rewriting rules for that case (Modelica Language
Specification 3.7.2.5).  Here |m_flow| is replaced, inside a band |m_flow| <
``m_flow_small``, by the C1 parabola (m_flow^2/m_flow_small + m_flow_small)/2, which
equals |m_flow| and its slope at the band's edges.  Outside the band H_flow is exactly
the MSL's; inside it a connection without flow holds the mean enthalpy of its
neighbours, and each port adds a small conduction, at zero flow m_flow_small/4 (h_port
- h) (at ``m_flow_small`` = 1e-6 kg/s and cp = 1 J/(kg.K), 2.5e-7 W/K), so mass and
energy stay conserved.  The band's function is C1 and is evaluated directly (``no_event``), as
tools evaluate the MSL's semiLinear, which is ``smooth(0, ...)``: a flow that reverses
is not an event.
"""
import acausal as ac
from acausal.ports import FlowPort

from .media import Medium

__all__ = ["semi_linear", "TwoPort", "SinglePort", "SimpleFriction", "WithMedium", "flag"]

SMALL = 1e-60        # Modelica.Constants.small


def semi_linear(m_flow, h_port, h, m_flow_small):
    """The enthalpy flow into a port (module docstring): m_flow h_port for an inflow,
    m_flow h for an outflow, |m_flow| regularised below ``m_flow_small``."""
    a = ac.no_event(ac.if_else(m_flow > m_flow_small, m_flow,
                               ac.if_else(m_flow < -m_flow_small, -m_flow,
                                          (m_flow**2 / m_flow_small + m_flow_small) / 2)))
    return m_flow * (h_port + h) / 2 + a * (h_port - h) / 2


class WithMedium(ac.Component):
    """A component of one medium: ``medium=`` a :class:`Medium` (default ``Medium()``),
    given where it is made and kept as the sub-component ``medium`` (a copy)."""

    medium = Medium()

    def __init__(self, *, medium=None, **modifications):
        if isinstance(medium, dict):          # a modification of the default medium
            modifications["medium"], medium = medium, None
        super().__init__(**modifications)
        if medium is not None:
            if not isinstance(medium, Medium):
                raise ac.ModelError(f"{type(self).__name__}: medium must be a Medium "
                                    f"(Water(), Medium(rho=...)), not {medium!r}")
            self.medium = medium._clone()


def flag(kind: str, name: str, value) -> bool:
    """A structural choice given where a component is made (a port that exists or not, a
    law): True or False, else a ModelError naming the component and the choice."""
    if not isinstance(value, bool):
        raise ac.ModelError(f"{kind}: {name} must be True or False, not {value!r}")
    return value


def _initial_temperature(modifications: dict, T0, T0fixed) -> dict:
    """The MSL's T(start=T0, fixed=T0fixed), with what the caller gave for T on top."""
    flag("a two-port or single port", "T0fixed", T0fixed)
    given = modifications.pop("T", {})
    given = given if isinstance(given, dict) else {"start": given}
    return {"start": T0, "fixed": T0fixed, **given}


class TwoPort(WithMedium):
    """A flow through a volume of mass m at temperature T (Modelica.Thermal.FluidHeatFlow.
    BaseClasses.TwoPort):

        dp = flowPort_a.p - flowPort_b.p,   V_flow = flowPort_a.m_flow / rho
        flowPort_a.m_flow + flowPort_b.m_flow = 0                        (mass)
        m cv der(T) = flowPort_a.H_flow + flowPort_b.H_flow + Q_flow    (energy)
        flowPort_x.H_flow = semiLinear(flowPort_x.m_flow, flowPort_x.h, h),   h = cp T
        T_a = flowPort_a.h / cp,   T_b = flowPort_b.h / cp
        dT = T - T_a (V_flow >= 0), T_b - T (V_flow < 0)
        T_q = T - sign(V_flow) (1 - tapT) dT

    T is the outlet temperature; T_q, between inlet (tapT = 0) and outlet (tapT = 1),
    exchanges heat with the surroundings.  m = 0 makes the energy balance algebraic (a
    structural zero, the MSL's ``m > small``).  T0 and T0fixed (the MSL's T(start=T0,
    fixed=T0fixed)) and the medium are given where the component is made.
    """

    m = ac.Parameter(1.0, unit="kg", min=0, description="mass of medium")
    tapT = ac.Parameter(1.0, unit="1", min=0, max=1, description="defines the "
                        "temperature of the heat exchange between inlet and outlet")
    m_flow_small = ac.Parameter(1e-6, unit="kg/s", description="band of mass flow around "
                                "zero where the port enthalpy is regularised (> 0)")
    flowPort_a = FlowPort()
    flowPort_b = FlowPort()
    dp = ac.Variable(unit="Pa", description="pressure drop a -> b")
    V_flow = ac.Variable(start=0.0, unit="m3/s", description="volume flow a -> b")
    Q_flow = ac.Variable(unit="W", description="heat exchange with ambient")
    T = ac.Variable(start=293.15, unit="K", nominal=300.0,
                    description="outlet temperature of medium")
    T_a = ac.Variable(unit="K", nominal=300.0, description="temperature at flowPort_a")
    T_b = ac.Variable(unit="K", nominal=300.0, description="temperature at flowPort_b")
    dT = ac.Variable(unit="K", description="temperature increase of coolant in flow "
                                           "direction")
    T_q = ac.Variable(unit="K", nominal=300.0,
                      description="temperature relevant for heat exchange with ambient")
    h = ac.Variable(unit="J/kg", description="medium's specific enthalpy")

    def __init__(self, *, T0=293.15, T0fixed=False, **modifications):
        T = _initial_temperature(modifications, T0, T0fixed)
        super().__init__(T=T, **modifications)

    def equations(self):
        a, b, md = self.flowPort_a, self.flowPort_b, self.medium
        small = self.m_flow_small
        return [ac.Eq(self.dp, a.p - b.p),
                ac.Eq(self.V_flow, a.m_flow / md.rho),
                ac.Eq(self.T_a, a.h / md.cp),
                ac.Eq(self.T_b, b.h / md.cp),
                ac.Eq(self.dT, ac.no_event(ac.if_else(self.V_flow >= 0, self.T - self.T_a,
                                                      self.T_b - self.T))),
                ac.Eq(self.h, md.cp * self.T),
                ac.Eq(self.T_q, self.T - ac.no_event(ac.sign(self.V_flow))
                      * (1 - self.tapT) * self.dT),
                ac.Eq(a.m_flow + b.m_flow, 0, label="mass balance"),
                ac.Eq(self.m * md.cv * ac.der(self.T), a.H_flow + b.H_flow + self.Q_flow,
                      label="energy balance"),
                ac.Eq(a.H_flow, semi_linear(a.m_flow, a.h, self.h, small)),
                ac.Eq(b.H_flow, semi_linear(b.m_flow, b.h, self.h, small))]


class SinglePort(WithMedium):
    """A volume with one flow port (Modelica.Thermal.FluidHeatFlow.BaseClasses.
    SinglePortLeft and SinglePortBottom, which differ only in their icons):

        T_port = flowPort.h / cp,   T = h / cp
        flowPort.H_flow = semiLinear(flowPort.m_flow, flowPort.h, h)   (exchange)
        h = flowPort.h                                                  (no exchange)

    A subclass says whether medium passes the port (``exchange``, the MSL's constant
    ``Exchange``).
    """

    exchange = True
    m_flow_small = ac.Parameter(1e-6, unit="kg/s", description="band of mass flow around "
                                "zero where the port enthalpy is regularised (> 0)")
    flowPort = FlowPort()
    T_port = ac.Variable(unit="K", nominal=300.0, description="temperature at flowPort")
    T = ac.Variable(start=293.15, unit="K", nominal=300.0,
                    description="outlet temperature of medium")
    h = ac.Variable(unit="J/kg", description="specific enthalpy in the volume")

    def __init__(self, *, T0=293.15, T0fixed=False, **modifications):
        T = _initial_temperature(modifications, T0, T0fixed)
        super().__init__(T=T, **modifications)

    def equations(self):
        port, md = self.flowPort, self.medium
        eqs = [ac.Eq(self.T_port, port.h / md.cp), ac.Eq(self.T, self.h / md.cp)]
        if self.exchange:
            eqs.append(ac.Eq(port.H_flow,
                             semi_linear(port.m_flow, port.h, self.h, self.m_flow_small)))
        else:
            eqs.append(ac.Eq(self.h, port.h))
        return eqs


class SimpleFriction(ac.Component):
    """Pressure drop of a pipe (Modelica.Thermal.FluidHeatFlow.BaseClasses.SimpleFriction):
    linear below V_flowLaminar, quadratic above it,

        pressureDrop = dpLaminar/V_flowLaminar volumeFlow
                       +- k (volumeFlow -+ V_flowLaminar)^2    (|volumeFlow| > V_flowLaminar)
        k = (dpNominal - dpNomMin) / (V_flowNominal - V_flowLaminar)^2,
        dpNomMin = dpLaminar/V_flowLaminar V_flowNominal
        Q_friction = frictionLoss volumeFlow pressureDrop

    The MSL requires V_flowNominal > V_flowLaminar and dpNominal >= dpNomMin (so k >= 0).
    """

    V_flowLaminar = ac.Parameter(0.1, unit="m3/s", min=SMALL, description="laminar "
                                                                          "volume flow")
    dpLaminar = ac.Parameter(0.1, unit="Pa", description="laminar pressure drop")
    V_flowNominal = ac.Parameter(1.0, unit="m3/s", description="nominal volume flow")
    dpNominal = ac.Parameter(1.0, unit="Pa", description="nominal pressure drop")
    frictionLoss = ac.Parameter(0.0, unit="1", min=0, max=1,
                                description="part of friction losses fed to medium")
    dpNomMin = ac.Parameter(lambda c: c.dpLaminar / c.V_flowLaminar * c.V_flowNominal,
                            unit="Pa", description="nominal pressure drop of the laminar "
                                                   "law")
    k = ac.Parameter(lambda c: (c.dpNominal - c.dpNomMin)
                     / (c.V_flowNominal - c.V_flowLaminar)**2,
                     unit="Pa.s2/m6", description="coefficient of the quadratic law")
    pressureDrop = ac.Variable(unit="Pa", description="pressure drop")
    volumeFlow = ac.Variable(unit="m3/s", description="volume flow")
    Q_friction = ac.Variable(unit="W", description="friction losses fed to the medium")

    def __init__(self, **modifications):
        super().__init__(**modifications)
        given = {n: modifications.get(n, vars(SimpleFriction)[n].value)
                 for n in ("V_flowLaminar", "dpLaminar", "V_flowNominal", "dpNominal")}
        if all(isinstance(v, (int, float)) for v in given.values()):
            _check_friction(type(self).__name__, **given)

    def equations(self):
        q, laminar = self.volumeFlow, self.dpLaminar / self.V_flowLaminar
        return [ac.Eq(self.pressureDrop,
                      ac.if_else(q > self.V_flowLaminar,
                                 laminar * q + self.k * (q - self.V_flowLaminar)**2,
                                 ac.if_else(q < -self.V_flowLaminar,
                                            laminar * q - self.k * (q + self.V_flowLaminar)**2,
                                            laminar * q))),
                ac.Eq(self.Q_friction, self.frictionLoss * q * self.pressureDrop)]


def _check_friction(kind, V_flowLaminar, dpLaminar, V_flowNominal, dpNominal):
    """The MSL's initial assertions of SimpleFriction, for values given as numbers."""
    if not V_flowNominal > V_flowLaminar:
        raise ac.InvalidValue(f"{kind}: V_flowNominal = {V_flowNominal!r} has to be > "
                              f"V_flowLaminar = {V_flowLaminar!r}")
    dpNomMin = dpLaminar / V_flowLaminar * V_flowNominal
    if not dpNominal >= dpNomMin * (1 - 1e-12):
        raise ac.InvalidValue(f"{kind}: dpNominal = {dpNominal!r} has to be >= dpLaminar/"
                              f"V_flowLaminar*V_flowNominal = {dpNomMin!r}")
