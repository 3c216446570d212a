"""NM-02/NM-03: the index examples 1.1 and 1.2 of the DTU notes (000 §2.1.2,
(2.1.3)-(2.1.18)).

Example 1.1 (NM-02), a singular algebraic constraint:

    y_1' = y_3,   0 = y_2 (1 - y_2),   0 = y_1 y_2 + y_3 (1 - y_2) - t          (2.1.3)-(2.1.5)

The notes' two cases: y_2 = 0, then y_3 = t and y_1 integrates to y_1(0) + t^2/2; and
y_2 = 1, then y_1 = t and y_3 = 1.  The Jacobian of the two algebraic equations with
respect to (y_2, y_3) has determinant (1 - 2 y_2)(1 - y_2): the branch y_2 = 0 is index
1, the branch y_2 = 1 makes it singular -- y_1 = t is then a constraint on the
differential variable, and the branch is index 2 (INVENTORY NM-02, derived there).  An
analysis of the incidence pattern sees index 1 on both.  Checked: the index report says
index 1 and flags both algebraic blocks as of variable regularity; from a guess near 0
the run follows the y_2 = 0 branch exactly (closed form); from a guess near 1 the
initialization lands on y_2 = 1 and the report names the singular block (equation
(2.1.5), variable y_3) at t = 0.  The run of that branch neither integrates it (y_1 = t,
y_3 = 1) nor names the singular Jacobian in its failure message: an expected failure.

Example 1.2 (NM-03), a Hessenberg index-2 system y' = f(y, z), 0 = g(y) (2.1.6)-(2.1.7):
with g_y f_z invertible one differentiation gives 0 = g_y f (2.1.8), two give an ODE for
z ((2.1.12)-(2.1.13)): index 2.  An instance on the unit circle with an input u(t):

    y_1' = y_2 + z y_1,   y_2' = -y_1 + z y_2 + u(t),   0 = y_1^2 + y_2^2 - 1,   u = sin t

g_y f_z = 2 (y_1^2 + y_2^2) = 2, and with y = (cos th, sin th) the exact solution is
th' = -1 + u cos th, z = -u sin th (worked by hand: g' = 2 z + 2 y_2 u = 0).  Checked:
the report's differential index is 2 with the constraint differentiated once and z not
a state; y and z agree with scipy's solve_ivp (rtol 1e-11) on the th-equation; the
constraint holds along the run to the solver's tolerance relative to |y| = 1.
"""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

import acausal as ac


class SingularConstraint(ac.Component):
    """Example 1.1 (000 (2.1.3)-(2.1.5))."""

    y1 = ac.Variable(start=0.0)
    y2 = ac.Variable(start=0.0)
    y3 = ac.Variable(start=0.0)

    def equations(self):
        return [ac.Eq(ac.der(self.y1), self.y3),
                ac.Eq(0, self.y2 * (1 - self.y2)),
                ac.Eq(0, self.y1 * self.y2 + self.y3 * (1 - self.y2) - ac.time)]


class Hessenberg2(ac.Component):
    """Example 1.2 (000 (2.1.6)-(2.1.7)) on the unit circle, forced by u = sin t."""

    # th(0) = 0.5: y_1 fixed, y_2 from the constraint (the guess picks the root)
    y1 = ac.Variable(start=float(np.cos(0.5)), fixed=True)
    y2 = ac.Variable(start=0.5)
    z = ac.Variable(start=0.0)

    def equations(self):
        u = ac.sin(ac.time)
        return [ac.Eq(ac.der(self.y1), self.y2 + self.z * self.y1),
                ac.Eq(ac.der(self.y2), -self.y1 + self.z * self.y2 + u),
                ac.Eq(0, self.y1**2 + self.y2**2 - 1)]


def test_example_1_1_report_is_structural_index_1():
    compiled = ac.compile(SingularConstraint())
    assert compiled.report.differential_index == 1
    assert compiled.report.states == ["y1"]
    # regularity of the (y2) and (y3) blocks depends on the point
    assert any("regularity is not decided" in n and "[y2]" in n and "[y3]" in n
               for n in compiled.report.notes)


def test_example_1_1_branch_y2_0():
    model = SingularConstraint(y1={"start": 0.5, "fixed": True}, y2={"start": 0.1})
    res = ac.simulate(model, t_end=2.0, rtol=1e-9, n_points=41, raise_on_failure=True)
    t = res.t
    assert np.max(np.abs(res["y2"])) < 1e-10
    assert np.max(np.abs(res["y3"] - t)) < 1e-8 * np.max(t)
    exact = 0.5 + t**2 / 2
    assert np.max(np.abs(res["y1"] - exact)) < 1e-8 * np.max(exact)


def test_example_1_1_branch_y2_1_is_flagged_at_the_initial_point():
    compiled = ac.compile(SingularConstraint(y1={"start": 0.0, "fixed": True},
                                             y2={"start": 0.9}))
    z0, _ = compiled.initialize(0.0)
    values = dict(zip(compiled.names, z0))
    assert values["y2"] == pytest.approx(1.0, abs=1e-12)
    flagged = [n for n in compiled.report.notes if n.startswith("structural analysis fails")]
    assert flagged and "y3" in flagged[0] and "y1*y2" in flagged[0]


def test_example_1_1_branch_y2_1_run():
    """On the branch y2 = 1 the structure found at compile time (index 1) does not hold
    (index 2: y3 follows from differentiating y1 = t).  The run either integrates the
    branch (y1 = t, y3 = 1) or stops naming the singular Jacobian at the start and y3;
    it never ends with a message that hides that."""
    compiled = ac.compile(SingularConstraint(y1={"start": 0.0, "fixed": True},
                                             y2={"start": 0.9}))
    with pytest.warns(RuntimeWarning):
        res = ac.simulate(compiled, t_end=2.0, rtol=1e-9, n_points=41)
    if res.success:
        assert np.max(np.abs(res["y1"] - res.t)) < 1e-6 * 2.0
        assert np.max(np.abs(res["y3"] - 1.0)) < 1e-6
    else:
        assert "singular" in res.message and "y3" in res.message


def test_example_1_2_report_is_index_2():
    report = ac.compile(Hessenberg2()).report
    assert report.differential_index == 2
    constraint = [e for e in report.equations if e["text"].startswith("0 = y1**2")]
    assert len(constraint) == 1 and constraint[0]["differentiated"] == 1
    assert "z" not in report.states
    assert len(report.states) == 1           # one degree of freedom on the circle


def test_example_1_2_solution():
    res = ac.simulate(Hessenberg2(), t_end=6.0, rtol=1e-10, n_points=301,
                      raise_on_failure=True)
    ref = solve_ivp(lambda t, th: -1.0 + np.sin(t) * np.cos(th), (0.0, 6.0), [0.5],
                    method="DOP853", rtol=1e-11, atol=1e-13, t_eval=res.t)
    th = ref.y[0]
    assert np.max(np.abs(res["y1"] - np.cos(th))) < 1e-7
    assert np.max(np.abs(res["y2"] - np.sin(th))) < 1e-7
    z = -np.sin(res.t) * np.sin(th)
    assert np.max(np.abs(res["z"] - z)) < 1e-6 * np.max(np.abs(z))
    assert np.max(np.abs(res["y1"]**2 + res["y2"]**2 - 1.0)) < 1e-8
