"""A model with hundreds of parameters on the numpy backend, whose generated code gets p
as a list made once (runtime/model.py), changed in place between runs: every run
follows the closed form of the parameters it ran with.

130 RC branches in parallel behind a 1 V step at t0 = 10 ms (a time event, so the
zero-crossing functions are evaluated after every step too): branch k charges as
v_k = 1 - exp(-(t - t0)/(R_k C_k)) for t >= t0, and is 0 before.
"""
import numpy as np

import acausal as ac
from acausal.library import electrical as el

N, T0 = 130, 0.01


class _Branches(ac.Component):
    def __init__(self, **mods):
        super().__init__(**mods)
        self.src = el.StepVoltage(V=1.0, startTime=T0)
        self.gnd = el.Ground()
        self.R = [el.Resistor(R=1.0 + 0.01 * k) for k in range(N)]
        self.C = [el.Capacitor(C=1e-3) for _ in range(N)]

    def equations(self):
        eqs = [ac.connect(self.src.n, self.gnd.p, *[c.n for c in self.C])]
        for r, c in zip(self.R, self.C):
            eqs += [ac.connect(self.src.p, r.p), ac.connect(r.n, c.p)]
        return eqs


def _worst(res, R):
    t = res.t
    worst = 0.0
    for k in range(N):
        tau = R[k] * 1e-3
        exact = np.where(t >= T0, 1.0 - np.exp(-np.maximum(t - T0, 0.0) / tau), 0.0)
        worst = max(worst, np.max(np.abs(res[f"C[{k}].v"] - exact)))
    return worst          # the signals' peak is about 1 V


def test_in_place_parameter_changes_reach_the_generated_code():
    c = ac.compile(_Branches(), backend="numpy")
    assert len(c.p) >= 256
    R = 1.0 + 0.01 * np.arange(N)
    t = np.linspace(0.0, 0.03, 61)
    first = ac.simulate(c, t_end=0.03, rtol=1e-9, t_eval=t)
    assert _worst(first, R) < 1e-6
    c.set_parameters({"R[7].R": 3.0})                  # written into p in place
    R[7] = 3.0
    second = ac.simulate(c, t_end=0.03, rtol=1e-9, t_eval=t)
    assert _worst(second, R) < 1e-6
    # and the change is visible: the branch's time constant tripled
    assert np.max(np.abs(second["C[7].v"] - first["C[7].v"])) > 0.1
