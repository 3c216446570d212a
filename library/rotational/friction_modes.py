"""The rotational base of the friction elements that stick
(Modelica.Mechanics.Rotational.Interfaces.PartialFriction): the relative speed
``w_relfric``, its derivative ``a_relfric`` and the friction torque ``tau``, with the
path parameter ``sa`` a torque.  The modes, their events and the way the stuck torque is
found are those of :class:`acausal.library.friction.modes.FrictionModes` (its module
docstring tells the whole story).
"""
from __future__ import annotations

import acausal as ac

from ..friction.modes import (MODES, FrictionModes, friction_table, table_at_zero,
                              table_value)

__all__ = ["PartialFriction", "friction_table", "table_value", "table_at_zero", "MODES"]


class PartialFriction(FrictionModes):
    """Modes of a rotational element with Coulomb friction that sticks
    (Modelica.Mechanics.Rotational.Interfaces.PartialFriction).

    A subclass declares the variables ``w_relfric`` (relative speed of the rubbing
    surfaces), ``a_relfric`` = der(w_relfric) and ``tau`` (friction torque, positive
    against w_relfric > 0), and the methods

    * ``free()``: the relation under which the surfaces do not touch (fn <= 0), or
      None where there is no free mode;
    * ``tau0()``, ``tau0_max()``: friction torque at w = 0 sliding, and the most the
      element holds at w = 0 (``peak`` tau0), the same both ways;
    * ``sliding_torque(w)``: the friction torque while sliding forwards at w >= 0
      (backwards it is -sliding_torque(-w)).

    An element whose limits or laws are not symmetric (``LossyGear``) overrides
    ``break_away()`` and ``sliding_laws()`` instead.
    """

    sa = ac.Variable(start=0.0, unit="N.m",
                     description="path parameter: torque held while locked, else 0 "
                                 "or the acceleration past break-away")
    # sa is a torque; past break-away it also measures an acceleration, 1 N.m for
    # 1 rad/s2 (the MSL's unitTorque and unitAngularAcceleration)
    unit_a = ac.Parameter(1.0, unit="rad/s2", min=0,
                          description="1 rad/s2: the unit of sa as an acceleration")
    unit_tau = ac.Parameter(1.0, unit="N.m", min=0, description="1 N.m: the unit of sa")
    # the friction tables are numbers of a speed in rad/s
    unit_w = ac.Parameter(1.0, unit="rad/s", min=0,
                          description="1 rad/s: the unit of the speed in the tables")

    def relfric(self) -> tuple:
        return self.w_relfric, self.a_relfric, self.tau

    def per(self):
        return self.unit_a / self.unit_tau

    def break_away(self) -> tuple:
        return self.tau0_max(), -self.tau0_max()

    def sliding_laws(self) -> tuple:
        return self.sliding_torque(self.w_relfric), -self.sliding_torque(-self.w_relfric)
