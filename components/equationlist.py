"""What a component's ``equations()`` returns: equations (``ac.Eq``), when-clauses
(``ac.when``) and connections (``ac.connect``), in a list that may nest lists and
generators; :func:`flatten_equation_list` makes it one flat list.
"""
from __future__ import annotations

from ..errors import InvalidEquation
from ..words import shortened

__all__ = ["Connection", "flatten_equation_list"]


class Connection:
    """connect(a, b, ...): the ports form one node (across equal, through sum to zero)."""

    __slots__ = ("ports", "owner")

    def __init__(self, ports):
        self.ports = tuple(ports)
        self.owner = None

    def __repr__(self):
        return "connect(" + ", ".join(p.path or repr(p) for p in self.ports) + ")"


_PLAIN_ITEMS = set()     # Equation, Connection and When (filled on first use)


def flatten_equation_list(items) -> list:
    """Equations may be returned as nested lists or generators; make one flat list."""
    if not _PLAIN_ITEMS:
        # sympy (some 0.3 s): only a model with equations needs it, not a class definition
        from .symbols import Equation, When
        _PLAIN_ITEMS.update((Equation, Connection, When))
    if type(items) is list and all(type(i) in _PLAIN_ITEMS for i in items):
        return list(items)       # the common case: a list of equations, already flat
    kinds = tuple(_PLAIN_ITEMS)
    if isinstance(items, kinds) or not (items is None or isinstance(items, (list, tuple))
                                        or hasattr(items, "__iter__")):
        raise InvalidEquation(f"returned {shortened(repr(items), 100)} "
                              f"({type(items).__name__}), not a list of equations: return "
                              "a list, e.g. [ac.Eq(lhs, rhs)]")
    out = []
    stack = [iter(items if items is not None else [])]
    while stack:
        try:
            item = next(stack[-1])
        except StopIteration:
            stack.pop()
            continue
        if isinstance(item, kinds):
            out.append(item)
        elif isinstance(item, (list, tuple)) or hasattr(item, "__next__"):
            stack.append(iter(item))
        else:
            out.append(item)
    return out
