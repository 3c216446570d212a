"""Force, speed and position sources (Modelica.Mechanics.Translational.Sources).

A force source pushes its flange in +s with ``flange.f = -f``; speed and position
sources impose the motion of their flange and take whatever force that needs.  Every
source acts against its housing: ``useSupport=True`` gives it a ``support`` flange that
takes the reaction (support.f = -flange.f), and its position and speed are then
relative to the support.  Without it the housing is fixed.
"""
import acausal as ac
from acausal.ports import RealInput

from ..blocks import signals
from .interfaces import PartialElementaryOneFlangeAndSupport

__all__ = ["ConstantForce", "StepForce", "Force", "ConstantSpeed", "Speed", "Position"]


class ConstantForce(PartialElementaryOneFlangeAndSupport):
    """Constant force pushing the flange in +s:  flange.f = -f_constant."""

    f_constant = ac.Parameter(1.0, unit="N", description="driving force")

    energy_role = "source"  # drives the flange from outside the model

    def equations(self):
        return [*super().equations(), ac.Eq(self.flange.f, -self.f_constant)]


class StepForce(PartialElementaryOneFlangeAndSupport):
    """Force step:  flange.f = -(offsetForce + (stepForce if time >= startTime else 0))."""

    stepForce = ac.Parameter(1.0, unit="N", description="height of the step")
    offsetForce = ac.Parameter(0.0, unit="N", description="force before the step")
    startTime = ac.Parameter(0.0, unit="s", description="time of the step")

    energy_role = "source"  # drives the flange from outside the model

    def equations(self):
        f = self.offsetForce + signals.step(self.stepForce, self.startTime)
        return [*super().equations(), ac.Eq(self.flange.f, -f)]


class Force(PartialElementaryOneFlangeAndSupport):
    """Force set by a signal:  flange.f = -f."""

    f = RealInput()

    energy_role = "source"  # drives the flange from outside the model

    def equations(self):
        return [*super().equations(), ac.Eq(self.flange.f, -self.f)]


class _SpeedSource(PartialElementaryOneFlangeAndSupport):
    """The flange's position s relative to the support (a state) and its speed
    v = der(s)."""

    s = ac.Variable(start=0.0, unit="m", description="position of the flange (to support)")
    v = ac.Variable(unit="m/s", description="speed of the flange (to support)")

    energy_role = "source"  # drives the flange from outside the model

    def equations(self):
        return [*super().equations(), ac.Eq(self.s, self.flange.s - self.s_support()),
                ac.Eq(self.v, ac.der(self.s))]


class ConstantSpeed(_SpeedSource):
    """Flange moving at constant speed:  der(flange.s - s_support) = v_fixed."""

    v_fixed = ac.Parameter(1.0, unit="m/s", description="imposed speed")

    def equations(self):
        return [*super().equations(), ac.Eq(self.v, self.v_fixed)]


class Speed(_SpeedSource):
    """Flange speed set by a signal:  der(flange.s - s_support) = v_ref."""

    v_ref = RealInput()

    def equations(self):
        return [*super().equations(), ac.Eq(self.v, self.v_ref)]


class Position(PartialElementaryOneFlangeAndSupport):
    """Flange position set by a signal:  flange.s - s_support = s_ref.

    Driving a mass, this differentiates s_ref twice (index reduction): the signal must
    be twice differentiable in the model.
    """

    s_ref = RealInput()

    energy_role = "source"  # drives the flange from outside the model

    def equations(self):
        return [*super().equations(), ac.Eq(self.flange.s - self.s_support(), self.s_ref)]
