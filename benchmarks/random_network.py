"""A random index-1 R/L/C network of N components (default 2000), compiled, initialized
and simulated for 5 ms, against nodal analysis and the matrix exponential.

The networks are those of ``tests/trust/test_random_networks.py`` (which runs 700 and
1000 components; larger ones take minutes to compile and stay out of the test suite):
``random_netlist(N, seed=N)``, resistors everywhere, capacitors without loops,
inductors, constant sources behind resistors, everything at rest at t = 0.  Printed:
seconds for the reference, the compilation and the simulation, the states, the steps
and the largest deviation of the node potentials relative to their scale.

Usage: ``python benchmarks/random_network.py [N ...]``.
"""
from __future__ import annotations

import sys
import time

import numpy as np

import acausal as ac
from acausal.tests.trust._descriptor import Descriptor
from acausal.tests.trust._networks import NetworkModel, nodal_matrices, random_netlist

T_END = 5e-3


def run(n: int) -> None:
    net = random_netlist(n, seed=n)
    E, A, b = nodal_matrices(net)
    t = np.linspace(0.0, T_END, 11)
    t0 = time.perf_counter()
    x = Descriptor(E, A).constant_response(b, t)
    t_ref = time.perf_counter() - t0
    t0 = time.perf_counter()
    compiled = ac.compile(NetworkModel(net))
    t_compile = time.perf_counter() - t0
    t0 = time.perf_counter()
    res = ac.simulate(compiled, t_end=T_END, rtol=1e-8, t_eval=t)
    t_sim = time.perf_counter() - t0
    line = (f"N = {n}: reference {t_ref:.1f} s, compile {t_compile:.1f} s, "
            f"simulate {t_sim:.1f} s, success={res.success}, "
            f"states {len(compiled.report.states)} (network order "
            f"{len(net.capacitors) + len(net.inductors)}), steps {res.stats['steps']}")
    if res.success:
        U = x[:, :net.n_nodes]
        u = np.column_stack([res[f"R[{k - 1}].p.v"] for k in range(1, net.n_nodes + 1)])
        line += f", deviation {np.max(np.abs(u - U)) / np.max(np.abs(U)):.1e} of scale"
    else:
        line += f": {res.message}"
    print(line, flush=True)


if __name__ == "__main__":
    for arg in sys.argv[1:] or ["2000"]:
        run(int(arg))
