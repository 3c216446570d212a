"""Semiconductor devices (Modelica.Electrical.Analog.Semiconductors)."""
import sympy as sp

import acausal as ac

from .interfaces import OnePort

__all__ = ["Diode"]


class Diode(OnePort):
    """Exponential (Shockley) diode with a parallel leakage resistance:

        i = Ids (exp(v/Vt) - 1) + v/R                          for v/Vt <= Maxexp
        i = Ids (exp(Maxexp) (1 + v/Vt - Maxexp) - 1) + v/R    for v/Vt >  Maxexp

    Above Maxexp the exponential is continued by its tangent (as in the MSL), so that a
    Newton iterate far in the forward direction cannot overflow.
    """

    Ids = ac.Parameter(1e-6, unit="A", min=0, description="saturation current")
    Vt = ac.Parameter(0.04, unit="V", min=0, description="thermal voltage (times ideality)")
    Maxexp = ac.Parameter(15.0, min=1, description="above v/Vt = Maxexp: linear continuation")
    R = ac.Parameter(1e8, unit="Ohm", min=0, description="parallel leakage resistance")

    def equations(self):
        x = self.v / self.Vt
        tangent = sp.exp(self.Maxexp) * (1 + x - self.Maxexp)
        law = ac.if_else(x > self.Maxexp, tangent, sp.exp(x))
        return [*super().equations(), ac.Eq(self.i, self.Ids * (law - 1) + self.v / self.R)]
