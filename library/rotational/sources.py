"""Torque, speed and angle sources (Modelica.Mechanics.Rotational.Sources).

A torque source drives its flange with ``flange.tau = -tau`` (the cut torque into the
source is minus the torque it exerts).  Speed and angle sources impose the motion of
their flange and take whatever torque that needs.  Every source acts against its
housing: ``useSupport=True`` gives it a ``support`` flange that takes the reaction
(support.tau = -flange.tau; a motor on a moving frame), and its speed and angle are
then relative to the support.  Without it the housing is fixed.
"""
import acausal as ac
from acausal.ports import RealInput

from ..blocks import signals
from .interfaces import PartialElementaryOneFlangeAndSupport

__all__ = ["ConstantTorque", "StepTorque", "Torque", "ConstantSpeed", "Speed", "Position"]


class ConstantTorque(PartialElementaryOneFlangeAndSupport):
    """Constant torque driving the flange:  flange.tau = -tau_constant.

    (A positive torque accelerates the flange in the positive direction; the cut torque
    into the source is its negative.)
    """

    tau_constant = ac.Parameter(1.0, unit="N.m", description="driving torque")

    energy_role = "source"  # drives the flange from outside the model

    def equations(self):
        return [*super().equations(), ac.Eq(self.flange.tau, -self.tau_constant)]


class StepTorque(PartialElementaryOneFlangeAndSupport):
    """Torque step:  flange.tau = -(offsetTorque + (stepTorque if time >= startTime))."""

    stepTorque = ac.Parameter(1.0, unit="N.m", description="height of the step")
    offsetTorque = ac.Parameter(0.0, unit="N.m", description="torque before the step")
    startTime = ac.Parameter(0.0, unit="s", description="time of the step")

    energy_role = "source"  # drives the flange from outside the model

    def equations(self):
        tau = self.offsetTorque + signals.step(self.stepTorque, self.startTime)
        return [*super().equations(), ac.Eq(self.flange.tau, -tau)]


class Torque(PartialElementaryOneFlangeAndSupport):
    """Torque set by a signal:  flange.tau = -tau."""

    tau = RealInput()

    energy_role = "source"  # drives the flange from outside the model

    def equations(self):
        return [*super().equations(), ac.Eq(self.flange.tau, -self.tau)]


class _SpeedSource(PartialElementaryOneFlangeAndSupport):
    """The flange's angle phi relative to the support (a state) and its speed
    w = der(phi)."""

    phi = ac.Variable(start=0.0, unit="rad", description="angle of the flange (to support)")
    w = ac.Variable(unit="rad/s", description="speed of the flange (to support)")

    energy_role = "source"  # drives the flange from outside the model

    def equations(self):
        return [*super().equations(), ac.Eq(self.phi, self.flange.phi - self.phi_support()),
                ac.Eq(self.w, ac.der(self.phi))]


class ConstantSpeed(_SpeedSource):
    """Flange turning at constant speed:  der(flange.phi - phi_support) = w_fixed."""

    w_fixed = ac.Parameter(1.0, unit="rad/s", description="imposed speed")

    def equations(self):
        return [*super().equations(), ac.Eq(self.w, self.w_fixed)]


class Speed(_SpeedSource):
    """Flange speed set by a signal:  der(flange.phi - phi_support) = w_ref."""

    w_ref = RealInput()

    def equations(self):
        return [*super().equations(), ac.Eq(self.w, self.w_ref)]


class Position(PartialElementaryOneFlangeAndSupport):
    """Flange angle set by a signal:  flange.phi - phi_support = phi_ref.

    Driving an inertia, this differentiates phi_ref twice (index reduction), so the
    signal must be twice differentiable in the model (a Sine, or a filtered reference);
    a step makes the torque impulsive.
    """

    phi_ref = RealInput()

    energy_role = "source"  # drives the flange from outside the model

    def equations(self):
        return [*super().equations(),
                ac.Eq(self.flange.phi - self.phi_support(), self.phi_ref)]
