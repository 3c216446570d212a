"""No size limit by construction: an RLC ladder of 5,000 sections with a single ground.

The ground node's current balance is one sum of 5,002 terms (about 90,000 flat
equations in all); a sum of that length once exceeded what CPython's compiler accepts.
The result is checked against the exact solution of the same linear ODE (the ladder's
equations written by hand: L i_k' = v_(k-1) - R i_k - v_k, C v_k' = i_k - i_(k+1), v_0 = 1 V
from t = 0), computed with the matrix exponential (scipy's expm_multiply).
"""
import numpy as np
import scipy.sparse as sps
from scipy.sparse.linalg import expm_multiply

import acausal as ac
from acausal.library import electrical as el

N = 5000
R, L, C = 1.0, 1e-3, 1e-3


class Ladder(ac.Component):
    def __init__(self, n, **mods):
        super().__init__(**mods)
        self.src = el.StepVoltage(V=1.0, startTime=0.0)
        self.gnd = el.Ground()
        self.R = [el.Resistor(R=R) for _ in range(n)]
        self.L = [el.Inductor(L=L) for _ in range(n)]
        self.C = [el.Capacitor(C=C) for _ in range(n)]

    def equations(self):
        eqs = [ac.connect(self.src.n, self.gnd.p, *[c.n for c in self.C])]
        node = self.src.p
        for r, l, c in zip(self.R, self.L, self.C):
            eqs += [ac.connect(node, r.p), ac.connect(r.n, l.p), ac.connect(l.n, c.p)]
            node = c.p
        return eqs


def _exact(n, t):
    """x = [i_1..i_n, v_1..v_n, 1]: x' = A x with the source as a constant state."""
    k = np.arange(n)
    A = sps.lil_matrix((2 * n + 1, 2 * n + 1))
    A[k, k] = -R / L
    A[k, n + k] = -1 / L
    A[k[1:], n + k[:-1]] = 1 / L
    A[0, 2 * n] = 1 / L
    A[n + k, k] = 1 / C
    A[n + k[:-1], k[1:]] = -1 / C
    x0 = np.zeros(2 * n + 1)
    x0[-1] = 1.0
    return expm_multiply(A.tocsc(), x0, start=0.0, stop=t[-1], num=len(t), endpoint=True)


def test_a_ladder_of_5000_sections_with_one_ground_builds_and_runs():
    compiled = ac.compile(Ladder(N), backend="numpy")
    assert len(compiled.states) == 2 * N
    t = np.linspace(0.0, 5e-3, 6)
    res = ac.simulate(compiled, t_end=t[-1], rtol=1e-8, t_eval=t)
    assert res.success, res.message
    x = _exact(N, t)
    for k in (0, 1, 2, 10):
        i_k, v_k = x[:, k], x[:, N + k]
        assert np.max(np.abs(res[f"L[{k}].i"] - i_k)) <= 1e-5 * np.max(np.abs(x[:, 0]))
        assert np.max(np.abs(res[f"C[{k}].v"] - v_k)) <= 1e-5 * np.max(np.abs(x[:, N]))
    # Kirchhoff at the one ground node: the source current returns through the capacitors
    i_gnd = res["gnd.p.i"]
    scale = np.max(np.abs(res["src.p.i"]))
    assert np.max(np.abs(i_gnd)) <= 1e-9 * scale
