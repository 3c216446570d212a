"""The reference solver of the random-network tests, checked on its own: against closed
forms, against scipy's solve_ivp on hand-reduced ODEs (rtol 1e-12), and on random
networks through the DAE residual (its solution must satisfy E x' = A x + B u) and the
initial condition.  None of this runs acausal."""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

from .generators import electrical_network, ill_posed_network, mechanical_network
from .harness import make_case
from .netlists import Element, Netlist, SeededChooser
from .reference import Reference


def _net(domain, *elements):
    return Netlist(domain, tuple(Element(*e) for e in elements))


def _terms(net):
    return {el.name: el.terms for el in net.elements if el.terms}


def _ode(rhs, t, y0):
    sol = solve_ivp(rhs, (0, t[-1]), y0, t_eval=t, method="DOP853", rtol=1e-12, atol=1e-15)
    assert sol.success
    return sol.y


def test_rc_low_pass_matches_the_closed_form():
    """R C v' + v = a sin(w t), v(0) = 0:
    v = a / (1 + (w tau)^2) (sin w t - w tau cos w t + w tau exp(-t / tau))."""
    a, f, R, C = 2.0, 30.0, 470.0, 2.2e-5
    net = _net("electrical", ("V", "V1", 1, 0, None, ((a, f),)), ("R", "R1", 1, 2, "470"),
               ("C", "C1", 2, 0, "2.2e-5"))
    ref = Reference(net)
    assert ref.regular and ref.ns == 1 and ref.index == 1
    t = np.linspace(0, 0.05, 41)
    w, tau = 2 * np.pi * f, R * C
    exact = a / (1 + (w * tau) ** 2) * (np.sin(w * t) - w * tau * np.cos(w * t)
                                        + w * tau * np.exp(-t / tau))
    got = ref.solve(t, _terms(net))
    assert np.max(np.abs(got["C1.v"] - exact)) < 1e-12 * a
    assert np.max(np.abs(got["R1.i"] - (a * np.sin(w * t) - exact) / R)) < 1e-12 * a / R


def test_capacitors_across_a_voltage_source_carry_C_du_dt():
    """Index 2: i_C = C u'(t) exactly, already at t = 0 (the initial values of an
    algebraic variable depend on the slope of the source)."""
    a, f = 1.5, 50.0
    net = _net("electrical", ("V", "V1", 1, 0, None, ((a, f),)), ("C", "C1", 1, 0, "1e-4"),
               ("C", "C2", 1, 2, "3.3e-5"), ("R", "R1", 2, 0, "1e3"))
    ref = Reference(net)
    assert ref.regular and ref.index == 2 and ref.ns == 1
    t = np.linspace(0, 0.04, 33)
    got = ref.solve(t, _terms(net))
    w = 2 * np.pi * f
    assert np.max(np.abs(got["C1.i"] - 1e-4 * a * w * np.cos(w * t))) < 1e-12 * 1e-4 * a * w
    # the C2-R1 branch: R C2 v' + v = u for the resistor voltage's complement
    y = _ode(lambda s, v: [(a * np.sin(w * s) - v[0]) / (1e3 * 3.3e-5)], t, [0.0])
    assert np.max(np.abs(got["C2.v"] - y[0])) < 1e-10 * a


def test_inductor_in_series_with_a_current_source_has_v_L_du_dt():
    a, f, L = 0.02, 10.0, 0.47
    net = _net("electrical", ("I", "I1", 0, 1, None, ((a, f),)), ("L", "L1", 1, 2, "0.47"),
               ("R", "R1", 2, 0, "100"))
    ref = Reference(net)
    assert ref.regular and ref.index == 2 and ref.ns == 0
    t = np.linspace(0, 0.2, 21)
    got = ref.solve(t, _terms(net))
    w = 2 * np.pi * f
    # the source pushes u out of its n pin (node 1), into the inductor
    assert np.max(np.abs(got["L1.i"] - a * np.sin(w * t))) < 1e-12 * a
    assert np.max(np.abs(got["L1.v"] - L * a * w * np.cos(w * t))) < 1e-12 * L * a * w


def test_mass_spring_damper_matches_solve_ivp():
    """m x'' = F - c x - d x'  (a force on node 1, spring and damper to the housing)."""
    m, c, d, a, f = 2.2, 1500.0, 3.3, 0.5, 2.0
    net = _net("translational", ("mass", "M1", 1, None, "2.2"), ("spring", "S1", 1, 0, "1500"),
               ("damper", "D1", 0, 1, "3.3"), ("force", "F1", 1, None, None, ((a, f),)))
    ref = Reference(net)
    assert ref.regular and ref.ns == 2
    t = np.linspace(0, 1.0, 51)
    w = 2 * np.pi * f
    y = _ode(lambda s, x: [x[1], (a * np.sin(w * s) - c * x[0] - d * x[1]) / m], t, [0, 0])
    got = ref.solve(t, _terms(net))
    scale = np.max(np.abs(y[0]))
    assert np.max(np.abs(got["M1.s"] - y[0])) < 1e-9 * scale
    # S1 runs from node 1 (flange_a) to the housing: s_rel = 0 - x
    assert np.max(np.abs(got["S1.s_rel"] + y[0])) < 1e-9 * scale
    assert np.max(np.abs(got["D1.f"] - d * y[1])) < 1e-9 * d * np.max(np.abs(y[1]))


