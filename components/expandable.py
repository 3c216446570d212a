"""Expandable connectors: a signal bus whose signals are those connected to it
(Modelica Language Specification 3.5, section 9.1.3).

    class SubControlBus(ac.ExpandableConnector):
        '''Sub-control bus that is adapted to the signals connected to it.'''
        myRealSignal = ac.Variable()
        myBooleanSignal = ac.Variable(type=bool)

    class ControlBus(ac.ExpandableConnector):
        realSignal1 = ac.Variable(unit="rad/s", description="first Real signal")
        integerSignal = ac.Variable(type=int)
        subControlBus = SubControlBus()

    ...
    ac.connect(self.sine.y, self.controlBus.realSignal1)          # adds realSignal1
    ac.connect(self.controlBus.realSignal1, self.gain.u)           # reads it
    ac.connect(self.part.subControlBus, self.controlBus.subControlBus)

The rules, as the specification's:

1. A bus declares no variables of its own.  What its class declares (``ac.Variable``,
   with ``type=bool`` or ``int``, and nested buses) are *potential* members: a member
   exists in the model only where something is connected to it (a declared member that
   nothing uses is not there), and a connection must agree with its declared type.
2. ``bus.name`` names a member, declared or not, and may only be connected:
   ``ac.connect(bus.name, port)`` makes the member a signal of the port's type (Real,
   Boolean or Integer); ``ac.connect(bus.name, other_bus)`` makes it a bus of
   ``other_bus``'s class.  A member of an undeclared member (``bus.new.x``) is an error,
   as in Modelica.
3. ``ac.connect(bus_a, bus_b)`` joins two buses: each then has the members of both,
   and members of the same name are connected (recursively, for nested buses).
4. Every member is a signal port of the bus, named by its path (``controlBus.realSignal1``
   in results) and set by what is connected to it, like any signal: exactly one output
   among the ports joined through the buses.  Only signals and buses travel on a bus
   (a physical connector is refused).

Members are made when the model is flattened (:func:`resolve_buses`): flattening reads
the connections, works out every member's type through the connected buses, makes the
member ports, and replaces the connections through buses by one connection per signal.
"""
from __future__ import annotations

from .component import Component, Port
from .declarations import Parameter, Signal, Variable
from .equationlist import Connection
from ..errors import InvalidConnection, InvalidEquation, InvalidValue
from ..ports.base import SignalPort

__all__ = ["ExpandableConnector", "BusMember", "is_bus_end", "drop_bus_members",
           "resolve_buses"]


class ExpandableConnector(Port):
    """A bus: a connector whose signals are declared by what is connected to it (module
    docstring).  Subclass it to declare the potential members."""

    hint = "a signal on a bus is read but never set"
    _bus_end = True

    @staticmethod
    def check_bus_connection(ports) -> None:
        """What ``ac.connect`` checks of a connection through a bus: :func:`check_connection`."""
        check_connection(ports)

    def __init_subclass__(cls, **kwargs):
        potential = dict(getattr(cls, "_potential", {}))
        for name, decl in list(vars(cls).items()):
            if isinstance(decl, Parameter):
                raise InvalidValue(f"{cls.__name__}.{name}: an expandable connector has "
                                   "no parameters, only its potential signals and buses")
            if isinstance(decl, Variable):
                if decl.shape is not None:
                    raise InvalidValue(f"{cls.__name__}.{name}: an array on a bus is not "
                                       "supported")
                potential[name] = decl
                delattr(cls, name)
            elif isinstance(decl, Component):
                if not isinstance(decl, ExpandableConnector):
                    raise InvalidValue(f"{cls.__name__}.{name}: only signals (ac.Variable) "
                                       "and other expandable connectors travel on a bus, "
                                       f"not a {type(decl).__name__}")
                potential[name] = decl
                delattr(cls, name)
        cls._potential = potential
        super().__init_subclass__(**kwargs)

    def __getattr__(self, name):
        # only reached for a name that is not an attribute: a member not made yet
        if name.startswith("_"):
            raise AttributeError(name)
        slots = self.__dict__.setdefault("_slots", {})
        if name not in slots:
            slots[name] = BusMember(self, name, type(self)._potential.get(name))
        return slots[name]

    def members(self) -> dict:
        """The members made so far (after flattening: every member of the model), by
        name."""
        return {n: c for n, c in self._children.items() if getattr(c, "bus_member", False)}


