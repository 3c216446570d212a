"""Rotational sensors (Modelica.Mechanics.Rotational.Sensors): ideal, they do no work."""
import acausal as ac
from acausal.ports import RealOutput

from .interfaces import PartialAbsoluteSensor, PartialRelativeSensor

__all__ = ["AngleSensor", "SpeedSensor", "AccSensor", "RelAngleSensor", "RelSpeedSensor",
           "RelAccSensor", "TorqueSensor", "PowerSensor", "MultiSensor"]


class AngleSensor(PartialAbsoluteSensor):
    """phi = flange.phi."""

    phi = RealOutput()

    def equations(self):
        return [ac.Eq(self.phi, self.flange.phi)]


class SpeedSensor(PartialAbsoluteSensor):
    """w = der(flange.phi)."""

    w = RealOutput()

    def equations(self):
        return [ac.Eq(self.w, ac.der(self.flange.phi))]


class AccSensor(PartialAbsoluteSensor):
    """w = der(flange.phi),  a = der(w)."""

    a = RealOutput()
    w = ac.Variable(unit="rad/s", description="speed of the flange")

    def equations(self):
        return [ac.Eq(self.w, ac.der(self.flange.phi)),
                ac.Eq(self.a, ac.der(self.w))]


class RelAngleSensor(PartialRelativeSensor):
    """phi_rel = flange_b.phi - flange_a.phi, with no torque:  flange_a.tau = 0."""

    phi_rel = RealOutput()

    def equations(self):
        return [ac.Eq(self.flange_a.tau, 0),
                ac.Eq(self.phi_rel, self.flange_b.phi - self.flange_a.phi)]


class RelSpeedSensor(PartialRelativeSensor):
    """w_rel = der(flange_b.phi - flange_a.phi), with no torque:  flange_a.tau = 0."""

    w_rel = RealOutput()

    def equations(self):
        return [ac.Eq(self.flange_a.tau, 0),
                ac.Eq(self.w_rel, ac.der(self.flange_b.phi - self.flange_a.phi))]


class RelAccSensor(PartialRelativeSensor):
    """w_rel = der(flange_b.phi - flange_a.phi),  a_rel = der(w_rel), with no torque:
    flange_a.tau = 0."""

    a_rel = RealOutput()
    w_rel = ac.Variable(unit="rad/s", description="relative speed")

    def equations(self):
        return [ac.Eq(self.flange_a.tau, 0),
                ac.Eq(self.w_rel, ac.der(self.flange_b.phi - self.flange_a.phi)),
                ac.Eq(self.a_rel, ac.der(self.w_rel))]


class TorqueSensor(PartialRelativeSensor):
    """Torque transmitted from flange_a to flange_b (put in series, rigid):

        flange_a.phi = flange_b.phi,   tau = flange_a.tau
    """

    tau = RealOutput()

    def equations(self):
        return [ac.Eq(self.flange_a.phi, self.flange_b.phi),
                ac.Eq(self.tau, self.flange_a.tau)]


class PowerSensor(PartialRelativeSensor):
    """Power transmitted from flange_a to flange_b (put in series, rigid):

        flange_a.phi = flange_b.phi,   power = flange_a.tau der(flange_a.phi)
    """

    power = RealOutput()

    def equations(self):
        return [ac.Eq(self.flange_a.phi, self.flange_b.phi),
                ac.Eq(self.power, self.flange_a.tau * ac.der(self.flange_a.phi))]


class MultiSensor(PartialRelativeSensor):
    """Torque, speed and power at one place of a shaft (MSL Sensors.MultiSensor), put in
    series, rigid:

        flange_a.phi = flange_b.phi,   tau = flange_a.tau,   w = der(flange_a.phi),
        power = tau w
    """

    tau = RealOutput()
    w = RealOutput()
    power = RealOutput()

    def equations(self):
        return [ac.Eq(self.flange_a.phi, self.flange_b.phi),
                ac.Eq(self.tau, self.flange_a.tau),
                ac.Eq(self.w, ac.der(self.flange_a.phi)),
                ac.Eq(self.power, self.tau * self.w)]
