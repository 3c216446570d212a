"""Alias elimination: trivial equations leave, every variable keeps its name."""
import numpy as np
import pytest

import acausal as ac
from acausal.compiler.frontend.alias import eliminate_aliases
from acausal.compiler.frontend.flatten import flatten
from acausal.library.electrical import Capacitor, Ground, Resistor
from acausal.library.rotational import Fixed, Inertia, Spring

from ..models.test_electrical_circuits import RCCharging as RC


def test_rc_circuit_reduces_to_its_four_real_equations():
    # 20 flat equations: 4 per one-port, 1 for ground, 7 from connections.  What is
    # left: Ohm's law, the capacitor and the one mesh equation (src.v = V is a constant).
    reduced, table = eliminate_aliases(flatten(RC()))
    assert (table.equations_before, table.equations_after) == (20, 3)
    assert len(reduced.variables) == 3
    assert str(table.constants["src.v"]) == "src.V"
    # the ground potential and its current are constants, potentials are aliases
    assert table.constants["gnd.p.v"] == 0 and table.constants["gnd.p.i"] == 0
    sign, root = table.resolve("R1.n.v")
    assert sign == 1 and root == "C1.v"
    (s1, r1), (s2, r2) = table.resolve("src.i"), table.resolve("R1.i")
    assert r1 == r2 and s1 == -s2          # the source current is the resistor's, reversed


def test_every_flat_variable_is_in_the_result():
    flat = flatten(RC())
    res = ac.simulate(RC(), t_end=0.05, rtol=1e-6, n_points=5)
    assert {v.name for v in flat.variables} <= set(res.names)
    assert np.allclose(res["gnd.p.v"], 0.0) and np.allclose(res["C1.n.i"], -res["C1.i"])


class Spun(ac.Component):
    """A flange fixed at a parameter angle: phi = phi0 is a constant, not an equation."""

    wall = Fixed(phi0=0.3)
    k = Spring(c=10.0)
    J = Inertia(J=1.0, phi={"start": 0.5, "fixed": True}, w={"start": 0.0, "fixed": True})

    def equations(self):
        return [ac.connect(self.wall.flange, self.k.flange_a),
                ac.connect(self.k.flange_b, self.J.flange_a)]


def test_variable_fixed_to_a_parameter_is_a_constant_and_tunable():
    compiled = ac.compile(Spun())
    assert "wall.flange.phi" not in compiled.names          # eliminated
    t = np.linspace(0, 2, 21)
    res = ac.simulate(compiled, t_end=2, rtol=1e-9, t_eval=t, parameters={"wall.phi0": 0.1})
    assert np.allclose(res["wall.flange.phi"], 0.1)
    # the inertia oscillates about the (new) wall angle: 0.1 + 0.4 cos(sqrt(10) t)
    assert np.max(np.abs(res["J.phi"] - (0.1 + 0.4 * np.cos(np.sqrt(10) * t)))) < 1e-7





class TwoCapacitorsInParallel(ac.Component):
    """Two capacitors on the same node pair, both with v fixed at the start (as the
    MSL's GenerationOfFMUs fixes a capacitor and its copy behind signal adaptors), and
    a resistor discharging them: v = v0 exp(-t / (R (C1 + C2)))."""

    C1 = Capacitor(C=1e-3, v={"start": 0.0, "fixed": True})
    C2 = Capacitor(C=2e-3, v={"start": 0.0, "fixed": True})
    R = Resistor(R=10.0)
    gnd = Ground()

    def equations(self):
        return [ac.connect(self.C1.p, self.C2.p, self.R.p),
                ac.connect(self.C1.n, self.C2.n, self.R.n, self.gnd.p)]


class TwoCapacitorsAntiParallel(TwoCapacitorsInParallel):
    """The same with C2 turned round: C2.v = -C1.v."""

    @ac.replaces(TwoCapacitorsInParallel)
    def equations(self):
        return [ac.connect(self.C1.p, self.C2.n, self.R.p),
                ac.connect(self.C1.n, self.C2.p, self.R.n, self.gnd.p)]


def test_aliases_with_the_same_fixed_start_zero_are_one_variable():
    """0 and 0.0 are the same start value (the signed copy of a float 0.0 is sympy's
    integer 0): the two fixed starts agree and the capacitors share one state."""
    t = np.linspace(0.0, 0.1, 11)
    res = ac.simulate(TwoCapacitorsInParallel(), t_end=0.1, rtol=1e-9, t_eval=t)
    assert np.all(res["C1.v"] == 0.0) and np.all(res["C2.v"] == 0.0)
    # the same with another start on both
    two = {"v": {"start": 2.0, "fixed": True}}
    res = ac.simulate(TwoCapacitorsInParallel(C1=two, C2=two),
                      t_end=0.1, rtol=1e-10, t_eval=t)
    tau = 10.0 * 3e-3
    assert np.max(np.abs(res["C2.v"] - 2.0 * np.exp(-t / tau))) < 1e-7
    # a reversed copy: 0.0 and -0.0, then 2 and -2
    res = ac.simulate(TwoCapacitorsAntiParallel(), t_end=0.1, rtol=1e-9, t_eval=t)
    assert np.all(res["C1.v"] == 0.0) and np.all(res["C2.v"] == 0.0)
    res = ac.simulate(TwoCapacitorsAntiParallel(
        C1=two, C2={"v": {"start": -2.0, "fixed": True}}), t_end=0.1, rtol=1e-10, t_eval=t)
    assert np.max(np.abs(res["C1.v"] - 2.0 * np.exp(-t / tau))) < 1e-7


def test_aliases_with_different_fixed_starts_are_refused():
    # one variable with two conditions that disagree: refused at the initial point,
    # naming both (a consistent second condition is dropped, runtime/redundant.py)
    with pytest.raises(ac.InitializationFailed,
                       match=r"over-specified and inconsistent.*C1\.v = 0\.0.*C2\.v = 1\.0"):
        ac.simulate(TwoCapacitorsInParallel(C2={"v": {"start": 1.0, "fixed": True}}), 0.1)


class CapacitorAcrossConstantSource(ac.Component):
    """A capacitor across a constant 1 V source (and a resistor): its voltage is the
    source's parameter V, a constant that alias elimination substitutes."""

    def __init__(self, v_start):
        super().__init__()
        from acausal.library.electrical import ConstantVoltage
        self.src = ConstantVoltage(V=1.0)
        self.C = Capacitor(C=1e-3, v={"start": v_start, "fixed": True})
        self.R = Resistor(R=10.0)
        self.gnd = Ground()

    def equations(self):
        return [ac.connect(self.src.p, self.C.p, self.R.p),
                ac.connect(self.src.n, self.C.n, self.R.n, self.gnd.p)]


def test_fixed_start_contradicting_a_parameter_constant_is_refused():
    # C.v = src.V = 1 by the equations; C.v(0) = -0.1 fixed contradicts it: refused
    # naming the variable, not dropped without a word
    with pytest.raises(ac.ModelError, match=r"'C\.v'.*start = -0\.1.*constant 1"):
        ac.compile(CapacitorAcrossConstantSource(-0.1))
    # the same value is consistent: it runs, at the source's voltage
    res = ac.simulate(ac.compile(CapacitorAcrossConstantSource(1.0)), t_end=0.1)
    assert res.success and np.all(res["C.v"] == 1.0)
