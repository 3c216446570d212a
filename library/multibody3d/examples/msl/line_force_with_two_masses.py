"""Modelica.Mechanics.MultiBody.Examples.Elementary.LineForceWithTwoMasses (MSL v4.0.0):
two pendulums (steel boxes 0.7 m long on revolute joints about z), each damped by a
rod from a fixed point below it: the first rod a JointUPS carrying two point masses of
1 kg (0.2 m from each end, on frame_ia and frame_ib) with a 1-D damper (3 N.s/m) on its
flanges, the second a LineForceWithTwoMasses with the same masses and damper.  The two
pendulums move alike."""
import numpy as np

import acausal as ac
from acausal.library.multibody3d import (Body, BodyBox, FixedTranslation, JointUPS,
                                         LineForceWithTwoMasses, Revolute, World)
from acausal.library.translational import Damper

from . import MSLNames

__all__ = ["LineForceWithTwoMasses"]

_N_AXIS_IA = np.array([0.7, 1.2, 0.0])
_E_AXIS_IA = _N_AXIS_IA / np.linalg.norm(_N_AXIS_IA)     # jointUPS.eAxis_ia


def _mass_on_rod(sign):
    r_CM = sign * 0.2 * _E_AXIS_IA
    return Body(m=ac.ref("m"), r_CM_1=r_CM[0], r_CM_2=r_CM[1], r_CM_3=r_CM[2],
                I_11=0.0, I_22=0.0, I_33=0.0)


def _bar(x, y, z):
    return FixedTranslation(r_1=x, r_2=y, r_3=z)


class LineForceWithTwoMasses(ac.Component):
    """Demonstrate a line force with two point masses using a JointUPS and alternatively
    a LineForceWithTwoMasses component."""

    msl_name = "Modelica.Mechanics.MultiBody.Examples.Elementary.LineForceWithTwoMasses"
    stop_time = 3.0
    tolerance = 1e-6
    msl_signals = MSLNames()

    m = ac.Parameter(1.0, unit="kg", description="mass of the point masses")
    rod_f_diff = ac.Variable(shape=3, unit="N",
                             description="difference of the cut forces in rod1 and rod3")
    body_f_diff = ac.Variable(shape=3, unit="N", description="difference of the cut forces "
                                                              "in bodyBox1 and bodyBox2")
    world = World()
    revolute1 = Revolute(phi={"fixed": True}, w={"fixed": True})
    bodyBox1 = BodyBox(r_1=0.7, r_2=0.0, r_3=0.0)
    rod1 = _bar(0.0, -0.9, 0.0)
    jointUPS = JointUPS(nAxis_ia_1=_N_AXIS_IA[0], nAxis_ia_2=_N_AXIS_IA[1],
                        nAxis_ia_3=_N_AXIS_IA[2])
    body1 = _mass_on_rod(+1)
    body2 = _mass_on_rod(-1)
    rod2 = _bar(0.0, 0.3, 0.0)
    damper1 = Damper(d=3.0)
    revolute2 = Revolute(phi={"fixed": True}, w={"fixed": True})
    bodyBox2 = BodyBox(r_1=0.7, r_2=0.0, r_3=0.0)
    rod3 = _bar(0.0, -0.9, 0.3)
    rod4 = _bar(0.0, 0.3, 0.3)
    damper2 = Damper(d=3.0)
    lineForceWithTwoMasses = LineForceWithTwoMasses(L_a=0.2, L_b=0.2, m_a=ac.ref("m"),
                                                    m_b=ac.ref("m"))

    def equations(self):
        f = lambda frame: [frame.fx, frame.fy, frame.fz]     # noqa: E731
        return [*(ac.Eq(d, p - q) for d, p, q in zip(self.rod_f_diff, f(self.rod1.frame_b),
                                                      f(self.rod3.frame_b))),
                *(ac.Eq(d, p - q) for d, p, q in zip(self.body_f_diff,
                                                      f(self.bodyBox1.frame_b),
                                                      f(self.bodyBox2.frame_b))),
                ac.connect(self.jointUPS.bearing, self.damper1.flange_a),
                ac.connect(self.jointUPS.axis, self.damper1.flange_b),
                ac.connect(self.jointUPS.frame_ib, self.body2.frame_a),
                ac.connect(self.world.frame_b, self.rod2.frame_a),
                ac.connect(self.world.frame_b, self.rod1.frame_a),
                ac.connect(self.rod2.frame_b, self.revolute1.frame_a),
                ac.connect(self.revolute1.frame_b, self.bodyBox1.frame_a),
                ac.connect(self.bodyBox1.frame_b, self.jointUPS.frame_b),
                ac.connect(self.body1.frame_a, self.jointUPS.frame_ia),
                ac.connect(self.rod1.frame_b, self.jointUPS.frame_a),
                ac.connect(self.rod4.frame_b, self.revolute2.frame_a),
                ac.connect(self.revolute2.frame_b, self.bodyBox2.frame_a),
                ac.connect(self.world.frame_b, self.rod4.frame_a),
                ac.connect(self.rod3.frame_a, self.rod4.frame_a),
                ac.connect(self.lineForceWithTwoMasses.frame_a, self.rod3.frame_b),
                ac.connect(self.lineForceWithTwoMasses.frame_b, self.bodyBox2.frame_b),
                ac.connect(self.lineForceWithTwoMasses.flange_b, self.damper2.flange_b),
                ac.connect(self.lineForceWithTwoMasses.flange_a, self.damper2.flange_a)]
