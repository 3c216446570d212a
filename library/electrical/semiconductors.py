"""Semiconductor devices (Modelica.Electrical.Analog.Semiconductors)."""
from acausal._sympy import sympy as sp

import acausal as ac

from .interfaces import OnePort

__all__ = ["Diode", "IdealDiode"]


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

    def loss_power(self):
        """P_loss = v i >= 0 (the characteristic lies in the first and third quadrants)."""
        return self.v * self.i

    def equations(self):
        x = self.v / self.Vt
        tangent = sp.exp(self.Maxexp) * (1 + x - self.Maxexp)
        law = ac.if_else(x > self.Maxexp, tangent, sp.exp(x))
        return [ac.Eq(self.i, self.Ids * (law - 1) + self.v / self.R)]


class IdealDiode(OnePort):
    """Ideal diode as a piecewise-linear characteristic in the curve parameter s
    (Modelica.Electrical.Analog.Ideal.IdealDiode):

        off = s < 0
        v = s (1 if off else Ron) + Vknee,   i = s (Goff if off else 1) + Goff Vknee

    Conducting (s >= 0) it is a resistance Ron, blocking a conductance Goff; the switch
    is an event on s, so the number of states does not change.  Note: a circuit where s
    is exactly 0 at the start time and rising (a sine source with zero phase) does not
    start; give the source a phase or a start time.
    """

    Ron = ac.Parameter(1e-5, unit="Ohm", min=0, description="resistance when conducting")
    Goff = ac.Parameter(1e-5, unit="S", min=0, description="conductance when blocking")
    Vknee = ac.Parameter(0.0, unit="V", min=0, description="forward threshold voltage")
    s = ac.Variable(start=0.0, description="curve parameter (i when on, v when off)")

    def loss_power(self):
        """P_loss = v i >= 0 (the characteristic lies in the first and third quadrants)."""
        return self.v * self.i

    def equations(self):
        off = self.s < 0
        return [ac.Eq(self.v, self.s * ac.if_else(off, 1, self.Ron) + self.Vknee),
                ac.Eq(self.i, self.s * ac.if_else(off, self.Goff, 1) + self.Goff * self.Vknee)]
