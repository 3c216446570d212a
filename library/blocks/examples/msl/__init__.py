"""Examples of Modelica.Blocks.Examples (MSL v4.0.0), each checked against the MSL's
reference result (``tests/msl``).

The MSL names a vector's elements from 1, acausal from 0 (as Python indexes):
``MSLNames`` is the map the examples give the harness (``msl_signals``).
"""
import re

__all__ = ["MSLNames"]

_INDEX = re.compile(r"\[([0-9,]+)\]")


class MSLNames(dict):
    """The acausal name of an MSL result name: ``a.x[2]`` is ``a.x[1]`` (elements from
    0); names given to the constructor map as given."""

    def __bool__(self):
        return True          # a rule, even where it lists no name of its own

    def get(self, name, default=None):
        if name in self:
            return self[name]
        return _INDEX.sub(lambda k: "[" + ",".join(str(int(i) - 1) for i in
                                                   k.group(1).split(",")) + "]", name)