ExpandableConnector._potential = {}


class BusMember:
    """``bus.name`` before the model is flattened: a member of a bus that may only be
    connected (module docstring, rule 2).  Flattening makes it a port (``port``)."""

    _bus_end = True
    check_bus_connection = staticmethod(ExpandableConnector.check_bus_connection)

    def __init__(self, owner, name: str, declared=None):
        self.owner = owner          # the bus, or the BusMember of a declared nested bus
        self.name = name
        self.declared = declared    # the class's potential declaration, or None
        self.port = None            # the member once made (a signal port or a bus)
        self._slots = {}

    # what connect() and its checks read of a port
    @property
    def path(self) -> str:
        owner = self.owner
        where = owner.path if isinstance(owner, BusMember) or owner._path else \
            type(owner).__name__
        return f"{where}.{self.name}"

    @property
    def _parent(self):
        return self.owner if isinstance(self.owner, ExpandableConnector) else self.owner._parent

    @property
    def _root(self):
        return self.owner._root

    @property
    def _path(self):
        return self.path if self.owner._path is not None else None

    def __getattr__(self, name):
        if name.startswith("_"):
            raise AttributeError(name)
        if not isinstance(self.declared, ExpandableConnector):
            raise AttributeError(
                f"'{self.path}.{name}': '{self.path}' is not declared a bus in "
                f"{_bus_class(self.owner).__name__}, so it has no members to name (declare "
                f"it there as a nested expandable connector, or connect '{self.path}' to a "
                "bus and name the member on that bus)")
        if name not in self._slots:
            self._slots[name] = BusMember(self, name, type(self.declared)._potential.get(name))
        return self._slots[name]

    def _sympy_(self):
        raise InvalidEquation(f"the bus member '{self.path}' is read in an equation; a bus "
                              "member may only be connected: connect it to an input of a "
                              "block and read that")

    def __repr__(self):
        return f"<bus member {self.path}>"


def _bus_class(owner):
    if isinstance(owner, ExpandableConnector):
        return type(owner)
    return type(owner.declared)


def is_bus_end(p) -> bool:
    """Whether ``p`` is a bus or a member of one (a connection through a bus)."""
    return isinstance(p, (ExpandableConnector, BusMember))


def check_connection(ports) -> None:
    """What connect() can check of a connection through a bus before the model is
    flattened: its ends are ports, buses or bus members, each once."""
    for p in ports:
        if not isinstance(p, (Port, BusMember)):
            raise InvalidConnection(f"connect() takes ports, got {p!r} ({type(p).__name__})")
        if isinstance(p, Port) and not is_bus_end(p) and not _is_signal(p):
            names = ", ".join(_shown(q) for q in ports)
            raise InvalidConnection(f"connect({names}): only signals (Real, Boolean, Integer "
                                    f"ports) and buses connect to a bus, not the "
                                    f"{type(p).__name__} '{p.path or p!r}'")
    seen = set()
    for p in ports:
        if id(p) in seen:
            raise InvalidConnection(f"{Connection(ports)!r}: '{p.path}' appears more than "
                                    "once")
        seen.add(id(p))


def _shown(p) -> str:
    return p.path if isinstance(p, BusMember) or p._path else f"<{type(p).__name__}>"


def _is_signal(p) -> bool:
    return isinstance(p, Port) and list(p.declarations()) == ["signal"] \
        and p.declarations()["signal"].kind == "signal"


# -- flattening --------------------------------------------------------------------------
def drop_bus_members(nodes: list) -> list:
    """``nodes`` (the instance tree in order) without the members an earlier flattening
    made on its buses, which are removed from the buses: the members are made afresh
    from this flattening's connections."""
    if not any(isinstance(c, ExpandableConnector) for c in nodes):
        return nodes
    made = set()
    for comp in nodes:
        if isinstance(comp, ExpandableConnector):
            for name, member in list(comp.members().items()):
                _forget(comp, name, member, made)
            comp.__dict__.pop("_slots", None)
    return [c for c in nodes if id(c) not in made]


