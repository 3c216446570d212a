"""Compile time of the whole pipeline (flatten .. codegen) as models grow.

Two chains that need index reduction: N inertias coupled by N ideal gears (one rigid
position constraint per gear, index 3) and N point-mass pendulum links in Cartesian
coordinates (one length constraint per link, index 3).  Prints the time of each pass
and the ratio t(N) / (N log N) normalised by the smallest N, measured in this process:
a ratio that stays near 1 means n log n growth.

    python benchmarks/bench_compile.py [N ...]
"""
from __future__ import annotations

import math
import sys
import time

import acausal as ac
from acausal.library import rotational as rot


class GearChain(ac.Component):
    """A torque on the first of N+1 inertias joined by N ideal gears."""

    def __init__(self, n=10, **mods):
        super().__init__(**mods)
        self.drive = rot.ConstantTorque(tau_constant=1.0)
        self.J = [rot.Inertia(J=1.0) for _ in range(n + 1)]
        self.gear = [rot.IdealGear(ratio=1.1) for _ in range(n)]

    def equations(self):
        eqs = [ac.connect(self.drive.flange, self.J[0].flange_a)]
        for k, g in enumerate(self.gear):
            eqs += [ac.connect(self.J[k].flange_b, g.flange_a),
                    ac.connect(g.flange_b, self.J[k + 1].flange_a)]
        return eqs


class PendulumChain(ac.Component):
    """N point masses, each hanging from the previous one on a rod of length 1."""

    def __init__(self, n=10, **mods):
        super().__init__(**mods)
        self.links = [Link(x={"start": 0.1 * (k + 1)}, y={"start": -(k + 1.0)})
                      for k in range(n)]

    def equations(self):
        eqs, prev = [], None
        for link in self.links:
            x0, y0 = (0, 0) if prev is None else (prev.x, prev.y)
            eqs.append(ac.Eq((link.x - x0)**2 + (link.y - y0)**2, 1.0))
            eqs += link.dynamics(x0, y0, self._next(link))
            prev = link
        return eqs

    def _next(self, link):
        k = self.links.index(link)
        return self.links[k + 1] if k + 1 < len(self.links) else None


class Link(ac.Component):
    m = ac.Parameter(1.0)
    g = ac.Parameter(9.81)
    x = ac.Variable()
    y = ac.Variable()
    vx = ac.Variable(start=0.0)
    vy = ac.Variable(start=0.0)
    lam = ac.Variable(start=10.0, description="rod force per length (to the previous mass)")

    def dynamics(self, x0, y0, nxt):
        fx = -self.lam * (self.x - x0)
        fy = -self.lam * (self.y - y0)
        if nxt is not None:
            fx += nxt.lam * (nxt.x - self.x)
            fy += nxt.lam * (nxt.y - self.y)
        return [ac.Eq(ac.der(self.x), self.vx), ac.Eq(ac.der(self.y), self.vy),
                ac.Eq(self.m * ac.der(self.vx), fx),
                ac.Eq(self.m * ac.der(self.vy), fy - self.m * self.g)]


def measure(factory, sizes):
    base = None
    print(f"{'N':>6} {'total s':>9} {'ratio':>7}  per pass (s)")
    for n in sizes:
        t0 = time.perf_counter()
        compiled = ac.compile(factory(n))
        total = time.perf_counter() - t0
        scaled = total / (n * math.log(n))
        base = base or scaled
        passes = " ".join(f"{k}={v:.2f}" for k, v in compiled.report.timings.items())
        print(f"{n:>6} {total:>9.2f} {scaled / base:>7.2f}  {passes}")


if __name__ == "__main__":
    sizes = [int(a) for a in sys.argv[1:]] or [25, 50, 100, 200, 400]
    print("gear chain (N ideal gears, index 3):")
    measure(GearChain, sizes)
    print("\npendulum chain (N links, index 3, dynamic state selection):")
    measure(PendulumChain, [n for n in sizes if n <= 200])
