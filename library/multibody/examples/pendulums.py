"""Pendulums assembled from joints, bars and bodies (the DAE notes, 000 sections 3.2-3.4;
the same systems as raw Cartesian equations are in ``acausal.library.examples.pendulum``).

Each link is a Revolute, a massless FixedTranslation of length L pointing down at
phi = 0, and a point mass (Body with J = 0) at its end, so a joint angle is measured
from the downward vertical and the absolute angle of link i is the sum of the first i
joint angles.  The bars fix the bodies' positions as functions of the angles: index 3;
the two bar equations of every link, and the angle relation of every joint after the
first, are differentiated twice; the joint angles and speeds are the states (a static choice, valid through the vertical and through full turns, where the
hand-reduced Cartesian form of 000 section 3.5 is singular).

* ``SinglePendulum``: one link, released at 0.5 rad.
* ``DoublePendulum``: two links, released at 0.5 rad and 0.4 rad relative (0.9 absolute).
* ``PendulumChain(n)``: n such links, released straight out horizontally (joint 1 at
  pi/2, the others at 0).
* ``PointMassChain(n)``: the n-mass pendulum of 000 section 3.4 in its own form: point
  masses on rigid rods, one distance constraint per rod (3.2.4), differentiated twice;
  the masses' Cartesian coordinates are the only candidates for states, and which of
  x_i, y_i is a state must change as the rods turn: dynamic state selection.
"""
import numpy as np

import acausal as ac
from acausal.library.multibody import (Body, FixedFrame, FixedTranslation, PartialTwoFrames,
                                      PointMass, Revolute, Rod)

__all__ = ["Link", "SinglePendulum", "DoublePendulum", "PendulumChain", "PointMassChain"]


class Link(PartialTwoFrames):
    """A revolute joint, a massless bar of length L and a point mass m at its end:

        frame_a --Revolute(phi)-- bar (0, -L) --> mass m at frame_b
    """

    L = ac.Parameter(1.0, unit="m", min=0, description="bar length")
    L_down = ac.Parameter(lambda c: -c.L, unit="m", description="y of the bar's end, -L")
    m = ac.Parameter(1.0, unit="kg", min=0, description="point mass at the end")
    g = ac.Parameter(9.81, unit="m/s2", description="gravity, acting in -y")
    joint = Revolute()
    bar = FixedTranslation(rx=0.0, ry=ac.ref("L_down"))
    mass = Body(m=ac.ref("m"), J=0.0, g=ac.ref("g"))

    def equations(self):
        return [ac.connect(self.frame_a, self.joint.frame_a),
                ac.connect(self.joint.frame_b, self.bar.frame_a),
                ac.connect(self.bar.frame_b, self.mass.frame, self.frame_b)]


class SinglePendulum(ac.Component):
    """Point mass 1 kg on a 1 m bar, released at rest at 0.5 rad."""

    stop_time = 10.0
    world = FixedFrame()
    link = Link(joint={"phi": {"start": 0.5, "fixed": True}, "w": {"start": 0.0, "fixed": True}})

    def equations(self):
        return [ac.connect(self.world.frame, self.link.frame_a)]


class DoublePendulum(ac.Component):
    """Two 1 kg point masses on 1 m bars, released at rest at absolute angles 0.5 rad
    and 0.9 rad (joint angles 0.5 and 0.4)."""

    stop_time = 10.0
    world = FixedFrame()
    link1 = Link(joint={"phi": {"start": 0.5, "fixed": True}, "w": {"start": 0.0, "fixed": True}})
    link2 = Link(joint={"phi": {"start": 0.4, "fixed": True}, "w": {"start": 0.0, "fixed": True}})

    def equations(self):
        return [ac.connect(self.world.frame, self.link1.frame_a),
                ac.connect(self.link1.frame_b, self.link2.frame_a)]


class PendulumChain(ac.Component):
    """n point masses of 1 kg on bars of 1 m (000 section 3.4), released at rest with
    the chain straight out horizontally."""

    stop_time = 2.0

    def __init__(self, n: int = 5, **modifications):
        super().__init__(**modifications)
        self.world = FixedFrame()
        self.links = [Link(joint={"phi": {"start": np.pi / 2 if i == 0 else 0.0,
                                          "fixed": True},
                                  "w": {"start": 0.0, "fixed": True}})
                      for i in range(n)]

    def equations(self):
        frames = [self.world.frame] + [link.frame_b for link in self.links]
        return [ac.connect(a, link.frame_a) for a, link in zip(frames, self.links)]


class PointMassChain(ac.Component):
    """n point masses of 1 kg on rods of 1 m (000 section 3.4), released at rest with
    the chain straight out horizontally along +x."""

    stop_time = 2.0

    def __init__(self, n: int = 5, **modifications):
        super().__init__(**modifications)
        self.world = FixedFrame()
        self.rods = [Rod(L=1.0) for _ in range(n)]
        # y is fixed, not x: along the horizontal the rods do not determine y
        self.masses = [PointMass(x={"start": i + 1.0}, y={"start": 0.0, "fixed": True},
                                 vy={"start": 0.0, "fixed": True})
                       for i in range(n)]

    def equations(self):
        frames = [self.world.frame] + [mass.frame for mass in self.masses]
        return [[ac.connect(a, rod.frame_a), ac.connect(rod.frame_b, b)]
                for a, b, rod in zip(frames, frames[1:], self.rods)]


if __name__ == "__main__":
    for model in (SinglePendulum(), DoublePendulum(), PendulumChain(5), PointMassChain(3)):
        compiled = ac.compile(model)
        print(compiled.report)
        res = ac.simulate(compiled, t_end=model.stop_time, rtol=1e-8)
        print(f"{type(model).__name__}: {res.stats['steps']} steps")
