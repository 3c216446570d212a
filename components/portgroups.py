"""Connectors made of connectors (Modelica's hierarchical connectors, Language
Specification 3.5, sec. 9.1: a connector whose elements are connectors, and whose
connection connects its elements pairwise).

    class ThermalPortDCPM(ac.PortGroup):
        heatPortArmature = HeatPort()
        heatPortCore = HeatPort()
        ...

    class Machine(ac.Component):
        thermalPort = ThermalPortDCPM()
        ...
        def equations(self):
            return [ac.connect(self.ra.heatPort, self.thermalPort.heatPortArmature), ...]

A group's members are ports of the component that holds the group: inside that
component they are connected from outside (as the component's own ports are), and a
member that nothing outside connects has its through variables zero.
``ac.connect(group_a, group_b)`` connects the members of the same name; two groups
connect when their members have the same names and types (as Modelica's connectors,
whatever their class names).  A member is reached and connected as any port,
``ac.connect(capacitor.port, machine.thermalPort.heatPortCore)``; results name it
``machine.thermalPort.heatPortCore.T``.  A group declares no variables of its own.
"""
from __future__ import annotations

from .component import Connection, Port

__all__ = ["PortGroup", "expand_connection", "port_owner", "leaf_ports"]


class PortGroup(Port):
    """A connector whose elements are ports (see the module docstring)."""

    def members(self) -> dict:
        """The group's ports by name, in declaration order."""
        return {n: c for n, c in self.children().items() if isinstance(c, Port)}

    def connection_type(self):
        return ("group",) + tuple((n, m.connection_type()) for n, m in self.members().items())


def expand_connection(conn: Connection) -> list:
    """The connections of primitive ports that ``conn`` stands for: itself, or, for a
    connection of groups, one connection per member (recursively), with its owner."""
    if not isinstance(conn.ports[0], PortGroup):
        return [conn]
    out = []
    for name in conn.ports[0].members():
        member = Connection([p.members()[name] for p in conn.ports])
        member.owner = conn.owner
        out.extend(expand_connection(member))
    return out


def port_owner(port: Port):
    """The component a port belongs to: its parent, above the groups (or the ports made
    of ports, such as a polyphase plug of pins) it is in."""
    node = getattr(port, "_parent", None)
    while isinstance(node, Port):
        node = node._parent
    return node


def leaf_ports(port: Port) -> list:
    """A port itself, or a group's primitive ports (recursively)."""
    if isinstance(port, PortGroup):
        return [q for m in port.members().values() for q in leaf_ports(m)]
    return [port]
