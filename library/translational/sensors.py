"""Translational sensors (Modelica.Mechanics.Translational.Sensors): ideal, they do no work."""
import acausal as ac
from acausal.ports import RealOutput

from .interfaces import PartialAbsoluteSensor, PartialRelativeSensor

__all__ = ["PositionSensor", "SpeedSensor", "AccSensor", "RelPositionSensor",
           "RelSpeedSensor", "RelAccSensor", "ForceSensor", "PowerSensor", "MultiSensor"]


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


class AccSensor(PartialAbsoluteSensor):
    """v = der(flange.s),  a = der(v)."""

    a = RealOutput()
    v = ac.Variable(unit="m/s", description="speed of the flange")

    def equations(self):
        return [ac.Eq(self.v, ac.der(self.flange.s)),
                ac.Eq(self.a, ac.der(self.v))]


class RelPositionSensor(PartialRelativeSensor):
    """s_rel = flange_b.s - flange_a.s, with no force:  flange_a.f = 0."""

    s_rel = RealOutput()

    def equations(self):
        return [ac.Eq(self.flange_a.f, 0),
                ac.Eq(self.s_rel, self.flange_b.s - self.flange_a.s)]


class RelSpeedSensor(PartialRelativeSensor):
    """v_rel = der(flange_b.s - flange_a.s), with no force:  flange_a.f = 0."""

    v_rel = RealOutput()

    def equations(self):
        return [ac.Eq(self.flange_a.f, 0),
                ac.Eq(self.v_rel, ac.der(self.flange_b.s - self.flange_a.s))]


class RelAccSensor(PartialRelativeSensor):
    """v_rel = der(flange_b.s - flange_a.s),  a_rel = der(v_rel), with no force:
    flange_a.f = 0."""

    a_rel = RealOutput()
    v_rel = ac.Variable(unit="m/s", description="relative speed")

    def equations(self):
        return [ac.Eq(self.flange_a.f, 0),
                ac.Eq(self.v_rel, ac.der(self.flange_b.s - self.flange_a.s)),
                ac.Eq(self.a_rel, ac.der(self.v_rel))]


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


class MultiSensor(PartialRelativeSensor):
    """Force, velocity and power at one place of a rigid line (MSL Translational
    Sensors.MultiSensor), put in series:

        flange_a.s = flange_b.s,   f = flange_a.f,   v = der(flange_a.s),   power = f v
    """

    power = RealOutput()
    f = RealOutput()
    v = RealOutput()

    def equations(self):
        return [ac.Eq(self.flange_a.s, self.flange_b.s),
                ac.Eq(self.f, self.flange_a.f),
                ac.Eq(self.v, ac.der(self.flange_a.s)),
                ac.Eq(self.power, self.f * self.v)]
