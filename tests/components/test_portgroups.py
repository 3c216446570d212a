"""Connectors made of connectors (ac.PortGroup): Modelica's hierarchical connectors, whose
connection connects their members, and whose members are ports of the component that
holds the group."""
import numpy as np
import pytest

import acausal as ac
from acausal.library.thermal import FixedTemperature, HeatCapacitor, ThermalConductor
from acausal.ports import HeatPort


class Pair(ac.PortGroup):
    a = HeatPort()
    b = HeatPort()


class Other(ac.PortGroup):      # the same members under another class name
    a = HeatPort()
    b = HeatPort()


class Triple(Pair):
    c = HeatPort()


class Bodies(ac.Component):
    """Two capacities behind a group of heat ports, through an internal group as the
    MSL's machines have (internalThermalPort -> thermalPort)."""

    usePort = ac.Parameter(True, structural=True, description="the group exists")
    port = ac.Conditional(Pair(), "usePort")
    internal = Pair()
    c1 = HeatCapacitor(C=2.0, T={"start": 350.0, "fixed": True})
    c2 = HeatCapacitor(C=4.0, T={"start": 330.0, "fixed": True})

    def equations(self):
        eqs = [ac.connect(self.c1.port, self.internal.a),
               ac.connect(self.c2.port, self.internal.b)]
        if self.usePort:
            eqs.append(ac.connect(self.internal, self.port))
        return eqs


class Surroundings(ac.Component):
    """A group whose members lead through conductors to a fixed temperature."""

    port = Other()
    ga = ThermalConductor(G=1.0)
    gb = ThermalConductor(G=0.5)
    env = FixedTemperature(T=300.0)

    def equations(self):
        return [ac.connect(self.port.a, self.ga.port_a),
                ac.connect(self.port.b, self.gb.port_a),
                ac.connect(self.ga.port_b, self.env.port),
                ac.connect(self.gb.port_b, self.env.port)]


class Cooled(ac.Component):
    bodies = Bodies()
    surroundings = Surroundings()

    def equations(self):
        return [ac.connect(self.bodies.port, self.surroundings.port)]


def test_connected_groups_connect_their_members():
    """Each capacity cools through its own conductor: T = 300 + dT0 exp(-G t / C)."""
    t = np.linspace(0.0, 5.0, 11)
    res = ac.simulate(Cooled(), t_end=5.0, t_eval=t, rtol=1e-10, atol=1e-10)
    np.testing.assert_allclose(res["bodies.c1.T"], 300.0 + 50.0 * np.exp(-t / 2.0),
                               rtol=1e-8)
    np.testing.assert_allclose(res["bodies.c2.T"], 300.0 + 30.0 * np.exp(-0.5 * t / 4.0),
                               rtol=1e-8)
    # the members are heat ports of the bodies: the heat leaving them, by name
    np.testing.assert_allclose(res["bodies.port.a.Q_flow"],
                               -(res["bodies.c1.T"] - 300.0), rtol=1e-8)
    # the internal group is connected from outside by nothing: no heat through it
    assert np.all(res["bodies.internal.b.Q_flow"] == 0.0)


def test_a_member_connects_as_a_port_of_its_own():
    class OneByOne(ac.Component):
        bodies = Bodies()
        ga = ThermalConductor(G=1.0)
        gb = ThermalConductor(G=0.5)
        env = FixedTemperature(T=300.0)

        def equations(self):
            return [ac.connect(self.bodies.port.a, self.ga.port_a),
                    ac.connect(self.bodies.port.b, self.gb.port_a),
                    ac.connect(self.ga.port_b, self.env.port),
                    ac.connect(self.gb.port_b, self.env.port)]

    t = np.linspace(0.0, 5.0, 11)
    res = ac.simulate(OneByOne(), t_end=5.0, t_eval=t, rtol=1e-10, atol=1e-10)
    np.testing.assert_allclose(res["bodies.c1.T"], 300.0 + 50.0 * np.exp(-t / 2.0),
                               rtol=1e-8)


def test_groups_connect_only_to_groups_of_the_same_members():
    bodies, other = Bodies(), Triple()
    with pytest.raises(ac.InvalidConnection, match="different types"):
        ac.connect(bodies.port, other)
    with pytest.raises(ac.InvalidConnection, match="different types"):
        ac.connect(bodies.port, HeatPort())
    assert ac.connect(bodies.port, Other()) is not None


def test_an_absent_group_names_its_flag():
    with pytest.raises(ac.AbsentComponent, match="usePort"):
        Bodies(usePort=False).port


def test_the_energy_audit_reads_a_group_as_its_members():
    """The heat the capacities lose is what the environment takes in (a source of the
    model that absorbs it)."""
    model = Cooled()
    res = ac.simulate(model, t_end=5.0, rtol=1e-10, atol=1e-10)
    audit = ac.energy_balance(res, model)
    assert audit.ok, audit.summary()
    assert audit.roles["surroundings.ga"] == "lossless"
    stored = audit.stored["bodies.c1"] + audit.stored["bodies.c2"]
    assert stored[-1] < stored[0]
