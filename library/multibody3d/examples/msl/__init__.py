"""Examples of Modelica.Mechanics.MultiBody.Examples.Elementary (MSL v4.0.0), each checked
against the MSL's reference result (``tests/msl``).

The MSL names a vector's elements from 1 and a frame's position ``frame_a.r_0``;
acausal names array elements from 0 and the frame's position ``frame_a.x``, ``.y``,
``.z``.  ``MSLNames`` is the map the examples give the harness (``msl_signals``).
"""
import re

__all__ = ["MSLNames"]

_FRAME = re.compile(r"^(.*frame_[ab])\.r_0\[([123])\]$")
_INDEX = re.compile(r"\[([0-9,]+)\]")


class MSLNames(dict):
    """The acausal name of an MSL result name: ``a.frame_a.r_0[2]`` is ``a.frame_a.y``
    (a frame's origin), ``a.v_0[2]`` is ``a.v_0[1]`` (elements from 0); names given
    to the constructor map as given."""

    def __bool__(self):
        return True          # a rule, even where it lists no name of its own

    def get(self, name, default=None):
        if name in self:
            return self[name]
        m = _FRAME.match(name)
        if m:
            return f"{m.group(1)}.{'xyz'[int(m.group(2)) - 1]}"
        return _INDEX.sub(lambda k: "[" + ",".join(str(int(i) - 1) for i in
                                                   k.group(1).split(",")) + "]", name)
