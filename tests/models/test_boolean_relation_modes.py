"""A Boolean equation whose relation reads an algebraic unknown that itself depends on the
Boolean (the MSL's ideal semiconductors: ``off = s < 0`` where s is solved with ``off``):
the relation is a mode, frozen between events and switched by the event iteration, so
the equation reads no value of the same instant through it (Modelica 3.6, sec. 8.6)."""
import numpy as np
import pytest

import acausal as ac
from acausal.compiler.frontend.sampled import DiscreteVariableError


class BooleanDiode(ac.Component):
    """An ideal diode whose state is a Boolean, as the MSL writes it:

        off = s < 0,   v = s (1 if off else Ron),   i = s (Goff if off else 1)
    """

    v = ac.Variable(unit="V")
    i = ac.Variable(unit="A")
    Ron = ac.Parameter(1e-3, unit="Ohm")
    Goff = ac.Parameter(1e-3, unit="S")
    off = ac.Variable(type=bool, start=True)
    s = ac.Variable(start=0.0)

    def equations(self):
        v, i = self.v, self.i
        return [ac.Eq(self.off, self.s < 0),
                ac.Eq(v, self.s * ac.if_else(self.off, 1, self.Ron)),
                ac.Eq(i, self.s * ac.if_else(self.off, self.Goff, 1))]


class Rectifier(ac.Component):
    """u = U sin(w t + phi) on the diode in series with R to ground."""

    diode = BooleanDiode()
    U = ac.Parameter(10.0, unit="V")
    w = ac.Parameter(2 * np.pi, unit="rad/s")
    phi = ac.Parameter(0.3, unit="rad")
    R = ac.Parameter(2.0, unit="Ohm")

    def equations(self):
        u = self.U * ac.sin(self.w * ac.time + self.phi)
        return [ac.Eq(self.diode.v, u - self.R * self.diode.i)]


def test_a_boolean_that_reads_the_unknown_it_switches_gives_the_rectified_current():
    t = np.linspace(0.0, 2.0, 401)
    res = ac.simulate(Rectifier(), t_end=2.0, rtol=1e-9, t_eval=t, raise_on_failure=True)
    u = 10.0 * np.sin(2 * np.pi * t + 0.3)
    exact = np.where(u > 0, u / (2.0 + 1e-3), u * 1e-3 / (1 + 2.0 * 1e-3))
    assert np.max(np.abs(res["diode.i"] - exact)) < 1e-7 * 5.0
    assert list(res["diode.off"]) == list(u <= 0)
    # two switches a period: off at the zeros of u going down, on going up
    crossings = np.sort(np.concatenate([(np.pi - 0.3 + 2 * np.pi * np.arange(2)),
                                        (2 * np.pi - 0.3 + 2 * np.pi * np.arange(2))]))
    events = np.array([float(e) for e in res.events])
    assert all(np.min(np.abs(events - c / (2 * np.pi))) < 1e-6 for c in crossings)


class Latch(ac.Component):
    """A thyristor-like latch: conducting once fired until its current reverses,
    off = s < 0 or pre(off) and not fire, fired at t = 0.25 s (its pre is read, its
    relation on s is a mode)."""

    diode = BooleanDiode()
    fire = ac.Variable(type=bool)
    latched = ac.Variable(type=bool, start=True)
    U = ac.Parameter(10.0, unit="V")
    w = ac.Parameter(2 * np.pi, unit="rad/s")
    R = ac.Parameter(2.0, unit="Ohm")

    def equations(self):
        u = self.U * ac.sin(self.w * ac.time + 0.3)
        d = self.diode
        return [ac.Eq(self.fire, (ac.time >= 0.25) & (ac.time < 0.3)),
                ac.Eq(self.latched, (d.s < 0) | (ac.pre(self.latched) & ~self.fire)),
                ac.Eq(d.v, u - self.R * d.i)]


def test_a_latch_on_a_mode_conducts_from_its_firing_to_the_current_zero():
    t = np.linspace(0.0, 1.0, 201)
    res = ac.simulate(Latch(), t_end=1.0, rtol=1e-9, t_eval=t, raise_on_failure=True)
    # fired at 0.25 s while u > 0, it conducts until u falls through 0, and is not
    # fired again when u rises through 0
    falls = (np.pi - 0.3) / (2 * np.pi)
    on = (t >= 0.25) & (t < falls)
    away = np.abs(t - 0.25) > 1e-9
    assert list(res["latched"][away]) == list(~on[away])
    assert abs(float(res.events[2]) - falls) < 1e-9


def test_a_loop_through_values_of_the_same_instant_is_still_refused():
    class Loop(ac.Component):
        a = ac.Variable(type=bool, start=False)
        b = ac.Variable(type=bool, start=False)

        def equations(self):
            return [ac.Eq(self.a, ~self.b), ac.Eq(self.b, self.a)]

    with pytest.raises(DiscreteVariableError, match="read each other"):
        ac.compile(Loop())
