"""Values at requested output times between steps (solver contract item 17).

A subnetwork of capacitors and an inductor that hangs from one node of a sine source
and nowhere else floats with that node: every current in it is zero and each of its
node voltages equals the source's, exactly.  Its capacitor loops make the voltage
derivatives unknowns that the error test leaves out (item 6), and since no state moves
the steps grow to several periods of the source; the values at output times must still
be the solution, computed from the interpolated states, not interpolated themselves.
"""
import warnings

import numpy as np
import pytest

import acausal as ac
from acausal.library import electrical as el
from acausal.solvers import cbdf

LOOPS = ["python"] + (["c"] if cbdf.library() is not None else [])


class FloatingNetwork(ac.Component):
    gnd = el.Ground()
    V1 = el.SineVoltage(V=2.7, f=2000.0)
    L1 = el.Inductor(L=0.015)
    C1 = el.Capacitor(C=1e-06)
    C2 = el.Capacitor(C=2.2e-06)
    C3 = el.Capacitor(C=1.2e-05)
    C4 = el.Capacitor(C=1e-06)
    C5 = el.Capacitor(C=3.3e-4)

    def equations(self):
        return [ac.connect(self.gnd.p, self.V1.n),
                ac.connect(self.V1.p, self.L1.n, self.C2.n, self.C3.n, self.C1.p, self.C4.p),
                ac.connect(self.L1.p, self.C2.p, self.C3.p, self.C5.n),
                ac.connect(self.C1.n, self.C4.n, self.C5.p)]


CURRENTS = ["L1.i", "C1.i", "C2.i", "C3.i", "C4.i", "C5.i"]


@pytest.mark.parametrize("loop", LOOPS)
def test_outputs_between_long_steps_are_the_solution(loop):
    model = ac.compile(FloatingNetwork())
    assert model.uncontrolled            # a voltage derivative without an error bound
    t = np.linspace(0.0, 1.7e-3, 21)     # 3.4 periods of the source
    res = ac.simulate(model, t_end=t[-1], rtol=1e-8, atol=1e-12, t_eval=t, step_loop=loop)
    assert res.success and res.stats["step_loop"] == loop
    assert res.stats["interpolated_outputs"] == 0
    # the source's current through C1..C5 would be 2.7 V * 2 pi 2 kHz * C: some 0.6 A
    for name in CURRENTS:
        assert np.max(np.abs(res[name])) <= 1e-9, name
    source = 2.7 * np.sin(2.0 * np.pi * 2000.0 * t)
    for node in ("C5.n.v", "C5.p.v"):
        assert np.max(np.abs(res[node] - source)) <= 1e-9 * 2.7, node


def test_an_output_time_that_cannot_be_solved_is_said(monkeypatch):
    model = ac.compile(FloatingNetwork())
    monkeypatch.setattr("acausal.runtime.model.consistent_output",
                        lambda *args: None)
    t = np.linspace(0.0, 1.7e-3, 5)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        res = ac.simulate(model, t_end=t[-1], rtol=1e-8, atol=1e-12, t_eval=t,
                          step_loop="python")
    assert res.success and res.stats["interpolated_outputs"] >= 1
    assert "interpolated, not solved" in res.message
    assert any("interpolated, not solved" in str(w.message) for w in caught)
