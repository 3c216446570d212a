"""Electrical sensors (Modelica.Electrical.Analog.Sensors, MSL v4.0.0): ideal, they draw
no power; each output is a ``RealOutput`` named as the MSL names it."""
import acausal as ac
from acausal.ports import NegativePin, PositivePin, RealOutput

__all__ = ["PotentialSensor", "VoltageSensor", "CurrentSensor", "PowerSensor", "MultiSensor"]


class PotentialSensor(ac.Component):
    """Potential of a pin (MSL PotentialSensor):  phi = p.v,  p.i = 0."""

    p = PositivePin()
    phi = RealOutput()

    energy_role = "lossless"  # an ideal sensor takes no power

    def equations(self):
        return [ac.Eq(self.p.i, 0), ac.Eq(self.phi, self.p.v)]


class VoltageSensor(ac.Component):
    """Voltage between two pins (MSL VoltageSensor):  v = p.v - n.v,  p.i = n.i = 0."""

    p = PositivePin()
    n = NegativePin()
    v = RealOutput()

    energy_role = "lossless"  # an ideal sensor takes no power

    def equations(self):
        return [ac.Eq(self.p.i, 0), ac.Eq(self.n.i, 0),
                ac.Eq(self.v, self.p.v - self.n.v)]


class CurrentSensor(ac.Component):
    """Current in a branch (MSL CurrentSensor):  p.v = n.v,  p.i = i,  n.i = -i (i flows
    from p to n through the sensor)."""

    p = PositivePin()
    n = NegativePin()
    i = RealOutput()

    energy_role = "lossless"  # an ideal sensor takes no power

    def equations(self):
        return [ac.Eq(self.p.v, self.n.v), ac.Eq(self.p.i, self.i),
                ac.Eq(self.n.i, -self.i)]


class PowerSensor(ac.Component):
    """Power v i into a one-port (MSL PowerSensor): the current path pc -> nc is put in
    series with the one-port, the voltage pins pv, nv across it:

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


class MultiSensor(ac.Component):
    """Current, voltage and power (MSL MultiSensor), wired as the PowerSensor:

        pc.v = nc.v,  pc.i + nc.i = 0,  pv.i = nv.i = 0
        i = pc.i,  v = pv.v - nv.v,  power = v i
    """

    pc = PositivePin()
    nc = NegativePin()
    pv = PositivePin()
    nv = NegativePin()
    i = RealOutput()
    v = RealOutput()
    power = RealOutput()

    energy_role = "lossless"  # an ideal sensor takes no power

    def equations(self):
        return [ac.Eq(0, self.pc.i + self.nc.i), ac.Eq(self.pc.v - self.nc.v, 0),
                ac.Eq(self.pv.i, 0), ac.Eq(self.nv.i, 0),
                ac.Eq(self.i, self.pc.i), ac.Eq(self.v, self.pv.v - self.nv.v),
                ac.Eq(self.power, self.v * self.i)]
