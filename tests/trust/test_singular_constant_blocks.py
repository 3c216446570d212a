"""Linear constant-coefficient models whose structure says more than their numbers do.

The structural passes (matching, Pantelides, Pryce's Sigma-method) see which variables
appear, not the coefficients; a block that is structurally regular can be numerically
singular, and then the structural index and state count are wrong.

1. A circuit in nodal form, written as one component: node potentials as variables,
   Kirchhoff's current law per node, capacitors between two non-ground nodes, so that
   C (U_i' - U_j') appears in two node equations.  The capacitance matrix is singular
   (no capacitor touches ground): only the capacitor voltages are states, the node
   potentials are fixed by them algebraically, and the DAE has differential index 1.

   * Two nodes: source u(t) - R_1 - node 1 - C - node 2 - R_2 - ground.  With
     v = U_1 - U_2:  C v' = (u - v)/(R_1 + R_2),  U_2 = R_2 (u - v)/(R_1 + R_2).
   * Three nodes: u - R_1 - node 1; C_1 between nodes 1 and 2; C_2 between 2 and 3;
     R_2, R_3 from nodes 2, 3 to ground; R_4 between nodes 1 and 3.  With
     v_1 = U_1 - U_2, v_2 = U_2 - U_3 (by hand, from the three KCL rows):
         U_3 (1/R_1 + 1/R_2 + 1/R_3) = (u - v_1 - v_2)/R_1 - v_2/R_2
         C_1 v_1' = (u - U_1)/R_1 - (U_1 - U_3)/R_4,   C_2 v_2' = U_3/R_3 - (U_1 - U_3)/R_4

   Values: resistors 1 - 4.7 kOhm, capacitors 1 - 2.2 uF, u = 5 V sin(2 pi 100 Hz t),
   capacitors uncharged at t = 0.  Reference: the hand-reduced ODE under scipy's
   solve_ivp (DOP853, rtol 1e-12).

2. A Mattsson-Soederlind-type higher-order system (constructed here):

       x1'' + x2'' + x3        = f1(t)
       x1'' + x2'' + x3' + 2x3 = f2(t)
       x1'  + x3'  - x2        = f3(t)

   Pryce's offsets are c = (0, 0, 0), d = (2, 2, 1) (signature sum 5), and the system
   Jacobian at the highest derivatives (x1'', x2'', x3') is [[1, 1, 0], [1, 1, 1],
   [0, 0, 1]], structurally regular and numerically singular.  By hand: row 2 - row 1
   gives x3' + x3 = f2 - f1 (1 state), row 1 gives w'' = f1 - x3 for w = x1 + x2
   (2 states), row 3 gives x1' + x1 = w + f3 - x3' (1 state): 4 degrees of freedom, not
   the structural 5.  The forcing is chosen so that x1 = sin t, x2 = cos 2t,
   x3 = exp(-t) is the solution; with the 4 initial conditions x1(0) = 0, x2(0) = 1,
   x3(0) = 1, x2'(0) = 0 it is the only one.
"""
import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

import acausal as ac

R1, R2, R3, R4, C1, C2 = 1e3, 2.2e3, 4.7e3, 1.5e3, 1e-6, 2.2e-6
V0, F_HZ, T_END = 5.0, 100.0, 0.02


def _source(t):
    return V0 * np.sin(2 * np.pi * F_HZ * t)


class TwoNodeNodal(ac.Component):
    """u - R1 - node 1 - C - node 2 - R2 - ground, KCL at nodes 1 and 2."""

    R1 = ac.Parameter(R1, unit="Ohm")
    R2 = ac.Parameter(R2, unit="Ohm")
    C = ac.Parameter(C1, unit="F")
    U1 = ac.Variable(start=0.0, unit="V")
    U2 = ac.Variable(start=0.0, unit="V")

    def equations(self):
        u = V0 * sp.sin(2 * sp.pi * F_HZ * ac.time)
        i_c = self.C * (ac.der(self.U1) - ac.der(self.U2))
        return [ac.Eq((u - self.U1) / self.R1, i_c),
                ac.Eq(i_c, self.U2 / self.R2)]

    def initial_equations(self):
        return [ac.Eq(self.U1 - self.U2, 0)]


