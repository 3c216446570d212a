"""Modelica.Mechanics.MultiBody.Examples.Elementary.RollingWheelSetDriving (MSL v4.0.0):
an axle with two wheels (radius 0.1 m, 0.5 kg, inertia 0.01 kg.m2 about the axle and
0.02 across, 0.5 m apart) carrying a small body (0.01 kg) 0.2 m ahead, driven by the
torques 2 sin(2 pi t) and 2 cos(2 pi t) N.m between each wheel and the axle."""
import math

import acausal as ac
from acausal.library.blocks import Sine
from acausal.library.multibody3d import Body, FixedTranslation, RollingWheelSet, World
from acausal.library.rotational import Torque2

from . import MSLNames

__all__ = ["RollingWheelSetDriving"]


def _fixed(start=0.0):
    return {"start": start, "fixed": True}


class RollingWheelSetDriving(ac.Component):
    """Rolling wheel set that is driven by torques driving the wheels."""

    msl_name = "Modelica.Mechanics.MultiBody.Examples.Elementary.RollingWheelSetDriving"
    stop_time = 3.0
    tolerance = 1e-6
    msl_signals = MSLNames()

    world = World(n_1=0.0, n_2=0.0, n_3=-1.0)
    wheelSet = RollingWheelSet(R_wheel=0.1, m_wheel=0.5, I_wheelAxis=0.01, I_wheelLong=0.02,
                               track=0.5, x=_fixed(0.1), y=_fixed(0.1), phi=_fixed(),
                               theta1=_fixed(), theta2=_fixed(), der_theta1=_fixed(),
                               der_theta2=_fixed())
    body = Body(m=0.01, r_CM_1=0.0, r_CM_2=0.0, r_CM_3=0.0)
    fixedTranslation = FixedTranslation(r_1=0.2, r_2=0.0, r_3=0.0)
    sine1 = Sine(f=1.0, amplitude=2.0)
    sine2 = Sine(f=1.0, amplitude=2.0, phase=math.pi / 2)
    torque1 = Torque2()
    torque2 = Torque2()

    def equations(self):
        return [ac.connect(self.fixedTranslation.frame_a, self.wheelSet.frameMiddle),
                ac.connect(self.fixedTranslation.frame_b, self.body.frame_a),
                ac.connect(self.wheelSet.axis1, self.torque1.flange_a),
                ac.connect(self.torque1.flange_b, self.wheelSet.support),
                ac.connect(self.wheelSet.axis2, self.torque2.flange_a),
                ac.connect(self.wheelSet.support, self.torque2.flange_b),
                ac.connect(self.sine1.y, self.torque1.tau),
                ac.connect(self.sine2.y, self.torque2.tau)]
