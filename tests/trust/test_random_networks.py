"""Random index-1 R/L/C networks of 700 and 1000 components (``_networks``: a
seeded generator; resistors everywhere, capacitors without loops, inductors, constant
voltage sources behind resistors), all capacitors uncharged and all inductor currents
zero at t = 0, the sources on.

Reference: nodal analysis assembled from the netlist with numpy, E x' = A x + b, reduced
to an ODE by linear algebra and solved exactly for the constant sources by the matrix
exponential (``_descriptor``) — a different formulation (node potentials, Norton
sources) and a different solver.  The model must compile, initialize, simulate 5 ms
(several time constants of the faster half of the network) and match the node
potentials, capacitor voltages and inductor currents to 1e-5 of their scale; the number
of states must be the network's order (one per capacitor of the forest and per
inductor).

There is no slow-test marker in this repository, so only sizes that compile in under a
minute run here; ``benchmarks/random_network.py`` runs the 2000-component network of the
same family (``random_netlist(2000, seed=2000)``), which takes minutes to compile.
"""
import numpy as np
import pytest

import acausal as ac

from ._descriptor import Descriptor
from ._networks import NetworkModel, nodal_matrices, random_netlist

T_END = 5e-3
SIZES = [700, 1000]


@pytest.fixture(scope="module", params=SIZES, ids=lambda n: f"{n} components")
def network(request):
    n = request.param
    net = random_netlist(n, seed=n)
    assert net.n_components == n
    E, A, b = nodal_matrices(net)
    reference = Descriptor(E, A)
    t = np.linspace(0.0, T_END, 11)
    x = reference.constant_response(b, t)
    compiled = ac.compile(NetworkModel(net))
    res = ac.simulate(compiled, t_end=T_END, rtol=1e-8, t_eval=t)
    return net, reference, x, compiled, res


def test_network_state_count_is_its_order(network):
    net, reference, _, compiled, _ = network
    assert reference.n_differential == len(net.capacitors) + len(net.inductors)
    assert len(compiled.report.states) == reference.n_differential


def test_network_simulates_the_interval(network):
    *_, res = network
    assert res.success, res.message
    assert res.t[-1] == pytest.approx(T_END)


def test_network_matches_nodal_analysis(network):
    net, _, x, _, res = network
    assert res.success, res.message
    N = net.n_nodes
    U, I_L = x[:, :N], x[:, N:]
    u_scale, i_scale = np.max(np.abs(U)), np.max(np.abs(I_L))
    # node k is the p pin of tree resistor k - 1 (the generator hangs node k there)
    u = np.column_stack([res[f"R[{k - 1}].p.v"] for k in range(1, N + 1)])
    assert np.max(np.abs(u - U)) < 1e-5 * u_scale
    U0 = np.column_stack([np.zeros(len(res.t)), U])
    for j, (p, n, _) in enumerate(net.capacitors):
        assert np.max(np.abs(res[f"C[{j}].v"] - (U0[:, p] - U0[:, n]))) < 1e-5 * u_scale
    for j in range(len(net.inductors)):
        assert np.max(np.abs(res[f"L[{j}].i"] - I_L[:, j])) < 1e-5 * i_scale
