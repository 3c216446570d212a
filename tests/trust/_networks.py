"""Seeded random R/L/C networks of index 1, as an acausal model and as the matrices of
nodal analysis (the reference, assembled here from the netlist with numpy).

Topology (nodes 1..N, ground 0):

* a random spanning tree of resistors: node k hangs on a random earlier node, so every
  node reaches ground through resistors and no cutset consists of inductors alone;
* capacitors between random node pairs, kept only if they close no loop of capacitors
  (a union-find over the nodes, ground included): no capacitor loops;
* inductors between random node pairs, resistors to make up the count;
* sources: a ``ConstantVoltage`` in series with a resistor into a random node, on a node
  of its own that no capacitor touches (so no loop of capacitors and sources either).

The nodal reference replaces each source by its Norton equivalent (V/R_s into the node,
1/R_s to ground) and reads, over x = (u_1..u_N, i_L),

    Cn u' = -G u - A_L i_L + I,     L i_L' = A_L^T u

with Cn, G the nodal capacitance and conductance matrices and A_L the node-branch
incidence of the inductors (+1 at p, -1 at n).
"""
from dataclasses import dataclass, field

import numpy as np

import acausal as ac
from acausal.library.electrical import Capacitor, ConstantVoltage, Ground, Inductor, Resistor

__all__ = ["Netlist", "random_netlist", "NetworkModel", "nodal_matrices"]


@dataclass
class Netlist:
    n_nodes: int
    resistors: list = field(default_factory=list)     # (p, n, R)
    capacitors: list = field(default_factory=list)    # (p, n, C)
    inductors: list = field(default_factory=list)     # (p, n, L)
    sources: list = field(default_factory=list)       # (node, V, R_s)

    @property
    def n_components(self):
        return (len(self.resistors) + len(self.capacitors) + len(self.inductors)
                + 2 * len(self.sources))


def _find(parent, a):
    while parent[a] != a:
        parent[a] = parent[parent[a]]
        a = parent[a]
    return a


def _pair(rng, n_nodes):
    a, b = rng.choice(n_nodes + 1, size=2, replace=False)
    return int(a), int(b)


def random_netlist(n_components: int, seed: int) -> Netlist:
    """About 45 % resistors, 20 % capacitors, 15 % inductors, 1 source per 150 parts."""
    rng = np.random.default_rng(seed)
    n_sources = max(1, n_components // 150)
    n_nodes = int(0.3 * n_components)
    net = Netlist(n_nodes)

    def loguniform(lo, hi):
        return float(np.exp(rng.uniform(np.log(lo), np.log(hi))))
    for k in range(1, n_nodes + 1):
        net.resistors.append((k, int(rng.integers(0, k)), loguniform(1e2, 1e4)))
    parent = list(range(n_nodes + 1))
    n_cap = int(0.2 * n_components)
    while len(net.capacitors) < n_cap:
        a, b = _pair(rng, n_nodes)
        ra, rb = _find(parent, a), _find(parent, b)
        if ra == rb:
            continue
        parent[ra] = rb
        net.capacitors.append((a, b, loguniform(1e-7, 1e-5)))
    for _ in range(int(0.15 * n_components)):
        a, b = _pair(rng, n_nodes)
        net.inductors.append((a, b, loguniform(1e-3, 1e-1)))
    for _ in range(n_sources):
        net.sources.append((int(rng.integers(1, n_nodes + 1)), rng.uniform(1.0, 10.0),
                            loguniform(1e1, 1e3)))
    while net.n_components < n_components:
        a, b = _pair(rng, n_nodes)
        net.resistors.append((a, b, loguniform(1e2, 1e4)))
    return net


class NetworkModel(ac.Component):
    """The netlist as library components; every capacitor uncharged and every inductor
    current zero at t = 0, the sources switched on."""

    def __init__(self, net: Netlist, **mods):
        super().__init__(**mods)
        self.net = net
        self.gnd = Ground()
        self.R = [Resistor(R=r) for _, _, r in net.resistors]
        self.C = [Capacitor(C=c, v={"start": 0.0, "fixed": True}) for _, _, c in net.capacitors]
        self.L = [Inductor(L=h, i={"start": 0.0, "fixed": True}) for _, _, h in net.inductors]
        self.V = [ConstantVoltage(V=v) for _, v, _ in net.sources]
        self.Rs = [Resistor(R=r) for _, _, r in net.sources]

    def equations(self):
        pins = {k: [] for k in range(self.net.n_nodes + 1)}
        pins[0].append(self.gnd.p)
        for part, (p, n, _) in zip(self.R + self.C + self.L,
                                   self.net.resistors + self.net.capacitors + self.net.inductors):
            pins[p].append(part.p)
            pins[n].append(part.n)
        eqs = []
        for src, rs, (node, _, _) in zip(self.V, self.Rs, self.net.sources):
            pins[0].append(src.n)
            pins[node].append(rs.n)
            eqs.append(ac.connect(src.p, rs.p))
        return eqs + [ac.connect(*ps) for ps in pins.values() if len(ps) > 1]


def nodal_matrices(net: Netlist):
    """E, A, b of E x' = A x + b over x = (u_1..u_N, i_L) (module docstring)."""
    N, nL = net.n_nodes, len(net.inductors)
    Cn, G, I = np.zeros((N + 1, N + 1)), np.zeros((N + 1, N + 1)), np.zeros(N + 1)

    def stamp(M, a, b, y):
        M[a, a] += y
        M[b, b] += y
        M[a, b] -= y
        M[b, a] -= y
    for a, b, r in net.resistors:
        stamp(G, a, b, 1.0 / r)
    for a, b, c in net.capacitors:
        stamp(Cn, a, b, c)
    for node, v, rs in net.sources:
        G[node, node] += 1.0 / rs
        I[node] += v / rs
    AL = np.zeros((N + 1, nL))
    for j, (a, b, _) in enumerate(net.inductors):
        AL[a, j], AL[b, j] = 1.0, -1.0
    Cn, G, I, AL = Cn[1:, 1:], G[1:, 1:], I[1:], AL[1:]         # ground removed
    E = np.zeros((N + nL, N + nL))
    E[:N, :N] = Cn
    E[N:, N:] = np.diag([h for _, _, h in net.inductors])
    A = np.zeros_like(E)
    A[:N, :N], A[:N, N:], A[N:, :N] = -G, -AL, AL.T
    return E, A, np.concatenate([I, np.zeros(nL)])
