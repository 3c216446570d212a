"""Partial models of the electrical domain (Modelica.Electrical.Analog.Interfaces)."""
import acausal as ac
from acausal.ports import HeatPort, NegativePin, PositivePin

__all__ = ["OnePort", "TwoPin", "TwoPort", "FourPin", "ConditionalHeatPort",
           "LeanConditionalHeatPort", "IdealSemiconductor", "IdealSwitch",
           "IdealSwitchWithArc"]


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
    # SI.Temperature's start and nominal, as the MSL declares it
    T_heatPort = ac.Variable(start=288.15, nominal=300.0, unit="K",
                             description="temperature of heatPort")

    def loss_power(self):
        """P_loss = LossPower (the MSL's lossPower) without the heat port; with it the
        loss leaves through heatPort (heatPort.Q_flow = -LossPower), a flow of energy to
        the thermal network, so the component itself keeps none."""
        return 0 if self.useHeatPort else self.LossPower

    def equations(self):
        if self.useHeatPort:
            return [ac.Eq(self.heatPort.T, self.T_heatPort),
                    ac.Eq(self.heatPort.Q_flow, -self.LossPower)]
        return [ac.Eq(self.T_heatPort, self.T)]


class LeanConditionalHeatPort(ConditionalHeatPort):
    """The :class:`ConditionalHeatPort` of an element that is one equation without its
    heat port (the linear resistor and conductor): at the fixed device temperature T its
    law reads T itself, and LossPower, T_heatPort (and the names in ``heat_variables``)
    are variables only with ``useHeatPort=True``, so a ladder of a thousand resistors
    keeps its size.  Without the port the loss is ``loss_power()`` (v i).
    """

    heat_variables = ("LossPower", "T_heatPort")

    def declarations(self) -> dict:
        decls = super().declarations()
        if self.useHeatPort:
            return decls
        return {n: d for n, d in decls.items() if n not in self.heat_variables}

    def device_temperature(self):
        """T_heatPort with the heat port, else the parameter T."""
        return self.T_heatPort if self.useHeatPort else self.T

    def loss_power(self):
        """The loss v i without the heat port; with it the loss leaves through heatPort."""
        return 0 if self.useHeatPort else self.v * self.i

    @ac.replaces(ConditionalHeatPort)
    def equations(self):
        if self.useHeatPort:
            return [ac.Eq(self.heatPort.T, self.T_heatPort),
                    ac.Eq(self.heatPort.Q_flow, -self.LossPower)]
        return []


class IdealSemiconductor(OnePort, ConditionalHeatPort):
    """Ideal semiconductor (Modelica.Electrical.Analog.Interfaces.IdealSemiconductor, MSL
    v4.0.0): a piecewise-linear characteristic in the curve parameter s, blocking (off) a
    conductance Goff, conducting a resistance Ron above the knee Vknee:

        v = s (1 if off else Ron) + Vknee,   i = s (Goff if off else 1) + Goff Vknee
        LossPower = v i

    The subclass gives the Boolean ``off`` by its equation (the diode: off = s < 0); s is
    i - Goff Vknee conducting and v - Vknee blocking, so the characteristic is
    continuous at the knee s = 0 and the switch keeps the number of states.
    """

    Ron = ac.Parameter(1e-5, unit="Ohm", min=0,
                       description="forward state-on differential resistance (closed resistance)")
    Goff = ac.Parameter(1e-5, unit="S", min=0,
                        description="backward state-off conductance (opened conductance)")
    Vknee = ac.Parameter(0.0, unit="V", min=0, description="forward threshold voltage")
    off = ac.Variable(type=bool, start=True, description="switching state")
    s = ac.Variable(start=0.0, description="auxiliary variable for actual position on the "
                                           "ideal diode characteristic")

    def equations(self):
        off = self.off
        return [ac.Eq(self.v, self.s * ac.if_else(off, 1, self.Ron) + self.Vknee),
                ac.Eq(self.i, self.s * ac.if_else(off, self.Goff, 1) + self.Goff * self.Vknee),
                ac.Eq(self.LossPower, self.v * self.i)]