class ThreeNodeNodal(ac.Component):
    """Two capacitors in series between nodes 1-2 and 2-3, none to ground."""

    R1 = ac.Parameter(R1, unit="Ohm")
    R2 = ac.Parameter(R2, unit="Ohm")
    R3 = ac.Parameter(R3, unit="Ohm")
    R4 = ac.Parameter(R4, unit="Ohm")
    C1 = ac.Parameter(C1, unit="F")
    C2 = ac.Parameter(C2, unit="F")
    U1 = ac.Variable(start=0.0, unit="V")
    U2 = ac.Variable(start=0.0, unit="V")
    U3 = ac.Variable(start=0.0, unit="V")

    def equations(self):
        u = V0 * sp.sin(2 * sp.pi * F_HZ * ac.time)
        i1 = self.C1 * (ac.der(self.U1) - ac.der(self.U2))
        i2 = self.C2 * (ac.der(self.U2) - ac.der(self.U3))
        bridge = (self.U1 - self.U3) / self.R4
        return [ac.Eq((u - self.U1) / self.R1, i1 + bridge),
                ac.Eq(i1, self.U2 / self.R2 + i2),
                ac.Eq(i2 + bridge, self.U3 / self.R3)]

    def initial_equations(self):
        return [ac.Eq(self.U1 - self.U2, 0), ac.Eq(self.U2 - self.U3, 0)]


def _two_node_reference(t):
    def rhs(tt, v):
        return [(_source(tt) - v[0]) / ((R1 + R2) * C1)]
    sol = solve_ivp(rhs, (0.0, T_END), [0.0], method="DOP853", rtol=1e-12, atol=1e-14,
                    t_eval=t)
    v = sol.y[0]
    U2 = R2 * (_source(t) - v) / (R1 + R2)
    return {"U1": v + U2, "U2": U2}


def _three_node_potentials(t, v1, v2):
    U3 = ((_source(t) - v1 - v2) / R1 - v2 / R2) / (1 / R1 + 1 / R2 + 1 / R3)
    return U3 + v1 + v2, U3 + v2, U3


def _three_node_reference(t):
    def rhs(tt, v):
        U1, _, U3 = _three_node_potentials(tt, v[0], v[1])
        bridge = (U1 - U3) / R4
        return [((_source(tt) - U1) / R1 - bridge) / C1, (U3 / R3 - bridge) / C2]
    sol = solve_ivp(rhs, (0.0, T_END), [0.0, 0.0], method="DOP853", rtol=1e-12,
                    atol=1e-14, t_eval=t)
    U1, U2, U3 = _three_node_potentials(t, sol.y[0], sol.y[1])
    return {"U1": U1, "U2": U2, "U3": U3}


NODAL = {"two nodes": (TwoNodeNodal, _two_node_reference, 1),
         "three nodes": (ThreeNodeNodal, _three_node_reference, 2)}


@pytest.mark.parametrize("case", sorted(NODAL))
def test_nodal_form_reports_index_one_and_the_capacitor_states(case):
    model, _, n_caps = NODAL[case]
    report = ac.compile(model()).report
    assert report.differential_index == 1
    assert len(report.states) == n_caps


@pytest.mark.parametrize("case", sorted(NODAL))
def test_nodal_form_matches_the_hand_reduced_ode(case):
    model, reference, _ = NODAL[case]
    t = np.linspace(0.0, T_END, 201)
    res = ac.simulate(model(), t_end=T_END, rtol=1e-9, t_eval=t)
    assert res.success, res.message
    ref = reference(t)
    scale = max(np.max(np.abs(u)) for u in ref.values())
    for name, u in ref.items():
        assert np.max(np.abs(res[name] - u)) < 1e-6 * scale, name


class SingularLeadingBlock(ac.Component):
    """The three equations of the module docstring, x1 = sin t, x2 = cos 2t, x3 = e^-t."""

    x1 = ac.Variable(start=0.0, fixed=True)
    x2 = ac.Variable(start=1.0, fixed=True)
    x3 = ac.Variable(start=1.0, fixed=True)
    v2 = ac.Variable(start=0.0, fixed=True, description="x2'")

    def equations(self):
        d, t = ac.der, ac.time
        x1, x2, x3 = self.x1, self.x2, self.x3
        x2_exact, x3_exact = sp.cos(2 * t), sp.exp(-t)
        w_dd = -sp.sin(t) - 4 * sp.cos(2 * t)                 # (x1 + x2)''
        return [ac.Eq(d(d(x1)) + d(d(x2)) + x3, w_dd + x3_exact),
                ac.Eq(d(d(x1)) + d(d(x2)) + d(x3) + 2 * x3, w_dd - x3_exact + 2 * x3_exact),
                ac.Eq(d(x1) + d(x3) - x2, sp.cos(t) - x3_exact - x2_exact),
                ac.Eq(self.v2, d(x2))]


def test_singular_leading_block_has_four_states():
    report = ac.compile(SingularLeadingBlock()).report
    assert len(report.states) == 4


def test_singular_leading_block_matches_its_closed_form():
    t = np.linspace(0.0, 2.0, 41)
    res = ac.simulate(SingularLeadingBlock(), t_end=2.0, rtol=1e-10, t_eval=t)
    assert res.success, res.message
    for name, exact in (("x1", np.sin(t)), ("x2", np.cos(2 * t)), ("x3", np.exp(-t))):
        assert np.max(np.abs(res[name] - exact)) < 1e-6 * np.max(np.abs(exact)), name
