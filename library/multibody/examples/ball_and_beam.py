"""Ball and beam (Egeland & Gravdahl 7.4, (7.107)-(7.143)).

A beam with inertia J_1 about its pivot is turned by a motor torque T; a ball of mass
m_2, radius R and inertia J_2 = (2/5) m_2 R^2 (7.118) rolls without slipping in a
track on the beam, its centre at distance x along the beam and R above it:

    (J_1 + m_2 x^2) theta'' = T + m_2 g x cos(theta) - 2 m_2 x theta' x'
                              - m_2 theta'^2 x R                          (7.133)
    (J_2 + m_2 R^2) (theta'' + x''/R) = m_2 R x theta'^2 + R m_2 g sin(theta)   (7.134)

with J_2 + m_2 R^2 = (7/5) m_2 R^2 (7.127); for small angles x'' = (5/7) g theta
(7.142), and the energy (7.135) changes as V' = theta' T (7.136).

Assembly: a Revolute (pivot, driven through its flange) and a Body (the beam, its
centre of mass at the pivot); a FixedTranslation R up to the line of the ball's
centre; a Prismatic along the beam (x); a Revolute for the ball's rotation relative
to the beam and a Body (the ball).  Rolling, x' = -R (ball's rotation relative to the
beam)', is an IdealGearR2T between the two joints' flanges, its force the friction
that makes the ball roll.  The book's theta and T are about an axis into the page,
so theta = -``pivot.phi`` and x = ``track.s``.
"""
import numpy as np

import acausal as ac
from acausal.library.blocks import Sine
from acausal.library.multibody import Body, FixedFrame, FixedTranslation, Prismatic, Revolute
from acausal.library.rotational import IdealGearR2T, Torque

__all__ = ["BallAndBeam"]


class BallAndBeam(ac.Component):
    """Beam tilted to theta = 0.1 rad (its +x end low), ball at rest at the pivot;
    torque T = 0.05 sin(2 pi 0.5 t) N m about the book's axis.

    J_1 = 0.05 kg m^2, m_2 = 0.1 kg, R = 0.02 m.
    """

    stop_time = 1.0
    J_1 = ac.Parameter(0.05, unit="kg.m2", description="beam inertia about the pivot")
    m_2 = ac.Parameter(0.1, unit="kg", description="ball mass")
    R = ac.Parameter(0.02, unit="m", description="ball radius")
    J_2 = ac.Parameter(lambda c: 2 * c.m_2 * c.R**2 / 5, unit="kg.m2",
                       description="ball inertia (7.118)")
    rolling_ratio = ac.Parameter(lambda c: -1 / c.R, unit="rad/m",
                                 description="ball's relative angle per unit travel")
    # the source turns the beam about +z, the book's T is about -z
    torque_signal = Sine(amplitude=-0.05, f=0.5)
    motor = Torque()
    world = FixedFrame()
    pivot = Revolute(phi={"start": -0.1, "fixed": True}, w={"start": 0.0, "fixed": True})
    beam = Body(m=1.0, J=ac.ref("J_1"))
    track_offset = FixedTranslation(rx=0.0, ry=ac.ref("R"))
    track = Prismatic(ex=1.0, ey=0.0, s={"start": 0.0, "fixed": True},
                      v={"start": 0.0, "fixed": True})
    # the ball's rotation follows from x by rolling: leave the book's theta, x as states
    ball_joint = Revolute(phi={"state_select": "default"}, w={"state_select": "default"})
    ball = Body(m=ac.ref("m_2"), J=ac.ref("J_2"))
    rolling = IdealGearR2T(ratio=ac.ref("rolling_ratio"))

    def equations(self):
        return [ac.connect(self.torque_signal.y, self.motor.tau),
                ac.connect(self.motor.flange, self.pivot.flange),
                ac.connect(self.world.frame, self.pivot.frame_a),
                ac.connect(self.pivot.frame_b, self.beam.frame, self.track_offset.frame_a),
                ac.connect(self.track_offset.frame_b, self.track.frame_a),
                ac.connect(self.track.frame_b, self.ball_joint.frame_a),
                ac.connect(self.ball_joint.frame_b, self.ball.frame),
                ac.connect(self.ball_joint.flange, self.rolling.flangeR),
                ac.connect(self.track.flange, self.rolling.flangeT)]


if __name__ == "__main__":
    compiled = ac.compile(BallAndBeam())
    print(compiled.report)
    res = ac.simulate(compiled, t_end=BallAndBeam.stop_time, rtol=1e-8)
    print(f"x(t_end) = {res['track.s'][-1]:.5f} m, theta(t_end) = "
          f"{-res['pivot.phi'][-1]:.5f} rad, x''(0) = {res['track.a'][0]:.6f} m/s2 "
          f"(5/7 g theta0 = {5 / 7 * 9.81 * 0.1:.6f})")
