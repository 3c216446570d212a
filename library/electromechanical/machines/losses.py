"""Losses of DC machines (Modelica.Electrical.Machines.Losses, MSL v4.0.0): friction,
brushes, core and stray load, each with its parameter record and an optional heat port.

A loss component dissipates lossPower.  ``useHeatPort=True`` (what the machines use)
gives it a ``heatPort`` through which the losses leave, heatPort.Q_flow = -lossPower
(the MSL's PartialElementaryConditionalHeatPortWithoutT); without it, it takes no heat
port and its losses leave the model.
"""
import acausal as ac
from acausal.ports import HeatPort, RotationalFlange

from ...electrical.interfaces import OnePort
from .records import (BrushParameters, CoreParameters, FrictionParameters,
                      StrayLoadParameters)

__all__ = ["FlangeSupport", "Friction", "Brush", "Core", "StrayLoad", "brushVoltageDrop"]


class _LossHeatPort(ac.Component):
    """lossPower, and the heat port it leaves through with useHeatPort=True."""

    lossPower = ac.Variable(unit="W", description="loss power leaving the component")

    def __init__(self, *, useHeatPort=False, **modifications):
        super().__init__(**modifications)
        if not isinstance(useHeatPort, bool):
            raise ac.ModelError(f"{type(self).__name__}: useHeatPort must be True or "
                                f"False, not {useHeatPort!r}")
        object.__setattr__(self, "useHeatPort", useHeatPort)
        if useHeatPort:
            self.heatPort = HeatPort()

    def loss_power(self):
        """P_loss = lossPower (the MSL's), unless it leaves through the heat port."""
        return 0 * self.lossPower if self.useHeatPort else self.lossPower

    def equations(self):
        if self.useHeatPort:
            return [ac.Eq(self.heatPort.Q_flow, -self.lossPower)]
        return []


class FlangeSupport(ac.Component):
    """A shaft and its housing (Modelica.Electrical.Machines.Interfaces.FlangeSupport):

        phi = flange.phi - support.phi,   w = der(phi),   tau = -flange.tau = support.tau
    """

    flange = RotationalFlange()
    support = RotationalFlange()
    phi = ac.Variable(unit="rad", description="angle between shaft and support")
    tau = ac.Variable(unit="N.m", description="torque")
    w = ac.Variable(unit="rad/s", description="relative angular velocity of flange and "
                                              "support")

    def equations(self):
        return [ac.Eq(self.phi, self.flange.phi - self.support.phi),
                ac.Eq(self.w, ac.der(self.phi)),
                ac.Eq(self.tau, -self.flange.tau),
                ac.Eq(self.tau, self.support.tau)]


class Friction(_LossHeatPort, FlangeSupport):
    """Speed dependent friction losses (Modelica.Electrical.Machines.Losses.Friction):

        tau = -tauRef sign(w) (|w|/wRef)^power_w     (|w| > wLinear)
        tau = -tauLinear w / wLinear                   (|w| <= wLinear)
        lossPower = -tau w

    (The MSL evaluates the switch at wLinear without an event, noEvent; the law is
    continuous there, and here the switch is an event.)
    """

    frictionParameters = FrictionParameters()

    def equations(self):
        fp, w = self.frictionParameters, self.w
        law = ac.if_else(ac.abs(w) > fp.wLinear,
                         fp.tauRef * ac.sign(w) * (ac.abs(w) / fp.wRef)**fp.power_w,
                         fp.tauLinear * w / fp.wLinear)
        return [ac.Eq(self.tau, -law),
                ac.Eq(self.lossPower, -self.tau * w)]


def brushVoltageDrop(brushParameters, i):
    """The brushes' voltage drop at the current i (Losses.DCMachines.brushVoltageDrop):
    V i/ILinear clipped to [-V, V] (0 when V = 0); for the nominal induced voltage of a
    machine's parameters."""
    V, ILinear = brushParameters.V, brushParameters.ILinear
    return ac.max(-V, ac.min(V, V * i / ILinear))


class Brush(_LossHeatPort, OnePort):
    """Voltage drop of carbon brushes (Modelica.Electrical.Machines.Losses.DCMachines.
    Brush):

        v = V sign(i)  (|i| > ILinear),   v = V i / ILinear  (|i| <= ILinear)
        lossPower = v i
    """

    brushParameters = BrushParameters()

    def equations(self):
        bp, i = self.brushParameters, self.i
        return [ac.Eq(self.v, ac.if_else(i > bp.ILinear, bp.V,
                                         ac.if_else(i < -bp.ILinear, -bp.V,
                                                    bp.V * i / bp.ILinear))),
                ac.Eq(self.lossPower, self.v * i)]


class Core(_LossHeatPort, OnePort):
    """Core losses, a conductance across the induced voltage
    (Modelica.Electrical.Machines.Losses.DCMachines.Core):

        Gc = GcRef,   i = Gc v,   lossPower = v i

    The MSL's remagnetization speed input w enters no equation (hysteresis losses are
    not implemented there: ratioHysteresis = 0), and is not here.
    """

    coreParameters = CoreParameters()
    Gc = ac.Variable(unit="S", description="variable core loss conductance")

    def equations(self):
        return [ac.Eq(self.Gc, self.coreParameters.GcRef),
                ac.Eq(self.i, self.Gc * self.v),
                ac.Eq(self.lossPower, self.v * self.i)]


class StrayLoad(_LossHeatPort, OnePort, FlangeSupport):
    """Stray load losses, a braking torque that grows with current and speed
    (Modelica.Electrical.Machines.Losses.DCMachines.StrayLoad):

        v = 0,   tau = -tauRef (i/IRef)^2 sign(w) (|w|/wRef)^power_w,   lossPower = -tau w
    """

    strayLoadParameters = StrayLoadParameters()

    def equations(self):
        sp, w = self.strayLoadParameters, self.w
        return [ac.Eq(self.v, 0),
                ac.Eq(self.tau, -sp.tauRef * (self.i / sp.IRef)**2 * ac.sign(w)
                      * (ac.abs(w) / sp.wRef)**sp.power_w),
                ac.Eq(self.lossPower, -self.tau * w)]
