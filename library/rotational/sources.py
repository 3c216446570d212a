"""Torque, speed and angle sources (Modelica.Mechanics.Rotational.Sources).

A torque source drives its flange with ``flange.tau = -tau`` (the cut torque into the
source is minus the torque it exerts).  Speed and angle sources impose the motion of
their flange and take whatever torque that needs.
"""
import acausal as ac
from acausal.ports import RealInput

from ..blocks import signals
from .interfaces import PartialElementaryOneFlange

__all__ = ["ConstantTorque", "StepTorque", "Torque", "ConstantSpeed", "Speed", "Position"]


class ConstantTorque(PartialElementaryOneFlange):
    """Constant torque driving the flange:  flange.tau = -tau_constant.

    (A positive torque accelerates the flange in the positive direction; the cut torque
    into the source is its negative.)
    """

    tau_constant = ac.Parameter(1.0, unit="N.m", description="driving torque")

    energy_role = "source"  # drives the flange from outside the model

    def equations(self):
        return [ac.Eq(self.flange.tau, -self.tau_constant)]


class StepTorque(PartialElementaryOneFlange):
    """Torque step:  flange.tau = -(offsetTorque + (stepTorque if time >= startTime))."""

    stepTorque = ac.Parameter(1.0, unit="N.m", description="height of the step")
    offsetTorque = ac.Parameter(0.0, unit="N.m", description="torque before the step")
    startTime = ac.Parameter(0.0, unit="s", description="time of the step")

    energy_role = "source"  # drives the flange from outside the model

    def equations(self):
        tau = self.offsetTorque + signals.step(self.stepTorque, self.startTime)
        return [ac.Eq(self.flange.tau, -tau)]


class Torque(PartialElementaryOneFlange):
    """Torque set by a signal:  flange.tau = -tau."""

    tau = RealInput()

    energy_role = "source"  # drives the flange from outside the model

    def equations(self):
        return [ac.Eq(self.flange.tau, -self.tau)]


class _SpeedSource(PartialElementaryOneFlange):
    """The flange's angle phi (a state) and speed w = der(phi)."""

    phi = ac.Variable(start=0.0, unit="rad", description="angle of the flange")
    w = ac.Variable(unit="rad/s", description="speed of the flange")

    energy_role = "source"  # drives the flange from outside the model

    def equations(self):
        return [ac.Eq(self.phi, self.flange.phi), ac.Eq(self.w, ac.der(self.phi))]


class ConstantSpeed(_SpeedSource):
    """Flange turning at constant speed:  der(flange.phi) = w_fixed."""

    w_fixed = ac.Parameter(1.0, unit="rad/s", description="imposed speed")

    def equations(self):
        return [ac.Eq(self.w, self.w_fixed)]


class Speed(_SpeedSource):
    """Flange speed set by a signal:  der(flange.phi) = w_ref."""

    w_ref = RealInput()

    def equations(self):
        return [ac.Eq(self.w, self.w_ref)]


class Position(PartialElementaryOneFlange):
    """Flange angle set by a signal:  flange.phi = phi_ref.

    Driving an inertia, this differentiates phi_ref twice (index reduction), so the
    signal must be twice differentiable in the model (a Sine, or a filtered reference);
    a step makes the torque impulsive.
    """

    phi_ref = RealInput()

    energy_role = "source"  # drives the flange from outside the model

    def equations(self):
        return [ac.Eq(self.flange.phi, self.phi_ref)]
