"""Partial models of the electrical domain (Modelica.Electrical.Analog.Interfaces)."""
import acausal as ac
from acausal.ports import HeatPort, NegativePin, PositivePin

__all__ = ["OnePort", "TwoPin", "TwoPort", "FourPin", "ConditionalHeatPort"]


class TwoPin(ac.Component):
    """Two pins and the voltage between them:  v = p.v - n.v."""

    p = PositivePin()
    n = NegativePin()
    v = ac.Variable(unit="V", description="voltage drop p.v - n.v")

    def equations(self):
        return [ac.Eq(self.v, self.p.v - self.n.v)]


class OnePort(TwoPin):
    """A two-pin element through which one current flows:

        v = p.v - n.v,   0 = p.i + n.i,   i = p.i
    """

    i = ac.Variable(unit="A", description="current from p to n through the element")

    def equations(self):
        return [ac.Eq(0, self.p.i + self.n.i),
                ac.Eq(self.i, self.p.i)]


class TwoPort(ac.Component):
    """Two one-ports, primary (p1, n1) and secondary (p2, n2):

        v1 = p1.v - n1.v,  0 = p1.i + n1.i,  i1 = p1.i   (and the same for 2)

    Both currents are positive into the positive pins, so v1 i1 + v2 i2 is the power
    into the two-port.
    """

    p1 = PositivePin()
    n1 = NegativePin()
    p2 = PositivePin()
    n2 = NegativePin()
    v1 = ac.Variable(unit="V", description="primary voltage p1.v - n1.v")
    v2 = ac.Variable(unit="V", description="secondary voltage p2.v - n2.v")
    i1 = ac.Variable(unit="A", description="current into p1")
    i2 = ac.Variable(unit="A", description="current into p2")

    def equations(self):
        return [ac.Eq(self.v1, self.p1.v - self.n1.v), ac.Eq(0, self.p1.i + self.n1.i),
                ac.Eq(self.i1, self.p1.i),
                ac.Eq(self.v2, self.p2.v - self.n2.v), ac.Eq(0, self.p2.i + self.n2.i),
                ac.Eq(self.i2, self.p2.i)]


class FourPin(ac.Component):
    """Two pairs of pins (MSL Analog.Interfaces.FourPin), without a current balance of
    its own (the component says how the currents of a pair are related):

        v1 = p1.v - n1.v,  v2 = p2.v - n2.v,  i1 = p1.i,  i2 = p2.i
    """

    p1 = PositivePin()
    n1 = NegativePin()
    p2 = PositivePin()
    n2 = NegativePin()
    v1 = ac.Variable(unit="V", description="voltage drop of port 1 (p1.v - n1.v)")
    v2 = ac.Variable(unit="V", description="voltage drop of port 2 (p2.v - n2.v)")
    i1 = ac.Variable(unit="A", description="current into p1")
    i2 = ac.Variable(unit="A", description="current into p2")

    def equations(self):
        return [ac.Eq(self.v1, self.p1.v - self.n1.v), ac.Eq(self.v2, self.p2.v - self.n2.v),
                ac.Eq(self.i1, self.p1.i), ac.Eq(self.i2, self.p2.i)]


class ConditionalHeatPort(ac.Component):
    """A conditional heat port through which an electrical component's losses leave
    (Modelica.Electrical.Analog.Interfaces.ConditionalHeatPort):

        useHeatPort:      heatPort.T = T_heatPort,   heatPort.Q_flow = -LossPower
        not useHeatPort:  T_heatPort = T   (the device at the fixed temperature T)

    The component gives ``LossPower`` by an equation (``LossPower = v i``) and may read
    ``T_heatPort`` (a temperature-dependent resistance).  ``useHeatPort`` is fixed where
    the component is made (``ac.Conditional``).
    """

    useHeatPort = ac.Parameter(False, structural=True, description="enable the heat port")
    T = ac.Parameter(293.15, unit="K", min=0, description="fixed device temperature if "
                                                          "useHeatPort = false")
    heatPort = ac.Conditional(HeatPort(), "useHeatPort")
    LossPower = ac.Variable(unit="W", description="loss power leaving the component via "
                                                  "heatPort")
    T_heatPort = ac.Variable(unit="K", description="temperature of heatPort")

    def loss_power(self):
        """P_loss = LossPower (the MSL's lossPower)."""
        return self.LossPower

    def equations(self):
        if self.useHeatPort:
            return [ac.Eq(self.heatPort.T, self.T_heatPort),
                    ac.Eq(self.heatPort.Q_flow, -self.LossPower)]
        return [ac.Eq(self.T_heatPort, self.T)]