def _forget(bus, name, member, made) -> None:
    made.add(id(member))
    if isinstance(member, ExpandableConnector):
        for inner, sub in list(member.members().items()):
            _forget(member, inner, sub, made)
    del bus._children[name]
    del bus.__dict__[name]


class _Sets:
    """Union-find over the ends of connections through buses (by identity)."""

    def __init__(self):
        self.parent = {}
        self.items = {}

    def add(self, x):
        self.parent.setdefault(id(x), id(x))
        self.items.setdefault(id(x), x)

    def find(self, x):
        i = id(x) if not isinstance(x, int) else x
        root = self.parent.setdefault(i, i)
        while self.parent[root] != root:
            root = self.parent[root]
        while self.parent[i] != root:
            self.parent[i], i = root, self.parent[i]
        return root

    def union(self, a, b) -> bool:
        self.add(a), self.add(b)
        ra, rb = self.find(a), self.find(b)
        if ra == rb:
            return False
        self.parent[max(ra, rb, key=self._order)] = min(ra, rb, key=self._order)
        return True

    def _order(self, i):
        return list(self.items).index(i)

    def groups(self) -> list:
        out = {}
        for i, x in self.items.items():
            out.setdefault(self.find(i), []).append(x)
        return list(out.values())


def resolve_buses(connections: list, root) -> tuple:
    """The connections with those through buses replaced by one connection per signal
    carried (owned by ``root``), and the members made (to be flattened as ports), in the
    order they were made.  Raises InvalidConnection for a member whose connections
    disagree about its type or that no signal gives a type."""
    through = [c for c in connections if any(is_bus_end(p) for p in c.ports)]
    if not through:
        return connections, []
    sets = _Sets()
    for conn in through:
        for p in conn.ports:
            sets.add(p)
        for p in conn.ports[1:]:
            sets.union(conn.ports[0], p)
    made = []
    changed = True
    while changed:
        changed = False
        for group in sets.groups():
            kind = _kind(group)
            if kind[0] == "bus":
                changed |= _join_buses(group, kind[1], sets, made, root)
    out = [c for c in connections if not any(is_bus_end(p) for p in c.ports)]
    for group in sets.groups():
        kind = _kind(group)
        if kind[0] != "signal":
            continue
        ports = []
        for end in group:
            if isinstance(end, BusMember):
                ports.append(_make_signal(end, kind[1], made, root))
            elif not isinstance(end, ExpandableConnector):
                ports.append(end)
        if len(ports) > 1:
            conn = Connection(ports)
            conn.owner = root
            out.append(conn)
    return out, made


def _kind(group: list) -> tuple:
    """("bus", class) for a group of buses, ("signal", port) for a group of signals (a
    port of the group, whose type the members take), or an InvalidConnection."""
    buses = [e for e in group if isinstance(e, ExpandableConnector)
             or (isinstance(e, BusMember) and (isinstance(e.declared, ExpandableConnector)
                                               or isinstance(e.port, ExpandableConnector)))]
    signals = [e for e in group if isinstance(e, Port) and not isinstance(e, ExpandableConnector)]
    names = ", ".join(e.path for e in group)
    if buses and signals:
        raise InvalidConnection(f"connect({names}) joins a bus and a signal: a bus "
                                "connects to buses, a signal to a bus's member")
    if buses:
        for e in buses:
            if isinstance(e, ExpandableConnector):
                return ("bus", type(e))
            if isinstance(e.port, ExpandableConnector):
                return ("bus", type(e.port))
        return ("bus", type(buses[0].declared))
    if signals:
        types = {s.connection_type() for s in signals}
        if len(types) > 1:
            kinds = ", ".join(f"{s.path} ({type(s).__name__})" for s in signals)
            raise InvalidConnection(f"a bus member connects signals of different types: "
                                    f"{kinds}")
        return ("signal", signals[0])
    members = [e for e in group if isinstance(e, BusMember)]
    declared = [e for e in members if e.declared is not None]
    if declared:
        return ("declared", declared[0])
    raise InvalidConnection(f"the bus members {names} are connected only to each other: "
                            "no signal gives them a type (connect one of them to a block's "
                            "port, or declare it in its bus class)")


