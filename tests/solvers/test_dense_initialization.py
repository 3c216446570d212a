"""A mid-size model (more unknowns than the sparse threshold, no more than the compiled
step loop factors dense) is initialized on dense systems, so that a new process that
loads and runs it -- each worker of a sweep -- never imports scipy.sparse (0.3-0.5 s
with the SuperLU it brings).  Its run is checked against the closed form of its linear
ODE (a matrix exponential)."""
from __future__ import annotations

import json
import pickle
import subprocess
import sys

import numpy as np
import scipy.linalg

import acausal as ac
from acausal.library import electrical as el
from acausal.solvers.linalg import DENSE_MAX, SPARSE_THRESHOLD

N, R, C = 80, 1.0, 1e-3      # 80 capacitor voltages: between the two thresholds


class RCLadder(ac.Component):
    """A 1 V source into N sections, a series resistor R and a capacitor C to ground."""

    def __init__(self, n=N, **mods):
        super().__init__(**mods)
        self.src = el.ConstantVoltage(V=1.0)
        self.gnd = el.Ground()
        self.R = [el.Resistor(R=R) for _ in range(n)]
        self.C = [el.Capacitor(C=C, v={"start": 0.0, "fixed": True}) for _ in range(n)]

    def equations(self):
        eqs = [ac.connect(self.src.n, self.gnd.p, *[c.n for c in self.C])]
        node = self.src.p
        for r, c in zip(self.R, self.C):
            eqs += [ac.connect(node, r.p), ac.connect(r.n, c.p)]
            node = c.p
        return eqs


_RUN = """
import json, pickle, sys
import acausal as ac
model = pickle.load(open(sys.argv[1], "rb"))
res = ac.simulate(model, t_end=float(sys.argv[2]), rtol=1e-8)
print(json.dumps({"v": [float(res[f"C[{k}].v"][-1]) for k in range(int(sys.argv[3]))],
                  "t": float(res.t[-1]),
                  "loaded": sorted(m for m in ("scipy.sparse", "scipy.sparse.linalg")
                                   if m in sys.modules)}))
"""


def _closed_form(t: float) -> np.ndarray:
    """C v' = (v_{k-1} - v_k)/R - (v_k - v_{k+1})/R, v_0 = 1, no v_{N+1}; v(0) = 0:
    v(t) = 1 - expm(A t) 1."""
    A = (np.diag(-2.0 * np.ones(N)) + np.diag(np.ones(N - 1), 1)
         + np.diag(np.ones(N - 1), -1))
    A[-1, -1] = -1.0
    A /= R * C
    return 1.0 - scipy.linalg.expm(A * t) @ np.ones(N)


def test_a_mid_size_model_runs_in_a_new_process_without_scipy_sparse(tmp_path):
    compiled = ac.compile(RCLadder())
    assert SPARSE_THRESHOLD < compiled.n <= DENSE_MAX
    path = tmp_path / "model.pkl"
    path.write_bytes(pickle.dumps(compiled))
    t_end = 0.5
    out = subprocess.run([sys.executable, "-c", _RUN, str(path), str(t_end), str(N)],
                         capture_output=True, text=True, check=True).stdout
    found = json.loads(out.strip().splitlines()[-1])
    assert found["loaded"] == []
    exact = _closed_form(found["t"])
    assert found["t"] == t_end
    assert np.max(np.abs(np.array(found["v"]) - exact)) < 1e-4 * np.max(np.abs(exact))
