"""Symbolic linearization: the book's matrices in the parameters, and agreement with the
numerical linearization at an operating point of a nonlinear, index-reduced model."""
import numpy as np
import sympy as sp

from acausal.analysis import linearize, linearize_symbolic, steady_state

from .test_linearize import GearedMotor, VoltageDrivenMotor


def test_dc_motor_matrices_in_the_parameters_3_41_3_43():
    sys = linearize_symbolic(VoltageDrivenMotor(), ["u_a"], ["motor.rotor.w"])
    R, L, k, J = sp.symbols("motor.R motor.L motor.k motor.J", real=True)
    assert sys.states == ["motor.La.i", "motor.emf.flange.phi", "motor.rotor.w"]
    # L i' = -R i - K w + u,  J w' = K i,  phi' = w
    assert sp.simplify(sys.A - sp.Matrix([[-R / L, 0, -k / L], [0, 0, 1], [k / J, 0, 0]])) \
        == sp.zeros(3, 3)
    assert sys.B == sp.Matrix([1 / L, 0, 0])
    poles = sys.numeric({"motor.R": 1.5, "motor.L": 2e-3, "motor.k": 0.06,
                         "motor.J": 2e-4}).minimal().poles()
    T_a, T_m = 2e-3 / 1.5, 2e-4 * 1.5 / 0.06**2
    assert np.allclose(np.sort_complex(poles), np.sort_complex(np.roots([T_a * T_m, T_m, 1])),
                       rtol=1e-12)


def test_agrees_with_the_numerical_linearization_through_a_gear():
    op = steady_state(GearedMotor(), inputs={"u_a": 12.0}, hold=["motor.emf.flange.phi"])
    numeric = linearize(op.compiled, ["u_a"], ["load.w", "motor.La.i"], at=op)
    sym = linearize_symbolic(GearedMotor(), ["u_a"], ["load.w", "motor.La.i"], simplify=False)
    c = op.compiled
    values = {p[len("plant."):]: v for p, v in zip(c.param_names, c.p) if p.startswith("plant.")}
    values.update(op.states)
    at = sym.numeric(values)
    assert at.states == numeric.states
    for M, N in ((at.A, numeric.A), (at.B, numeric.B), (at.C, numeric.C), (at.D, numeric.D)):
        assert np.allclose(M, N, rtol=1e-8, atol=1e-8 * np.abs(N).max())