def test_two_inertias_through_an_ideal_gear_match_the_reduced_ode():
    """phi_1 = n phi_2 (index 3): (J1 + J2 / n^2) phi_1'' = T - c phi_1."""
    J1, J2, n, c, a, f = 0.01, 0.05, 3.0, 40.0, 0.2, 1.5
    net = _net("rotational", ("mass", "J1", 1, None, "0.01"), ("gear", "G1", 1, 2, "3"),
               ("mass", "J2", 2, None, "0.05"), ("spring", "S1", 0, 1, "40"),
               ("force", "T1", 1, None, None, ((a, f),)))
    ref = Reference(net)
    assert ref.regular and ref.ns == 2 and ref.index == 3
    t = np.linspace(0, 2.0, 41)
    w, Je = 2 * np.pi * f, J1 + J2 / n**2
    y = _ode(lambda s, x: [x[1], (a * np.sin(w * s) - c * x[0]) / Je], t, [0, 0])
    got = ref.solve(t, _terms(net))
    assert np.max(np.abs(got["J1.phi"] - y[0])) < 1e-9 * np.max(np.abs(y[0]))
    assert np.max(np.abs(got["J2.phi"] - y[0] / n)) < 1e-9 * np.max(np.abs(y[0]))
    # the gear's torque on J2 is what accelerates it:  J2 phi_2'' = flange_b torque on J2
    acc2 = (a * np.sin(w * t) - c * y[0]) / Je / n
    assert np.max(np.abs(got["J2.flange_a.tau"] - J2 * acc2)) < 1e-8 * np.max(np.abs(J2 * acc2))


@pytest.mark.parametrize("elements", [
    # two voltage sources in parallel, equal waves: consistent, but the split of the
    # current between them is free
    [("V", "V1", 1, 0, None, ((1.0, 1.0),)), ("V", "V2", 1, 0, None, ((1.0, 1.0),)),
     ("R", "R1", 1, 0, "10")],
    # a node reached only through current sources
    [("I", "I1", 0, 1, None, ((1.0, 1.0),)), ("I", "I2", 1, 0, None, ((1.0, 1.0),)),
     ("R", "R1", 2, 0, "10")],
    # a part without ground
    [("V", "V1", 1, 0, None, ((1.0, 1.0),)), ("R", "R1", 1, 0, "10"),
     ("C", "C1", 2, 3, "1e-3")],
], ids=["V||V", "I in series", "floating"])
def test_ill_posed_networks_have_a_singular_pencil(elements):
    assert not Reference(_net("electrical", *elements)).regular


@pytest.mark.parametrize("strategy", ["electrical", "translational", "rotational"])
def test_random_reference_solutions_satisfy_the_dae(strategy):
    """E x' - A x - B u = 0 along the solution (x' from the augmented ODE, exactly
    the derivative of x), the candidate states are 0 at t = 0, and the matrix
    exponential agrees with scipy's Radau on the augmented ODE (rtol 1e-12)."""
    for k in range(4):
        case = make_case(SeededChooser(f"reference:{strategy}:{k}"), strategy)
        ref = case.ref
        if case.net.expect != "regular":
            assert not ref.regular
            continue
        terms = _terms(case.net)
        x, xp, u = ref.trajectories(case.times, terms)
        r = xp @ ref.E.T - x @ ref.A.T - u @ ref.B.T
        size = (np.abs(xp) @ np.abs(ref.E).T + np.abs(x) @ np.abs(ref.A).T
                + np.abs(u) @ np.abs(ref.B).T)
        assert np.all(np.abs(r) <= 1e-9 * np.max(size, axis=0) + 1e-300), case.net.describe()
        peak = np.max(np.abs(x), axis=0)
        M, Cx, xi0, _ = ref.system(terms)
        sol = solve_ivp(lambda s, y: M @ y, (0, case.times[-1]), xi0, method="Radau",
                        jac=M, t_eval=case.times, rtol=1e-9, atol=1e-13)
        assert sol.success
        assert np.all(np.abs(sol.y.T @ Cx.T - x) <= 1e-6 * np.max(peak)), case.net.describe()
        x0 = x[0]
        for name in ref.candidates:
            i = ref.index_of[name]
            assert abs(x0[i]) <= 1e-12 * max(peak[i], 1e-300), (name, case.net.describe())


def test_generators_are_deterministic():
    for draw in (electrical_network, lambda ch: mechanical_network(ch, "rotational"),
                 lambda ch: ill_posed_network(ch, "translational")):
        assert draw(SeededChooser("same")) == draw(SeededChooser("same"))
