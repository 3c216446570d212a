"""Modelica.Blocks.Examples.CompareSincExpSine (MSL v4.0.0): a sinc signal of 5 Hz next
to two exponentially damped sines of 5 Hz (damping 5 1/s), one with phase pi/2."""
import math

import acausal as ac
from acausal.library.blocks import ExpSine, Sinc

from . import MSLNames

__all__ = ["CompareSincExpSine"]


class CompareSincExpSine(ac.Component):
    """Compare sinc and exponential sine signal."""

    msl_name = "Modelica.Blocks.Examples.CompareSincExpSine"
    stop_time = 1.0
    tolerance = 1e-6
    msl_signals = MSLNames()

    sinc = Sinc(f=5.0)
    expSine1 = ExpSine(f=5.0, damping=5.0)
    expSine2 = ExpSine(f=5.0, phase=math.pi / 2, damping=5.0)
