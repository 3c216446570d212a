"""Planar pendulums in Cartesian coordinates (the DAE notes, 000 sections 3.2-3.6).

The point-mass pendulum  m x'' = -lam x,  m y'' = -lam y - m g,  x^2 + y^2 = L^2  is
index 3: the constraint must be differentiated twice, and no static choice of states
works along the whole motion (x is a bad state near the horizontal, y near the vertical),
so acausal selects the states dynamically.
"""
import acausal as ac

__all__ = ["Pendulum", "DoublePendulum"]


class Pendulum(ac.Component):
    """Point mass m on a massless rod of length L."""

    L = ac.Parameter(1.0, unit="m")
    m = ac.Parameter(1.0, unit="kg")
    g = ac.Parameter(9.81, unit="m/s2")
    x = ac.Variable(start=0.5, fixed=True, unit="m")
    y = ac.Variable(start=-0.9, unit="m")
    vx = ac.Variable(start=0.0, fixed=True, unit="m/s")
    vy = ac.Variable(start=0.0, unit="m/s")
    lam = ac.Variable(start=10.0, unit="N/m", description="rod force per unit length")

    def equations(self):
        x, y, vx, vy, lam, m = self.x, self.y, self.vx, self.vy, self.lam, self.m
        return [ac.Eq(ac.der(x), vx),
                ac.Eq(ac.der(y), vy),
                ac.Eq(m * ac.der(vx), -lam * x),
                ac.Eq(m * ac.der(vy), -lam * y - m * self.g),
                ac.Eq(x**2 + y**2, self.L**2)]


class DoublePendulum(ac.Component):
    """Two point masses on two rods (000 section 3.2, Cartesian form)."""

    L1 = ac.Parameter(1.0, unit="m")
    L2 = ac.Parameter(1.0, unit="m")
    m1 = ac.Parameter(1.0, unit="kg")
    m2 = ac.Parameter(1.0, unit="kg")
    g = ac.Parameter(9.81, unit="m/s2")
    x1 = ac.Variable(start=0.5, fixed=True)
    y1 = ac.Variable(start=-0.8)
    x2 = ac.Variable(start=1.2, fixed=True)
    y2 = ac.Variable(start=-1.5)
    vx1 = ac.Variable(start=0.0, fixed=True)
    vy1 = ac.Variable(start=0.0)
    vx2 = ac.Variable(start=0.0, fixed=True)
    vy2 = ac.Variable(start=0.0)
    lam1 = ac.Variable(start=10.0)
    lam2 = ac.Variable(start=10.0)

    def equations(self):
        dx, dy = self.x2 - self.x1, self.y2 - self.y1
        return [ac.Eq(ac.der(self.x1), self.vx1), ac.Eq(ac.der(self.y1), self.vy1),
                ac.Eq(ac.der(self.x2), self.vx2), ac.Eq(ac.der(self.y2), self.vy2),
                ac.Eq(self.m1 * ac.der(self.vx1), -self.lam1 * self.x1 + self.lam2 * dx),
                ac.Eq(self.m1 * ac.der(self.vy1), -self.lam1 * self.y1 + self.lam2 * dy
                      - self.m1 * self.g),
                ac.Eq(self.m2 * ac.der(self.vx2), -self.lam2 * dx),
                ac.Eq(self.m2 * ac.der(self.vy2), -self.lam2 * dy - self.m2 * self.g),
                ac.Eq(self.x1**2 + self.y1**2, self.L1**2),
                ac.Eq(dx**2 + dy**2, self.L2**2)]
