"""Examples of Modelica.Mechanics.MultiBody.Examples.Elementary (MSL v4.0.0), each checked
against the MSL's reference result (``tests/msl``).

The MSL names a vector's elements from 1 and a frame's position ``frame_a.r_0``;
acausal names array elements from 0 and the frame's position ``frame_a.x``, ``.y``,
``.z``.  ``MSLNames`` is the map the examples give the harness (``msl_signals``).
"""
import re

from acausal.library.blocks.examples.msl import MSLNames as _IndexFromOne

__all__ = ["MSLNames"]

_FRAME = re.compile(r"^(.*frame_[ab])\.r_0\[([123])\]$")


class MSLNames(_IndexFromOne):
    """The acausal name of an MSL result name: ``a.frame_a.r_0[2]`` is ``a.frame_a.y``
    (a frame's origin), ``a.v_0[2]`` is ``a.v_0[1]`` (elements from 0); names given
    to the constructor map as given."""

    def get(self, name, default=None):
        m = _FRAME.match(name)
        if m and name not in self:
            return f"{m.group(1)}.{'xyz'[int(m.group(2)) - 1]}"
        return super().get(name, default)
