"""Modelica.Mechanics.MultiBody.Examples.Elementary.RollingWheelSetPulling (MSL v4.0.0):
the axle of ``RollingWheelSetDriving`` pulled at the small body by a force given in the
world by a table: (1, 0, 0) N for a second, turning to (0, 2, 0) N over the next."""
import acausal as ac
from acausal.library.blocks import CombiTimeTable
from acausal.library.multibody3d import (Body, FixedTranslation, RollingWheelSet, World,
                                         WorldForce)

from . import MSLNames

__all__ = ["RollingWheelSetPulling"]


def _fixed(start=0.0):
    return {"start": start, "fixed": True}


class RollingWheelSetPulling(ac.Component):
    """Rolling wheel set that is pulled by a force."""

    msl_name = "Modelica.Mechanics.MultiBody.Examples.Elementary.RollingWheelSetPulling"
    stop_time = 3.0
    tolerance = 1e-6
    msl_signals = MSLNames()

    force = WorldForce()
    world = World(n_1=0.0, n_2=0.0, n_3=-1.0)
    wheelSet = RollingWheelSet(R_wheel=0.1, m_wheel=0.5, I_wheelAxis=0.01, I_wheelLong=0.02,
                               track=0.5, x=_fixed(0.1), y=_fixed(0.1), phi=_fixed(),
                               theta1=_fixed(), theta2=_fixed(), der_theta1=_fixed(),
                               der_theta2=_fixed())
    body = Body(m=0.01, r_CM_1=0.0, r_CM_2=0.0, r_CM_3=0.0)
    combiTimeTable = CombiTimeTable(table=[[0, 1, 0, 0], [1, 1, 0, 0], [2, 0, 2, 0],
                                           [3, 0, 2, 0]], extrapolation="last_two_points")
    fixedTranslation = FixedTranslation(r_1=0.2, r_2=0.0, r_3=0.0)

    def equations(self):
        return [*(ac.connect(y, f) for y, f in zip(self.combiTimeTable.y, self.force.force)),
                ac.connect(self.fixedTranslation.frame_a, self.wheelSet.frameMiddle),
                ac.connect(self.fixedTranslation.frame_b, self.body.frame_a),
                ac.connect(self.force.frame_b, self.fixedTranslation.frame_b)]
