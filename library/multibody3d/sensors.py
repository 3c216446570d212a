"""Ideal sensors of spatial multibody systems (Modelica.Mechanics.MultiBody.Sensors).
Absolute sensors take no force or torque from their frame; the cut-force sensor is a
rigid connection that reports what passes through it.  Outputs are resolved as stated
in each class (the MSL's default resolveInFrame)."""
from acausal._sympy import sympy as sp

import acausal as ac
from acausal.ports import RealOutput
from acausal.ports.spatial import Frame

from .frames import angular_velocity2, force, orientation, position, resolve2, torque
from .interfaces import PartialRigidTwoFrames, PartialTwoFrames, equal, propagate

__all__ = ["AbsolutePosition", "AbsoluteVelocity", "AbsoluteAngularVelocity",
           "RelativePosition", "CutForceAndTorque"]


class _AbsoluteSensor(ac.Component):
    frame_a = Frame()
    energy_role = "lossless"  # takes no power

    def _free(self):
        zero = sp.zeros(3, 1)
        return [*equal(force(self.frame_a), zero), *equal(torque(self.frame_a), zero)]


def _outputs(c, name):
    return sp.Matrix([p.signal for p in getattr(c, name)])


def _three():
    return [RealOutput() for _ in range(3)]


class AbsolutePosition(_AbsoluteSensor):
    """r = r_0 of frame_a, in world coordinates (MSL Sensors.AbsolutePosition,
    resolveInFrame = world); outputs r[0..2]."""

    def build(self):
        self.r = _three()

    def equations(self):
        return [*self._free(), *equal(_outputs(self, "r"), position(self.frame_a))]


class AbsoluteVelocity(_AbsoluteSensor):
    """v = der(r_0) of frame_a, in world coordinates (MSL Sensors.AbsoluteVelocity,
    resolveInFrame = world); outputs v[0..2]."""

    def build(self):
        self.v = _three()

    def equations(self):
        return [*self._free(),
                *equal(_outputs(self, "v"), position(self.frame_a).applyfunc(ac.der))]


class AbsoluteAngularVelocity(_AbsoluteSensor):
    """w of frame_a, resolved in frame_a (MSL Sensors.AbsoluteAngularVelocity,
    resolveInFrame = frame_a): skew(w) = -der(R) R^T; outputs w[0..2]."""

    def build(self):
        self.w = _three()

    def equations(self):
        R = orientation(self.frame_a)
        return [*self._free(),
                *equal(_outputs(self, "w"), angular_velocity2(R, R.applyfunc(ac.der)))]


class RelativePosition(PartialTwoFrames):
    """r_rel = R_a (r_0,b - r_0,a): frame_b's origin from frame_a's, resolved in
    frame_a (MSL Sensors.RelativePosition, resolveInFrame = frame_a); outputs
    r_rel[0..2].  Takes no force."""

    energy_role = "lossless"

    def build(self):
        self.r_rel = _three()

    def equations(self):
        a, b = self.frame_a, self.frame_b
        zero = sp.zeros(3, 1)
        return [*equal(force(a), zero), *equal(torque(a), zero),
                *equal(force(b), zero), *equal(torque(b), zero),
                *equal(_outputs(self, "r_rel"),
                       resolve2(orientation(a), position(b) - position(a)))]


class CutForceAndTorque(PartialRigidTwoFrames):
    """A rigid connection of frame_a and frame_b that reports the cut force and torque
    acting on frame_a, resolved in frame_a (MSL Sensors.CutForceAndTorque,
    resolveInFrame = frame_a; the MSL measures at frame_a as well):

        r_0,b = r_0,a,   R_b = R_a,   f_a + f_b = 0,   t_a + t_b = 0,
        force = f_a,   torque = t_a

    Outputs force[0..2] and torque[0..2].
    """

    energy_role = "lossless"

    def build(self):
        self.force, self.torque = _three(), _three()

    def equations(self):
        a, b = self.frame_a, self.frame_b
        return [*equal(position(b), position(a)), *propagate(a, b),
                *equal(force(a), -force(b)), *equal(torque(a), -torque(b)),
                *equal(_outputs(self, "force"), force(a)),
                *equal(_outputs(self, "torque"), torque(a))]
