"""Forced movement of a flange by signals that carry their own derivatives
(Modelica.Mechanics.Rotational.Sources.Move, and the Move_w of
Components.AngleToTorqueAdaptor; their translational twins use the same functions).

The angle is imposed as ``phi = position(u, time)``, a function whose derivative
annotation says that d/dt position is u[1] and d2/dt2 position is u[2]
(:mod:`acausal.components.userfunctions`): index reduction, differentiating the
constraint to find the torque, reads the speed and acceleration from the inputs instead
of differentiating the angle signal.  The user guarantees that the signals are
consistent (u[1] the derivative of u[0], u[2] of u[1]); where they are not, the motion
follows each signal at its own level, as in the MSL.
"""
from __future__ import annotations

import acausal as ac
from acausal.ports import RealInput

from .interfaces import PartialElementaryOneFlangeAndSupport

__all__ = ["Move", "position", "position_w"]


@ac.function
def position_der2(q_qd_qdd, dummy, dummy_der, dummy_der2):
    """The acceleration u[2]."""
    return q_qd_qdd[2]


@ac.function(derivative=position_der2, no_derivative=("q_qd_qdd", "dummy_der"))
def position_der(q_qd_qdd, dummy, dummy_der):
    """The speed u[1]; its derivative is the acceleration."""
    return q_qd_qdd[1]


@ac.function(derivative=position_der, no_derivative="q_qd_qdd")
def position(q_qd_qdd, dummy):
    """The position u[0] (``dummy`` is time, the one input to differentiate)."""
    return q_qd_qdd[0]


@ac.function(no_derivative=("q_qd", "dummy_der"))
def position_w_der(q_qd, dummy, dummy_der):
    """The speed u[1] (no acceleration signal: not differentiable further)."""
    return q_qd[1]


@ac.function(derivative=position_w_der, no_derivative="q_qd")
def position_w(q_qd, dummy):
    """The position u[0] of an angle and speed signal."""
    return q_qd[0]


class Move(PartialElementaryOneFlangeAndSupport):
    """Forced movement of a flange according to an angle, speed and angular acceleration
    signal (Modelica.Mechanics.Rotational.Sources.Move):

        phi = flange.phi - phi_support,   phi = position(u, time)
        d/dt position = u[1],   d2/dt2 position = u[2]

    ``u``: three inputs, u[0] the angle, u[1] the speed, u[2] the acceleration of the
    flange relative to the support (the MSL's u[1], u[2], u[3]).
    """

    phi = ac.Variable(unit="rad", description="rotation angle of flange with respect to "
                                              "support")

    energy_role = "source"  # drives the flange from outside the model

    def build(self):
        self.u = [RealInput() for _ in range(3)]

    def equations(self):
        u = [port.signal for port in self.u]
        return [ac.Eq(self.phi, self.flange.phi - self.phi_support()),
                ac.Eq(self.phi, position(u, ac.time))]