class IdealSwitch(OnePort, ConditionalHeatPort):
    """Ideal electrical switch (Modelica.Electrical.Analog.Interfaces.IdealSwitch, MSL
    v4.0.0), piecewise linear in the curve parameter s:

        v = s (1 if off else Ron),   i = s (Goff if off else 1),   LossPower = v i

    The subclass gives the Boolean ``off`` from its control.
    """

    Ron = ac.Parameter(1e-5, unit="Ohm", min=0, description="closed switch resistance")
    Goff = ac.Parameter(1e-5, unit="S", min=0, description="opened switch conductance")
    off = ac.Variable(type=bool, description="indicates off-state")
    s = ac.Variable(start=0.0, description="auxiliary variable (i when closed, v when open)")

    def equations(self):
        off = self.off
        return [ac.Eq(self.v, self.s * ac.if_else(off, 1, self.Ron)),
                ac.Eq(self.i, self.s * ac.if_else(off, self.Goff, 1)),
                ac.Eq(self.LossPower, self.v * self.i)]


class IdealSwitchWithArc(OnePort, ConditionalHeatPort):
    """Ideal switch with a simple arc model (Modelica.Electrical.Analog.Interfaces.
    IdealSwitchWithArc, MSL v4.0.0).  Closed it is the resistance Ron; opened while
    current flows, an arc holds a voltage rising from V0 at the rate dVdt to at most
    Vmax, against the current, until the current has fallen to what the open switch's
    conductance Goff passes at that voltage (the arc quenches):

        when edge(off):  tSwitch = time
        quenched = off and (|i| <= |v| Goff or pre(quenched))
        off, quenched:       i = Goff v
        off, not quenched:   v = min(Vmax, V0 + dVdt (time - tSwitch)) sign(i)
        not off:             v = Ron i
        LossPower = v i

    The subclass gives ``off`` from its control.
    """

    Ron = ac.Parameter(1e-5, unit="Ohm", description="closed switch resistance")
    Goff = ac.Parameter(1e-5, unit="S", description="opened switch conductance")
    V0 = ac.Parameter(30.0, unit="V", description="initial arc voltage")
    dVdt = ac.Parameter(10e3, unit="V/s", description="arc voltage slope")
    Vmax = ac.Parameter(60.0, unit="V", description="max. arc voltage")
    unitVoltage = ac.Parameter(1.0, unit="V", description="1 V (the MSL's unitVoltage)")
    unitCurrent = ac.Parameter(1.0, unit="A", description="1 A (the MSL's unitCurrent)")
    off = ac.Variable(type=bool, start=True,
                      description="indicates off-state (but maybe not quenched)")
    quenched = ac.Variable(type=bool, start=True, fixed=True,
                           description="indicating quenched arc (if switch is off)")
    tSwitch = ac.Variable(discrete=True, start=-1e60, fixed=True, unit="s",
                          description="last switch off time instant (the MSL's start is "
                                      "-inf)")

    def equations(self):
        v, i, off, quenched = self.v, self.i, self.off, self.quenched
        arc = ac.min(self.Vmax, self.V0 + self.dVdt * (ac.time - self.tSwitch)) * ac.sign(i)
        ohm = self.unitVoltage / self.unitCurrent   # the current branch in volts
        return [ac.when(ac.edge(off), ac.assign(self.tSwitch, ac.time)),
                ac.Eq(quenched, off & ((ac.abs(i) <= ac.abs(v) * self.Goff)
                                       | ac.pre(quenched))),
                # the MSL's if-equation: one equation, its law chosen by off and quenched
                ac.Eq(0, ac.if_else(off, ac.if_else(quenched, (i - self.Goff * v) * ohm,
                                                    v - arc),
                                    v - self.Ron * i)),
                ac.Eq(self.LossPower, v * i)]
