"""Electrical sensors (Modelica.Electrical.Analog.Sensors): ideal, they draw no power."""
import acausal as ac
from acausal.ports import NegativePin, PositivePin, RealOutput

from .interfaces import TwoPin

__all__ = ["PotentialSensor", "VoltageSensor", "CurrentSensor", "PowerSensor"]


class PotentialSensor(ac.Component):
    """phi = p.v,  p.i = 0."""

    p = PositivePin()
    phi = RealOutput()

    energy_role = "lossless"  # an ideal sensor takes no power

    def equations(self):
        return [ac.Eq(self.p.i, 0), ac.Eq(self.phi, self.p.v)]


class VoltageSensor(TwoPin):
    """v_out = p.v - n.v, with no current through the sensor."""

    v_out = RealOutput()

    energy_role = "lossless"  # an ideal sensor takes no power

    def equations(self):
        return [ac.Eq(self.p.i, 0), ac.Eq(self.n.i, 0),
                ac.Eq(self.v_out, self.v)]


class CurrentSensor(ac.Component):
    """i_out = p.i, the current from p to n; no voltage across the sensor."""

    p = PositivePin()
    n = NegativePin()
    i_out = RealOutput()

    energy_role = "lossless"  # an ideal sensor takes no power

    def equations(self):
        return [ac.Eq(self.p.v, self.n.v), ac.Eq(0, self.p.i + self.n.i),
                ac.Eq(self.i_out, self.p.i)]


class PowerSensor(ac.Component):
    """Power v i into a one-port: the current path pc -> nc is put in series with the
    one-port, the voltage pins pv, nv across it (Modelica PowerSensor):

        pc.v = nc.v,  pc.i + nc.i = 0,  pv.i = nv.i = 0,  power = (pv.v - nv.v) pc.i
    """

    pc = PositivePin()
    nc = NegativePin()
    pv = PositivePin()
    nv = NegativePin()
    power = RealOutput()

    energy_role = "lossless"  # an ideal sensor takes no power

    def equations(self):
        return [ac.Eq(self.pc.v, self.nc.v), ac.Eq(0, self.pc.i + self.nc.i),
                ac.Eq(self.pv.i, 0), ac.Eq(self.nv.i, 0),
                ac.Eq(self.power, (self.pv.v - self.nv.v) * self.pc.i)]
