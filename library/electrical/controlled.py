"""Linear controlled sources (Modelica.Electrical.Analog.Basic VCV, VCC, CCV, CCC).

Each is a two-port: the controlling port (p1, n1) is an ideal voltmeter (i1 = 0) or an
ideal ammeter (v1 = 0) and takes no power; the controlled port (p2, n2) is an ideal
source whose power comes from outside the model.
"""
import acausal as ac

from .interfaces import TwoPort

__all__ = ["VCV", "VCC", "CCV", "CCC"]


class VCV(TwoPort):
    """Voltage-controlled voltage source:  v2 = gain v1,   i1 = 0."""

    gain = ac.Parameter(1.0, description="voltage gain v2 / v1")

    energy_role = "source"  # the controlled port is fed from outside the model

    def equations(self):
        return [ac.Eq(self.v2, self.gain * self.v1), ac.Eq(self.i1, 0)]


class VCC(TwoPort):
    """Voltage-controlled current source:  i2 = transConductance v1,   i1 = 0."""

    transConductance = ac.Parameter(1.0, unit="S", description="i2 / v1")

    energy_role = "source"  # the controlled port is fed from outside the model

    def equations(self):
        return [ac.Eq(self.i2, self.transConductance * self.v1),
                ac.Eq(self.i1, 0)]


class CCV(TwoPort):
    """Current-controlled voltage source:  v2 = transResistance i1,   v1 = 0."""

    transResistance = ac.Parameter(1.0, unit="Ohm", description="v2 / i1")

    energy_role = "source"  # the controlled port is fed from outside the model

    def equations(self):
        return [ac.Eq(self.v2, self.transResistance * self.i1),
                ac.Eq(self.v1, 0)]


class CCC(TwoPort):
    """Current-controlled current source:  i2 = gain i1,   v1 = 0."""

    gain = ac.Parameter(1.0, description="current gain i2 / i1")

    energy_role = "source"  # the controlled port is fed from outside the model

    def equations(self):
        return [ac.Eq(self.i2, self.gain * self.i1), ac.Eq(self.v1, 0)]
