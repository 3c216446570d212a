"""An equation whose relation reads the variable the equation defines,
``z = if z > 1 then 2 x else x``: between events the relation is frozen (its value is
the discrete state's), so z is solved linearly with the relation kept as written; the
event iteration then finds the discrete state consistent with z.  Solving by r(z = 0)
once put z = 0 into the relation too (``0 > 1``: z = x for ever, silently)."""
import numpy as np
import pytest
import sympy as sp

import acausal as ac
from acausal.words import TEXT, shortened


class SelfRelation(ac.Component):
    x = ac.Variable(start=0.0, fixed=True)
    z = ac.Variable()

    def equations(self):
        return [ac.Eq(ac.der(self.x), 1),
                ac.Eq(self.z, ac.if_else(self.z > 1, 2 * self.x, self.x))]


class NoConsistentState(ac.Component):
    """After x > 0.5: z = -1 makes the condition false, z = 1 makes it true."""

    x = ac.Variable(start=0.0, fixed=True)
    z = ac.Variable()

    def equations(self):
        s = sum(1e-3 * ac.sin(k * self.x) for k in range(1, 40))   # a long equation
        return [ac.Eq(ac.der(self.x), 1),
                ac.Eq(self.z, ac.if_else(sp.And(self.z + s > 0, self.x > 0.5), -1, 1))]


@pytest.mark.parametrize("step_loop", ["c", "python"])
def test_the_relation_keeps_the_variable_it_reads(step_loop):
    """z = x until x = 1, then the relation z > 1 holds with z = 2 x (closed form)."""
    res = ac.simulate(SelfRelation(), t_end=2.0, n_points=201, step_loop=step_loop)
    assert res.success, res.message
    away = np.abs(res.t - 1.0) > 1e-6
    want = np.where(res.t > 1.0, 2 * res.t, res.t)
    assert np.max(np.abs(res["z"] - want)[away]) < 1e-9 * np.max(np.abs(want))
    assert len(res.events) == 1 and abs(float(res.events[0]) - 1.0) < 1e-9


def test_no_consistent_discrete_state_is_refused_in_bounded_words():
    res = ac.simulate(NoConsistentState(), t_end=1.0)
    assert not res.success
    assert "no consistent discrete state" in res.message
    assert "z + " in res.message                    # the relation as written, with z
    assert "[(model) (NoConsistentState)]" in res.message
    assert len(res.message) < 5 * TEXT


def test_shortened_keeps_the_component_tag():
    text = "v = " + " + ".join(f"a{k}" for k in range(200)) + "  [valve (Valve)]"
    out = shortened(text)
    assert len(out) <= TEXT and out.endswith("... [valve (Valve)]")
    assert out.startswith("v = a0 + a1")


class SelfConstant(ac.Component):
    """z = if z > p then 2 else 0.5 with p = 0.25: z = 0.5 contradicts its relation, so
    z = 2 is the only solution; as an equation of one variable and parameters it was
    once taken for the constant z = (2 if 0 > p else 0.5)."""

    p = ac.Parameter(0.25)
    x = ac.Variable(start=0.0, fixed=True)
    z = ac.Variable()

    def equations(self):
        return [ac.Eq(ac.der(self.x), self.z),
                ac.Eq(self.z, ac.if_else(self.z > self.p, 2.0, 0.5))]


def test_an_equation_of_one_variable_whose_relation_reads_it_is_not_a_constant():
    res = ac.simulate(SelfConstant(), t_end=1.0, n_points=11)
    assert res.success, res.message
    assert np.allclose(res["z"], 2.0, rtol=0, atol=1e-12)
    assert np.allclose(res["x"], 2.0 * res.t, rtol=1e-9, atol=1e-12)


class SelfNoEvent(ac.Component):
    """z = no_event(if z > 1 then 2 x else x): the relation is evaluated live, so z is
    not an assignment but a loop of one equation with a jump (two solutions for
    1/2 < x <= 1); solved as an assignment it read z before computing it, and a second
    run of the same compiled model started on the branch the first one ended on."""

    x = ac.Variable(start=0.0, fixed=True)
    z = ac.Variable()

    def equations(self):
        return [ac.Eq(ac.der(self.x), 1),
                ac.Eq(self.z, ac.no_event(ac.if_else(self.z > 1, 2 * self.x, self.x)))]


def test_a_live_relation_on_the_variable_solved_for_is_refused_naming_it():
    with pytest.raises(ac.InvalidEquation) as info:
        ac.compile(SelfNoEvent(), cache=False)
    text = str(info.value)
    assert "no_event" in text and "solved for z" in text and "(SelfNoEvent)" in text
    assert len(text) < 4 * TEXT
