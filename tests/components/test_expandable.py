"""Expandable connectors (Modelica 3.5, section 9.1.3): a bus carries the signals
connected to it, its declared members are potential, buses joined share their members.
Each signal read off a bus is checked against the source that drives it."""
import numpy as np
import pytest

import acausal as ac
from acausal.compiler.structure.matching import OverdeterminedModel
from acausal.library.blocks import (BooleanStep, Constant, Gain, IntegerStep, Sine,
                                    Step)
from acausal.library.electrical import Resistor


class SubBus(ac.ExpandableConnector):
    """A sub-bus with two potential signals."""

    x = ac.Variable(description="a Real signal")
    flag = ac.Variable(type=bool, description="a Boolean signal")


class Bus(ac.ExpandableConnector):
    """A bus with potential signals and a nested bus."""

    speed = ac.Variable(unit="rad/s", description="a Real signal")
    unused = ac.Variable(description="declared, never connected")
    count = ac.Variable(type=int, description="an Integer signal")
    sub = SubBus()


class Producer(ac.Component):
    """Puts a ramp and a flag on its own sub-bus."""

    bus = SubBus()
    ramp = Step(height=2.0, startTime=0.3)
    on = BooleanStep(startTime=0.5)

    def equations(self):
        return [ac.connect(self.ramp.y, self.bus.x), ac.connect(self.on.y, self.bus.flag)]


class Consumer(ac.Component):
    """Reads x from a bus of its own (an undeclared member: ``bus.extra`` too)."""

    bus = SubBus()
    gain = Gain(k=3.0)
    copy = Gain(k=1.0)

    def equations(self):
        return [ac.connect(self.bus.x, self.gain.u), ac.connect(self.bus.extra, self.copy.u)]


class Network(ac.Component):
    """sine -> bus.speed -> gain; producer.bus -> bus.sub -> consumer.bus."""

    sine = Sine(f=1.0)
    steps = IntegerStep(height=1, offset=2, startTime=0.5)
    gain = Gain(k=2.0)
    extra = Constant(k=7.0)
    producer = Producer()
    consumer = Consumer()
    bus = Bus()

    def equations(self):
        c = ac.connect
        return [c(self.sine.y, self.bus.speed), c(self.bus.speed, self.gain.u),
                c(self.steps.y, self.bus.count),
                c(self.producer.bus, self.bus.sub), c(self.bus.sub, self.consumer.bus),
                c(self.extra.y, self.bus.sub.extra)]


T = np.linspace(0.0, 1.0, 21)


def _run(model):
    return ac.simulate(model, t_end=1.0, t_eval=T, rtol=1e-9)


def test_signals_travel_on_buses_and_their_sub_buses():
    res = _run(Network())
    sine = np.sin(2 * np.pi * T)
    assert np.max(np.abs(res["bus.speed"] - sine)) < 1e-12
    assert np.max(np.abs(res["gain.y"] - 2 * sine)) < 1e-12
    assert list(res["bus.count"]) == [2 if t < 0.5 else 3 for t in T]
    ramp = np.where(T >= 0.3, 2.0, 0.0)
    assert np.array_equal(res["bus.sub.x"], ramp)
    assert np.array_equal(res["consumer.gain.y"], 3 * ramp)
    assert list(res["bus.sub.flag"]) == list(T >= 0.5)
    assert res["bus.sub.flag"].dtype == bool and res["bus.count"].dtype.kind == "i"
    # a member that only one bus of the joined ones names is on all of them
    assert np.all(res["consumer.copy.y"] == 7.0) and np.all(res["producer.bus.extra"] == 7.0)


def test_a_declared_member_nothing_uses_is_not_in_the_model():
    res = _run(Network())
    assert "bus.unused" not in res and "bus.speed" in res
    model = Network()
    ac.compile(model)
    assert set(model.bus.members()) == {"speed", "count", "sub"}
    assert set(model.bus.sub.members()) == {"x", "flag", "extra"}


def test_a_model_compiled_twice_makes_its_members_afresh():
    model = Network()
    first = _run(model)
    second = _run(model)
    for name in ("gain.y", "bus.sub.x", "consumer.copy.y"):
        assert np.array_equal(first[name], second[name])


def test_a_part_with_a_bus_compiles_alone():
    res = _run(Producer())
    assert list(res["bus.flag"]) == list(T >= 0.5)


def test_a_connection_must_agree_with_the_declared_type():
    class Wrong(ac.Component):
        sine = Sine()
        bus = Bus()

        def equations(self):
            return [ac.connect(self.sine.y, self.bus.count)]

    with pytest.raises(ac.InvalidConnection, match=r"'bus.count' is declared in Bus as an "
                                                   r"Integer signal, but is connected to a "
                                                   r"RealOutput"):
        ac.compile(Wrong())


def test_members_connected_only_to_each_other_have_no_type():
    class Floating(ac.Component):
        a = Bus()
        b = Bus()
        gain = Gain()

        def equations(self):
            return [ac.connect(self.a.free, self.b.free), ac.connect(self.a.speed, self.gain.u),
                    ac.connect(self.b.speed, self.gain.y)]

    with pytest.raises(ac.InvalidConnection, match=r"a\.free, b\.free are connected only to "
                                                   r"each other"):
        ac.compile(Floating())


def test_only_signals_and_buses_go_on_a_bus():
    bus, resistor = Bus(), Resistor()
    with pytest.raises(ac.InvalidConnection, match=r"only signals .* not the PositivePin"):
        ac.connect(bus.speed, resistor.p)

    class Mixed(ac.Component):
        bus = Bus()
        producer = Producer()

        def equations(self):
            return [ac.connect(self.producer.bus, self.bus.speed)]

    with pytest.raises(ac.InvalidConnection, match=r"'bus.speed' is declared in Bus as a "
                                                   r"Real signal, but is connected to a bus"):
        ac.compile(Mixed())


def test_a_bus_member_is_connected_not_read():
    class Reader(ac.Component):
        bus = Bus()
        sine = Sine()
        y = ac.Variable()

        def equations(self):
            return [ac.connect(self.sine.y, self.bus.speed), ac.Eq(self.y, self.bus.speed)]

    with pytest.raises(ac.ModelError, match=r"the bus member 'bus.speed' is read in an "
                                            r"equation"):
        ac.compile(Reader())
    with pytest.raises(AttributeError, match=r"'Bus.speed.x': 'Bus.speed' is not declared "
                                             r"a bus in Bus"):
        Reader().bus.speed.x


def test_two_outputs_on_one_bus_signal_are_too_many():
    class Twice(ac.Component):
        a = Sine()
        b = Sine(f=2.0)
        bus = Bus()

        def equations(self):
            return [ac.connect(self.a.y, self.bus.speed), ac.connect(self.b.y, self.bus.speed)]

    with pytest.raises(OverdeterminedModel, match=r"a\.y\.signal = bus\.speed\.signal"):
        ac.compile(Twice())


def test_bus_classes_declare_no_parameters_or_physical_ports():
    with pytest.raises(ac.InvalidValue, match="an expandable connector has no parameters"):
        class WithParameter(ac.ExpandableConnector):
            k = ac.Parameter(1.0)
    with pytest.raises(ac.InvalidValue, match="only signals .* not a Resistor"):
        class WithResistor(ac.ExpandableConnector):
            r = Resistor()
