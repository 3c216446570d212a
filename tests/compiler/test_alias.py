"""Alias elimination: trivial equations leave, every variable keeps its name."""
import numpy as np

import acausal as ac
from acausal.compiler.frontend.alias import eliminate_aliases
from acausal.compiler.frontend.flatten import flatten
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


