"""Hierarchical connectors (Modelica 3.5, section 9.1: a connector made of connectors,
as a polyphase plug of pins): ``connect`` of two such ports connects member by member,
and a member of a component's own port is seen from inside that component (its flow
enters the component's node equations with the outside sign)."""
import pytest

import acausal as ac
from acausal.library.electrical import ConstantVoltage, Ground, Resistor
from acausal.ports import Pin


class Pair(ac.Port):
    """Two pins."""

    def build(self):
        self.a = Pin()
        self.b = Pin()


class TwoResistors(ac.Component):
    """A resistor per member, each from plug_p's member to plug_n's."""

    R = ac.Parameter(1.0)
    R2 = ac.Parameter(lambda c: 2 * c.R)
    plug_p = Pair()
    plug_n = Pair()
    ra = Resistor(R=ac.ref("R"))
    rb = Resistor(R=ac.ref("R2"))

    def equations(self):
        return [ac.connect(self.plug_p.a, self.ra.p), ac.connect(self.ra.n, self.plug_n.a),
                ac.connect(self.plug_p.b, self.rb.p), ac.connect(self.rb.n, self.plug_n.b)]


class Circuit(ac.Component):
    """Sources on two pins, through two TwoResistors in series, into ground."""

    va = ConstantVoltage(V=3.0)
    vb = ConstantVoltage(V=5.0)
    first = TwoResistors(R=1.0)
    second = TwoResistors(R=2.0)
    ground = Ground()

    def equations(self):
        c = ac.connect
        return [c(self.va.p, self.first.plug_p.a), c(self.vb.p, self.first.plug_p.b),
                c(self.first.plug_n, self.second.plug_p),            # member by member
                c(self.second.plug_n.a, self.second.plug_n.b, self.ground.p),
                c(self.va.n, self.vb.n, self.ground.p)]


def test_plugs_connect_member_by_member_with_the_right_flow_signs():
    res = ac.simulate(Circuit(), t_end=1.0)
    # member a: 3 V over 1 + 2 Ohm; member b: 5 V over 2 + 4 Ohm
    assert res["first.ra.i"][-1] == pytest.approx(1.0, rel=1e-12)
    assert res["second.ra.i"][-1] == pytest.approx(1.0, rel=1e-12)
    assert res["first.rb.i"][-1] == pytest.approx(5 / 6, rel=1e-12)
    assert res["second.plug_p.b.v"][-1] == pytest.approx(5 * 4 / 6, rel=1e-12)
    assert res["first.plug_n.a.i"][-1] == pytest.approx(-1.0, rel=1e-12)


def test_connect_of_plugs_returns_one_connection_per_member():
    model = Circuit()
    conns = ac.connect(model.first.plug_n, model.second.plug_p)
    assert isinstance(conns, list) and len(conns) == 2
