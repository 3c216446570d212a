"""Whole systems written with array variables, and the same systems written without.

* ``ArrayChain(n)``: n masses in a line on n springs, the first spring to a wall, in
  array form; ``ComponentChain(n)`` is the same chain from n ``Mass`` and n ``Spring``
  of the translational library.
* ``RodChain(n)``: the n-link pendulum of the DAE notes (000 section 3.4): point masses
  on massless rods, the first hinged at the origin, in Cartesian coordinates with one
  length constraint per rod (index 3), in array form.  ``RodChain3Scalars`` is the same
  mechanism for n = 3 written with one declaration per scalar, as a model had to be
  written before arrays; the library's ``PointMassChain(n)`` assembles it from
  ``Rod`` and ``PointMass`` components.
"""
import numpy as np

import acausal as ac
from acausal.library.translational import Fixed, Mass, Spring

__all__ = ["ArrayChain", "ComponentChain", "RodChain", "RodChain3Scalars", "chain_masses",
           "chain_stiffnesses", "chain_start"]


def chain_masses(n):
    return 1.0 + 0.1 * np.arange(n)


def chain_stiffnesses(n):
    return 1.0e3 * (1.0 + 0.05 * np.arange(n))


def chain_start(n):
    """The last mass pulled out by 0.05 m, the others at rest at 0."""
    s = np.zeros(n)
    s[-1] = 0.05
    return s


class ArrayChain(ac.Component):
    """n masses on n springs, spring 0 from the wall (at 0) to mass 0:

        m_i s_i'' = f_(i+1) - f_i,   f_i = c_i (s_i - s_(i-1)),   s_(-1) = 0,  f_n = 0
    """

    m = ac.Parameter(1.0, shape="n", unit="kg", min=0, description="masses")
    c = ac.Parameter(1.0e3, shape="n", unit="N/m", min=0, description="spring constants")
    s = ac.Variable(shape="n", start=0.0, fixed=True, unit="m", description="positions")
    v = ac.Variable(shape="n", start=0.0, fixed=True, unit="m/s", description="velocities")

    def __init__(self, n: int, **modifications):
        self.n = n
        super().__init__(**modifications)

    def equations(self):
        f = self.c * (self.s - np.concatenate(([0.0], self.s[:-1])))
        return [ac.Eq(ac.der(self.s), self.v),
                ac.Eq(self.m * ac.der(self.v), np.append(f[1:], 0.0) - f)]


class ComponentChain(ac.Component):
    """The chain of ``ArrayChain`` from library components: wall, Spring, Mass, Spring..."""

    def __init__(self, n: int, **modifications):
        super().__init__(**modifications)
        m, c, s0 = chain_masses(n), chain_stiffnesses(n), chain_start(n)
        self.wall = Fixed()
        self.springs = [Spring(c=c[i]) for i in range(n)]
        self.masses = [Mass(m=m[i], s={"start": s0[i], "fixed": True},
                            v={"start": 0.0, "fixed": True}) for i in range(n)]

    def equations(self):
        ends = [self.wall.flange] + [mass.flange_b for mass in self.masses]
        return [[ac.connect(a, spring.flange_a), ac.connect(spring.flange_b, mass.flange_a)]
                for a, spring, mass in zip(ends, self.springs, self.masses)]


