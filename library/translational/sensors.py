"""Translational sensors (Modelica.Mechanics.Translational.Sensors): ideal, they do no work."""
import acausal as ac
from acausal.ports import RealOutput

from .interfaces import PartialAbsoluteSensor, PartialRelativeSensor

__all__ = ["PositionSensor", "SpeedSensor", "RelPositionSensor", "ForceSensor",
           "PowerSensor"]


class PositionSensor(PartialAbsoluteSensor):
    """s = flange.s."""

    s = RealOutput()

    def equations(self):
        return [ac.Eq(self.s, self.flange.s)]


class SpeedSensor(PartialAbsoluteSensor):
    """v = der(flange.s)."""

    v = RealOutput()

    def equations(self):
        return [ac.Eq(self.v, ac.der(self.flange.s))]


class RelPositionSensor(PartialRelativeSensor):
    """s_rel = flange_b.s - flange_a.s, with no force:  flange_a.f = 0."""

    s_rel = RealOutput()

    def equations(self):
        return [ac.Eq(self.flange_a.f, 0),
                ac.Eq(self.s_rel, self.flange_b.s - self.flange_a.s)]


class ForceSensor(PartialRelativeSensor):
    """Force transmitted from flange_a to flange_b (in series, rigid):

        flange_a.s = flange_b.s,   f = flange_a.f
    """

    f = RealOutput()

    def equations(self):
        return [ac.Eq(self.flange_a.s, self.flange_b.s),
                ac.Eq(self.f, self.flange_a.f)]


class PowerSensor(PartialRelativeSensor):
    """Power transmitted from flange_a to flange_b (in series, rigid):

        flange_a.s = flange_b.s,   power = flange_a.f der(flange_a.s)
    """

    power = RealOutput()

    def equations(self):
        return [ac.Eq(self.flange_a.s, self.flange_b.s),
                ac.Eq(self.power, self.flange_a.f * ac.der(self.flange_a.s))]
