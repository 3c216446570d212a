"""The fill bound of the causal form on a random R/L/C network whose assignment chains
fill in (``causalize._bound_fill``).

``random_netlist(300, seed=300)``: capacitor currents and resistor voltages are
assigned along long chains of node balances, so without the bound an assigned
variable's gradient with respect to the solver unknowns collects up to about 150
entries, each from an equation that reads a handful of variables.  With the bound those
variables are solver unknowns and their equations rows of F.

Checked: (1) structure -- every gradient of the generated Jacobian has at most
``max(FILL_LIMIT, the variables its own expression reads)`` entries, so the gradient
entries are bounded by the bound times the incidence (linear in the model), while the
same model without the bound has a gradient several times the bound and more entries in
all; the report counts the variables kept and the integrator leaves them out of the
error test, as when they were assigned; (2) the results -- against nodal analysis and
the matrix exponential (``_descriptor``, as ``test_random_networks``): node potentials,
capacitor voltages, inductor currents and the resistor currents (Ohm's law on the
reference potentials) to 1e-5 of their scale, and Kirchhoff's current law at every node
(the kept capacitor currents included) to 1e-6 of the current scale.
"""
import numpy as np
import pytest

import acausal as ac
from acausal.compiler.structure import causalize

from ._descriptor import Descriptor
from ._networks import NetworkModel, nodal_matrices, random_netlist

N, T_END = 300, 5e-3


def _gradient_sizes(code):
    """(entries, entries allowed) per gradient of the Program behind the Jacobian."""
    prog = code.program
    out = []
    for k, g in prog.grads.items():
        reads = {q for q in prog.assigned[k].free_symbols
                 if prog.refs.get(q, ("",))[0] in ("y", "a")}
        out.append((len(g), max(causalize.FILL_LIMIT, len(reads))))
    return out


@pytest.fixture(scope="module")
def network():
    net = random_netlist(N, seed=N)
    compiled = ac.compile(NetworkModel(net), backend="numpy", cache=False)
    E, A, b = nodal_matrices(net)
    t = np.linspace(0.0, T_END, 11)
    x = Descriptor(E, A).constant_response(b, t)
    res = ac.simulate(compiled, t_end=T_END, rtol=1e-8, t_eval=t)
    return net, compiled, x, res


def test_gradients_are_bounded_and_the_unbounded_form_fills_in(network, monkeypatch):
    net, compiled, *_ = network
    bounded = _gradient_sizes(compiled.code)
    assert all(n <= allowed for n, allowed in bounded)
    limit = causalize.FILL_LIMIT
    monkeypatch.setattr(causalize, "FILL_LIMIT", 10 ** 9)
    unbounded = ac.compile(NetworkModel(net), backend="numpy", cache=False)
    assert not unbounded.report.kept_for_fill
    sizes = [n for n, _ in _gradient_sizes(unbounded.code)]
    assert max(sizes) > 4 * limit
    assert sum(sizes) > 2 * sum(n for n, _ in bounded)
    assert len(unbounded.code.jac_rows) > len(compiled.code.jac_rows)
    # the same model: the kept variables moved from the assignments into the unknowns
    kept = compiled.report.kept_for_fill
    assert len(compiled.names) == len(unbounded.names) + len(kept)
    assert set(compiled.names) - set(unbounded.names) == set(kept)


def test_report_counts_the_kept_variables(network):
    _, compiled, *_ = network
    kept = compiled.report.kept_for_fill
    assert kept and set(kept) <= set(compiled.names)
    assert f"fill: {len(kept)} assigned variable(s) kept as unknowns" in str(compiled.report)
    blocks = [b for b in compiled.report.blocks if b.get("kept_for_fill")]
    assert sum(len(b["kept_for_fill"]) for b in blocks) == len(kept)
    # judged through the unknowns they are computed from, as when they were assigned
    index = {name: k for k, name in enumerate(compiled.names)}
    assert all(compiled.algebraic[index[q]] and compiled.self_scaled[index[q]] for q in kept)


def test_network_with_kept_variables_matches_nodal_analysis(network):
    net, _, x, res = network
    assert res.success, res.message
    n = net.n_nodes
    U0 = np.column_stack([np.zeros(len(res.t)), x[:, :n]])
    I_L = x[:, n:]
    u_scale, i_scale = np.max(np.abs(U0)), np.max(np.abs(I_L))
    for k in range(1, n + 1):
        assert np.max(np.abs(res[f"R[{k - 1}].p.v"] - U0[:, k])) < 1e-5 * u_scale
    for j, (p, q, _) in enumerate(net.capacitors):
        assert np.max(np.abs(res[f"C[{j}].v"] - (U0[:, p] - U0[:, q]))) < 1e-5 * u_scale
    for j in range(len(net.inductors)):
        assert np.max(np.abs(res[f"L[{j}].i"] - I_L[:, j])) < 1e-5 * i_scale
    i_R = [(U0[:, p] - U0[:, q]) / r for p, q, r in net.resistors]
    r_scale = max(np.max(np.abs(i)) for i in i_R)
    for j, i in enumerate(i_R):
        assert np.max(np.abs(res[f"R[{j}].i"] - i)) < 1e-5 * r_scale


def test_kirchhoff_current_law_holds_at_every_node(network):
    net, _, _, res = network
    balance = np.zeros((net.n_nodes + 1, len(res.t)))
    parts = ([("R", p, q) for p, q, _ in net.resistors]
             + [("C", p, q) for p, q, _ in net.capacitors]
             + [("L", p, q) for p, q, _ in net.inductors])
    count = {"R": 0, "C": 0, "L": 0}
    scale = 0.0
    for kind, p, q in parts:
        name = f"{kind}[{count[kind]}]"
        count[kind] += 1
        balance[p] += res[f"{name}.p.i"]
        balance[q] += res[f"{name}.n.i"]
        scale = max(scale, np.max(np.abs(res[f"{name}.p.i"])))
    for j, (node, _, _) in enumerate(net.sources):
        balance[node] += res[f"Rs[{j}].n.i"]
    # ground (node 0) also takes the sources' return currents: check the other nodes
    assert np.max(np.abs(balance[1:])) < 1e-6 * scale