# -- the n-link pendulum in Cartesian coordinates (000 section 3.4) ---------------------------
class RodChain(ac.Component):
    """n point masses on rods; rod i from mass i-1 (the origin for i = 0) to mass i:

        m_i r_i'' = -lam_i (r_i - r_(i-1)) + lam_(i+1) (r_(i+1) - r_i) - m_i g e_y
        |r_i - r_(i-1)|^2 = L_i^2,   lam_n = 0          (000 (3.2.4), one rod per mass)
    """

    m = ac.Parameter(1.0, shape="n", unit="kg", min=0, description="masses")
    L = ac.Parameter(1.0, shape="n", unit="m", min=0, description="rod lengths")
    g = ac.Parameter(9.81, unit="m/s2", description="gravity, acting in -y")
    x = ac.Variable(shape="n", unit="m")
    y = ac.Variable(shape="n", unit="m")
    vx = ac.Variable(shape="n", unit="m/s")
    vy = ac.Variable(shape="n", unit="m/s")
    lam = ac.Variable(shape="n", unit="N/m", description="rod tension per length")

    def __init__(self, n: int, **modifications):
        self.n = n
        super().__init__(**modifications)

    def equations(self):
        dx = self.x - np.concatenate(([0.0], self.x[:-1]))
        dy = self.y - np.concatenate(([0.0], self.y[:-1]))
        fx, fy = self.lam * dx, self.lam * dy
        return [ac.Eq(ac.der(self.x), self.vx), ac.Eq(ac.der(self.y), self.vy),
                ac.Eq(self.m * ac.der(self.vx), np.append(fx[1:], 0.0) - fx),
                ac.Eq(self.m * ac.der(self.vy), np.append(fy[1:], 0.0) - fy - self.m * self.g),
                ac.Eq(dx**2 + dy**2, self.L**2)]


class RodChain3Scalars(ac.Component):
    """``RodChain(3)`` with one declaration per scalar (the equations of ``RodChain``)."""

    m1 = ac.Parameter(1.0, unit="kg", min=0, description="mass 1")
    m2 = ac.Parameter(1.0, unit="kg", min=0, description="mass 2")
    m3 = ac.Parameter(1.0, unit="kg", min=0, description="mass 3")
    L1 = ac.Parameter(1.0, unit="m", min=0, description="rod length 1")
    L2 = ac.Parameter(1.0, unit="m", min=0, description="rod length 2")
    L3 = ac.Parameter(1.0, unit="m", min=0, description="rod length 3")
    g = ac.Parameter(9.81, unit="m/s2", description="gravity, acting in -y")
    x1 = ac.Variable(unit="m")
    x2 = ac.Variable(unit="m")
    x3 = ac.Variable(unit="m")
    y1 = ac.Variable(unit="m")
    y2 = ac.Variable(unit="m")
    y3 = ac.Variable(unit="m")
    vx1 = ac.Variable(unit="m/s")
    vx2 = ac.Variable(unit="m/s")
    vx3 = ac.Variable(unit="m/s")
    vy1 = ac.Variable(unit="m/s")
    vy2 = ac.Variable(unit="m/s")
    vy3 = ac.Variable(unit="m/s")
    lam1 = ac.Variable(unit="N/m", description="rod tension per length 1")
    lam2 = ac.Variable(unit="N/m", description="rod tension per length 2")
    lam3 = ac.Variable(unit="N/m", description="rod tension per length 3")

    def equations(self):
        dx1, dy1 = self.x1, self.y1
        dx2, dy2 = self.x2 - self.x1, self.y2 - self.y1
        dx3, dy3 = self.x3 - self.x2, self.y3 - self.y2
        return [ac.Eq(ac.der(self.x1), self.vx1), ac.Eq(ac.der(self.y1), self.vy1),
                ac.Eq(ac.der(self.x2), self.vx2), ac.Eq(ac.der(self.y2), self.vy2),
                ac.Eq(ac.der(self.x3), self.vx3), ac.Eq(ac.der(self.y3), self.vy3),
                ac.Eq(self.m1 * ac.der(self.vx1), self.lam2 * dx2 - self.lam1 * dx1),
                ac.Eq(self.m2 * ac.der(self.vx2), self.lam3 * dx3 - self.lam2 * dx2),
                ac.Eq(self.m3 * ac.der(self.vx3), -self.lam3 * dx3),
                ac.Eq(self.m1 * ac.der(self.vy1),
                      self.lam2 * dy2 - self.lam1 * dy1 - self.m1 * self.g),
                ac.Eq(self.m2 * ac.der(self.vy2),
                      self.lam3 * dy3 - self.lam2 * dy2 - self.m2 * self.g),
                ac.Eq(self.m3 * ac.der(self.vy3), -self.lam3 * dy3 - self.m3 * self.g),
                ac.Eq(dx1**2 + dy1**2, self.L1**2),
                ac.Eq(dx2**2 + dy2**2, self.L2**2),
                ac.Eq(dx3**2 + dy3**2, self.L3**2)]
