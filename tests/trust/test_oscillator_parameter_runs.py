"""The Modelica Standard Library's Translational.Examples.Oscillator (damped): a 1 kg
mass on a spring-damper to a fixed point at s0 = 1 m, driven by a 1 N, 1 Hz sine force,
released at s = -0.5 m:

    m s'' = F sin(2 pi t) + c (s0 - s - s_rel0) - d s'.

A run with other parameter values (``simulate(..., parameters=...)``) is for that run
only: the next run of the same compiled model, and an equilibrium found afterwards, are
at the values it was compiled with.  An operating point keeps the values it was found at:
read or linearized after another ``steady_state(..., parameters=...)`` of the same model,
it is still that equilibrium.  Reference: the equation above under solve_ivp
(DOP853, rtol 1e-12) with each run's values.
"""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal as ac
from acausal.library import blocks as bl
from acausal.library import translational as tr

M, C, D, S0, S_REL0 = 1.0, 1e4, 10.0, 1.0, 0.5


class Oscillator(ac.Component):
    sine = bl.Sine(amplitude=1.0, f=1.0)
    force = tr.Force()
    mass = tr.Mass(m=M, s={"start": -0.5, "fixed": True}, v={"start": 0.0, "fixed": True})
    sd = tr.SpringDamper(c=C, d=D, s_rel0=S_REL0)
    fixed = tr.Fixed(s0=S0)

    def equations(self):
        return [ac.connect(self.sine.y, self.force.f),
                ac.connect(self.force.flange, self.mass.flange_a),
                ac.connect(self.mass.flange_b, self.sd.flange_a),
                ac.connect(self.sd.flange_b, self.fixed.flange)]


def _reference(t, m=M, c=C, d=D, s0=S0, s_rel0=S_REL0):
    def rhs(tt, z):
        s, v = z
        return [v, (np.sin(2 * np.pi * tt) + c * (s0 - s - s_rel0) - d * v) / m]
    return solve_ivp(rhs, (0.0, t[-1]), [-0.5, 0.0], method="DOP853", rtol=1e-12,
                     atol=1e-14, t_eval=t).y[0]


def _rel(a, b):
    return np.max(np.abs(a - b)) / np.max(np.abs(b))


def test_a_parameter_run_leaves_the_compiled_model_as_it_was():
    compiled = ac.compile(Oscillator(), backend="numpy")
    t = np.linspace(0.0, 1.0, 201)
    changed = {"sd.c": 2000.0, "sd.d": 3.0, "mass.m": 0.5}
    res = ac.simulate(compiled, 1.0, t_eval=t, rtol=1e-9, parameters=changed)
    assert res.success
    assert _rel(res["mass.s"], _reference(t, m=0.5, c=2000.0, d=3.0)) < 1e-6
    again = ac.simulate(compiled, 1.0, t_eval=t, rtol=1e-9)
    assert again.success
    assert _rel(again["mass.s"], _reference(t)) < 1e-6
    moved = ac.simulate(compiled, 1.0, t_eval=t, rtol=1e-9,
                        parameters={"fixed.s0": 2.0, "sd.s_rel0": 1.0})
    assert _rel(moved["mass.s"], _reference(t, s0=2.0, s_rel0=1.0)) < 1e-6
    # the equilibrium is the compiled one's: s = s0 - s_rel0 + F(0)/c = 0.5
    op = ac.steady_state(compiled)
    assert abs(op["mass.s"] - (S0 - S_REL0)) < 1e-9


class LoadedOscillator(Oscillator):
    """The same oscillator under a constant 5 N force (the sine's offset)."""

    sine = bl.Sine(amplitude=0.0, f=1.0, offset=5.0)


def test_an_operating_point_keeps_the_parameters_it_was_found_at():
    """Equilibria at two spring rates of one compiled model: each point is read and
    linearized at its own rate.  Closed form: s* = s0 - s_rel0 + F/c, the spring force
    -F, poles the roots of m s^2 + d s + c."""
    compiled = ac.compile(LoadedOscillator(), backend="numpy")
    soft = ac.steady_state(compiled, parameters={"sd.c": 2000.0})
    stiff = ac.steady_state(compiled, parameters={"sd.c": 1e4})
    assert abs(stiff["mass.s"] - (S0 - S_REL0 + 5.0 / 1e4)) < 1e-9
    assert abs(soft["mass.s"] - (S0 - S_REL0 + 5.0 / 2000.0)) < 1e-9
    assert abs(soft["sd.f"] + 5.0) < 1e-9 * 5.0
    poles = np.sort_complex(np.linalg.eigvals(ac.linearize(compiled, at=soft).A))
    expected = np.sort_complex(np.roots([M, D, 2000.0]))
    assert np.max(np.abs(poles - expected)) < 1e-6 * np.max(np.abs(expected))
    # the compiled model is at the last values set, and reading a point leaves it there
    assert compiled.p[compiled.param_names.index("sd.c")] == 1e4


def test_linearize_through_the_force_input_and_a_port_named_for_it():
    """Force to position: poles the roots of m s^2 + d s + c, static gain 1/c.  Naming
    the RealInput port itself (``force.f``) is refused with its signal named."""
    # the Component: the sine's offset 0 is compiled tunable, so the force is an input
    ss = ac.linearize(Oscillator(), inputs=["force.f.signal"], outputs=["mass.s"])
    poles = np.sort_complex(np.linalg.eigvals(ss.A))
    expected = np.sort_complex(np.roots([M, D, C]))
    assert np.max(np.abs(poles - expected)) < 1e-6 * np.max(np.abs(expected))
    gain = (ss.C @ np.linalg.solve(-ss.A, ss.B) + ss.D).item()
    assert abs(gain * C - 1.0) < 1e-5
    with pytest.raises(KeyError, match="did you mean force.f.signal"):
        ac.linearize(Oscillator(), inputs=["force.f"], outputs=["mass.s"])
