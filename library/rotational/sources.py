"""Torque sources (Modelica.Mechanics.Rotational.Sources)."""
import acausal as ac

from .interfaces import PartialElementaryOneFlange

__all__ = ["ConstantTorque"]


class ConstantTorque(PartialElementaryOneFlange):
    """Constant torque driving the flange:  flange.tau = -tau_constant.

    (A positive torque accelerates the flange in the positive direction; the cut torque
    into the source is its negative.)
    """

    tau_constant = ac.Parameter(1.0, unit="N.m", description="driving torque")

    def equations(self):
        return [ac.Eq(self.flange.tau, -self.tau_constant)]