def _join_buses(group, cls, sets, made, root) -> bool:
    """Make the bus members of ``group`` buses of class ``cls``, and give every bus of
    the group the members of all of them, same names joined; True if anything changed."""
    changed = False
    buses = []
    for end in group:
        if isinstance(end, BusMember):
            if end.port is None:
                _make_bus(end, cls, made, root)
                changed = True
            buses.append(end.port)
        elif isinstance(end, ExpandableConnector):
            buses.append(end)
    names = []
    for bus in buses:
        for name in list(bus.__dict__.get("_slots", {})):
            if name not in names:
                names.append(name)
    for name in names:
        first = getattr(buses[0], name)
        for bus in buses[1:]:
            changed |= sets.union(first, getattr(bus, name))
    return changed


def _owner_bus(member: BusMember, made, root):
    """The bus that holds ``member`` (made first, for a member of a declared nested
    bus)."""
    owner = member.owner
    if isinstance(owner, BusMember):
        if owner.port is None:
            _make_bus(owner, type(owner.declared), made, root)
        return owner.port
    return owner


def _check_declared(member: BusMember, what: str, ok: bool) -> None:
    if member.declared is not None and not ok:
        bus = _bus_class(member.owner).__name__
        raise InvalidConnection(f"'{member.path}' is declared in {bus} as "
                                f"{_declared_text(member.declared)}, but is connected to "
                                f"{what}")


def _declared_text(decl) -> str:
    if isinstance(decl, Variable):
        return {float: "a Real signal", bool: "a Boolean signal",
                int: "an Integer signal"}[decl.type]
    return f"a bus ({type(decl).__name__})"


def _make_bus(member: BusMember, cls, made, root) -> None:
    _check_declared(member, f"a bus ({cls.__name__})",
                    isinstance(member.declared, ExpandableConnector)
                    and isinstance(member.declared, cls))
    bus = _owner_bus(member, made, root)
    port = member.declared._clone() if member.declared is not None else cls()
    _attach(bus, member.name, port, root)
    # the members already named on the declared nested bus are its members now
    port.__dict__.setdefault("_slots", {}).update(member._slots)
    for slot in member._slots.values():
        slot.owner = port
    member.port = port
    made.append(port)


def _make_signal(member: BusMember, example, made, root):
    if member.port is not None:
        return member.port
    typ = example.declarations()["signal"].type
    _check_declared(member, f"a {type(example).__name__}",
                    isinstance(member.declared, Variable) and member.declared.type is typ)
    bus = _owner_bus(member, made, root)
    port = bus_signal_class(typ)()
    _attach(bus, member.name, port, root)
    member.port = port
    made.append(port)
    return port


def _attach(bus, name: str, port, root) -> None:
    """``port`` becomes the member ``name`` of ``bus`` (a child, named and bound)."""
    bus._children[name] = port
    bus.__dict__[name] = port
    object.__setattr__(port, "bus_member", True)
    port._bind_one(f"{bus.path}.{name}", bus, root)


_SIGNAL_CLASSES: dict = {}


def bus_signal_class(typ):
    """The port class of a member of a bus carrying a signal of value type ``typ``."""
    if typ not in _SIGNAL_CLASSES:
        label = {float: "Real", bool: "Boolean", int: "Integer"}[typ]
        cls = type(f"{label}BusSignal", (SignalPort,), {
            "__doc__": f"A {label} signal on a bus (a member of an expandable connector).",
            "__module__": __name__,
            "signal": Signal(description=f"{label} signal on a bus",
                             **({} if typ is float else {"type": typ})),
            "hint": "a signal on a bus is read but never set",
            "bus_member": True})
        _SIGNAL_CLASSES[typ] = cls
    return _SIGNAL_CLASSES[typ]
