"""Modelica.Mechanics.MultiBody.Examples.Elementary.RollingWheel (MSL v4.0.0): a wheel
(radius 0.3 m, 2 kg, inertia 0.06 kg.m2 about its axis and 0.12 kg.m2 across) rolling on
the ground (gravity along -z) from (0.2, 0.2), upright, spinning at 5 rad/s and tipping
at 1 rad/s."""
import acausal as ac
from acausal.library.multibody3d import RollingWheel, World

from . import MSLNames

__all__ = ["RollingWheelExample"]


class RollingWheelExample(ac.Component):
    """Single wheel rolling on ground starting from an initial speed."""

    msl_name = "Modelica.Mechanics.MultiBody.Examples.Elementary.RollingWheel"
    stop_time = 4.0
    tolerance = 1e-6
    msl_signals = MSLNames()
    wheel1 = RollingWheel(radius=0.3, m=2.0, I_axis=0.06, I_long=0.12, x={"start": 0.2},
                          y={"start": 0.2}, der_angles={"start": [0.0, 5.0, 1.0]})
    world = World(n_1=0.0, n_2=0.0, n_3=-1.0)
