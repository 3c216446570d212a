"""Pendulums from spatial joints, bars and bodies.

* ``DoublePendulum``: two links in the world's x-y plane, revolute axes along z, the
  same system as ``acausal.library.multibody.examples.pendulums.DoublePendulum`` of
  the planar library (1 kg point masses on 1 m bars, released at joint angles 0.5 and
  0.4 rad, g = 9.81 m/s^2 in -y): the spatial library must reproduce it.
* ``PendulumChain(n)``: n links whose revolute axes alternate between z and x, so the
  chain moves in three dimensions; released with every link turned 0.3 rad.
"""
import acausal as ac
from acausal.library.multibody3d import Body, FixedTranslation, Revolute, World
from acausal.library.multibody3d.interfaces import PartialTwoFrames

__all__ = ["Link", "DoublePendulum", "PendulumChain"]


class Link(PartialTwoFrames):
    """A revolute joint about n, a massless bar of length L pointing down (-y of the
    joint's frame_b) and a point mass m at its end, which is frame_b."""

    L = ac.Parameter(1.0, unit="m", min=0, description="bar length")
    L_down = ac.Parameter(lambda c: -c.L, unit="m", description="y of the bar's end, -L")
    m = ac.Parameter(1.0, unit="kg", min=0, description="point mass at the end")
    n_1 = ac.Parameter(0.0, description="joint axis in frame_a, x")
    n_2 = ac.Parameter(0.0, description="joint axis in frame_a, y")
    n_3 = ac.Parameter(1.0, description="joint axis in frame_a, z")
    joint = Revolute(n_1=ac.ref("n_1"), n_2=ac.ref("n_2"), n_3=ac.ref("n_3"))
    bar = FixedTranslation(r_2=ac.ref("L_down"))
    mass = Body(m=ac.ref("m"), I_11=0.0, I_22=0.0, I_33=0.0)

    def equations(self):
        return [ac.connect(self.frame_a, self.joint.frame_a),
                ac.connect(self.joint.frame_b, self.bar.frame_a),
                ac.connect(self.bar.frame_b, self.mass.frame_a, self.frame_b)]


def _released(phi):
    return {"phi": {"start": phi, "fixed": True}, "w": {"start": 0.0, "fixed": True}}


class DoublePendulum(ac.Component):
    """The planar library's double pendulum, built in 3-D."""

    stop_time = 10.0
    world = World(g=9.81)
    link1 = Link(joint=_released(0.5))
    link2 = Link(joint=_released(0.4))

    def equations(self):
        return [ac.connect(self.world.frame_b, self.link1.frame_a),
                ac.connect(self.link1.frame_b, self.link2.frame_a)]


class PendulumChain(ac.Component):
    """n links of 1 kg and 1 m, axes alternating z, x; every joint released at 0.3 rad."""

    stop_time = 2.0

    def __init__(self, n: int = 10, **modifications):
        super().__init__(**modifications)
        self.world = World()
        self.links = [Link(n_1=float(i % 2), n_3=float(1 - i % 2), joint=_released(0.3))
                      for i in range(n)]

    def equations(self):
        frames = [self.world.frame_b] + [link.frame_b for link in self.links]
        return [ac.connect(a, link.frame_a) for a, link in zip(frames, self.links)]


if __name__ == "__main__":
    import time
    for n in (1, 3, 10):
        t0 = time.perf_counter()
        compiled = ac.compile(PendulumChain(n), cache=False)
        t1 = time.perf_counter()
        res = ac.simulate(compiled, t_end=PendulumChain.stop_time, rtol=1e-6)
        t2 = time.perf_counter()
        print(f"{n:2d} links: compile {t1 - t0:.2f} s, simulate {t2 - t1:.2f} s, "
              f"{res.stats['steps']} steps, states {compiled.report.states}")
