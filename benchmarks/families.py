"""The benchmark models, built from the library: M1..M5 of the performance comparison and
the size families of the scale benchmark.

M1  RLC ladder: a 1 V step into N sections (series R and L, shunt C), one ground for all
    the capacitors, so the ground node's current balance is one sum of N + 2 terms;
    2N states.
M2  Cartesian pendulum (index 3, as written: library/examples/pendulum.py).
M3  DC motor, elastic shaft and load (library/examples/motor_drive.py).
M4  mass-spring chain: N masses joined by N springs (the first to a wall), a constant
    force on the last mass; 2N states.
M5  valve-controlled hydraulic motor with P control (library/hydraulics/examples).

``ladder(n)``, ``chain(n)`` and ``network(n)`` (a random R/L/C network) are the size
families of ``bench_scale.py``.
"""
from __future__ import annotations

import acausal as ac
from acausal.library import electrical as el
from acausal.library import translational as tr

__all__ = ["RLCLadder", "SpringChain", "PEERS", "peer_model", "ladder", "chain",
           "network"]


class RLCLadder(ac.Component):
    """A 1 V step at t = 0 into N sections R = 1 Ohm, L = 1 mH, C = 1 mF."""

    def __init__(self, n=10, **mods):
        super().__init__(**mods)
        self.n_sections = n
        self.src = el.StepVoltage(V=1.0, startTime=0.0)
        self.gnd = el.Ground()
        self.R = [el.Resistor(R=1.0) for _ in range(n)]
        self.L = [el.Inductor(L=1e-3) for _ in range(n)]
        self.C = [el.Capacitor(C=1e-3) for _ in range(n)]

    def equations(self):
        eqs = [ac.connect(self.src.n, self.gnd.p, *[c.n for c in self.C])]
        node = self.src.p
        for r, l, c in zip(self.R, self.L, self.C):
            eqs += [ac.connect(node, r.p), ac.connect(r.n, l.p), ac.connect(l.n, c.p)]
            node = c.p
        return eqs


class SpringChain(ac.Component):
    """N masses m = 1 kg on springs c = 1e4 N/m from a wall, 1 N on the last mass."""

    def __init__(self, n=10, **mods):
        super().__init__(**mods)
        self.wall = tr.Fixed()
        self.spring = [tr.Spring(c=1e4, s_rel0=0.0) for _ in range(n)]
        self.mass = [tr.Mass(m=1.0) for _ in range(n)]
        self.force = tr.ConstantForce(f_constant=1.0)

    def equations(self):
        eqs, flange = [], self.wall.flange
        for s, m in zip(self.spring, self.mass):
            eqs += [ac.connect(flange, s.flange_a), ac.connect(s.flange_b, m.flange_a)]
            flange = m.flange_b
        return eqs + [ac.connect(flange, self.force.flange)]


def ladder(n):
    return RLCLadder(n)


def chain(n):
    return SpringChain(n)


def network(n):
    from acausal.tests.trust._networks import NetworkModel, random_netlist
    return NetworkModel(random_netlist(n, seed=n))


def peer_model(name, n=1000):
    """(model, t_end) for M1..M5."""
    if name == "M1":
        return RLCLadder(n), 0.1
    if name == "M2":
        from acausal.library.examples.pendulum import Pendulum
        return Pendulum(), 10.0
    if name == "M3":
        from acausal.library.examples.motor_drive import MotorDrive
        return MotorDrive(), 1.0
    if name == "M4":
        return SpringChain(n), 1.0
    if name == "M5":
        from acausal.library.hydraulics.examples.valve_motor import ValveControlledMotor
        return ValveControlledMotor(), 0.5
    raise ValueError(f"unknown model {name!r}; the models are {PEERS}")


PEERS = ("M1", "M2", "M3", "M4", "M5")
