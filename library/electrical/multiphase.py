"""Polyphase circuits (Modelica.Electrical.Polyphase, MSL v4.0.0): plugs of m pins and the
components the MSL builds of m single-phase ones, as the MSL's Blocks.Examples
Rectifier6pulseFFT and Rectifier12pulseFFT use them.

A plug is a port made of ports: ``connect(a.plug_p, b.plug_n)`` connects the pins
``pin[0] ... pin[m-1]`` one by one (the MSL's ``pin[1] ... pin[m]``).  Each component
holds its m single-phase components in a list under the MSL's name (``resistor[k]``,
``inductor[k]``, ``idealDiode[k]``, ``sineVoltage[k]``, ``currentSensor[k]``), so their
variables read as the MSL's (``l2sigma.inductor[0].i``).  The MSL's per-phase parameter
vectors (``R[m]``, ``V[m]``, ...) are one value for every phase here (its examples give
``fill(x, m)``); the source's phases are a list.  ``m`` is structural, given where the
component is made.
"""
import math

import acausal as ac
from acausal.ports import NegativePin, Pin, RealOutput

from .basic import Inductor as _Inductor
from .basic import Resistor as _Resistor
from .ideal import IdealDiode as _IdealDiode
from .sensors import CurrentSensor as _CurrentSensor
from .sources import SineVoltage as _SineVoltage

__all__ = ["Plug", "PositivePlug", "NegativePlug", "TwoPlug", "Star", "Delta", "Resistor",
           "Inductor", "IdealDiode", "SineVoltage", "CurrentSensor", "symmetricOrientation"]


def symmetricOrientation(m: int) -> list:
    """The orientations of the fundamental waves of a symmetric m-phase system (MSL
    Polyphase.Functions.symmetricOrientation): (k - 1) 2 pi/m for odd m; for even m the
    two halves of m/2 phases, the second turned by -pi/m (m = 2: 0, pi/2)."""
    if m % 2:
        return [k * 2 * math.pi / m for k in range(m)]
    if m == 2:
        return [0.0, math.pi / 2]
    half = symmetricOrientation(m // 2)
    return half + [x - math.pi / m for x in half]


class Plug(ac.Port):
    """Polyphase electrical plug with m pins (MSL Polyphase.Interfaces.Plug): a port made
    of the pins ``pin[0] ... pin[m-1]``, connected pin by pin."""

    m = ac.Parameter(3, structural=True, min=1, description="number of phases")

    def build(self):
        self.pin = [Pin() for _ in range(int(self.m))]


class PositivePlug(Plug):
    """Positive polyphase electrical plug with m pins (MSL Polyphase.Interfaces.PositivePlug)."""


class NegativePlug(Plug):
    """Negative polyphase electrical plug with m pins (MSL Polyphase.Interfaces.NegativePlug)."""


class _Polyphase(ac.Component):
    """A component of m phases (its ``m`` structural)."""

    m = ac.Parameter(3, structural=True, min=1, description="number of phases")

    def phases(self) -> range:
        return range(int(self.m))


class TwoPlug(_Polyphase):
    """A component with two polyphase plugs, plug_p and plug_n (MSL
    Polyphase.Interfaces.TwoPlug, without its vectors v and i: each phase's component
    has its own)."""

    def build(self):
        self.plug_p = PositivePlug(m=self.m)
        self.plug_n = NegativePlug(m=self.m)


class Star(_Polyphase):
    """Star connection (MSL Polyphase.Basic.Star): every pin of plug_p connected to
    pin_n."""

    pin_n = NegativePin()

    def build(self):
        self.plug_p = PositivePlug(m=self.m)

    def equations(self):
        return [ac.connect(self.plug_p.pin[j], self.pin_n) for j in self.phases()]


class Delta(TwoPlug):
    """Delta (polygon) connection (MSL Polyphase.Basic.Delta): plug_n.pin[j] to
    plug_p.pin[j+1], the last to the first."""

    def equations(self):
        m = int(self.m)
        return [ac.connect(self.plug_n.pin[j], self.plug_p.pin[(j + 1) % m])
                for j in range(m)]


class Resistor(TwoPlug):
    """Ideal linear electrical resistors, one per phase (MSL Polyphase.Basic.Resistor;
    without the heat port: each at its reference temperature)."""

    R = ac.Parameter(1.0, unit="Ohm", description="resistance R_ref at temperature T_ref")
    T_ref = ac.Parameter(300.15, unit="K", min=0, description="reference temperature")
    alpha = ac.Parameter(0.0, unit="1/K", description="temperature coefficient of "
                                                      "resistance at the reference temperature")

    def build(self):
        super().build()
        self.resistor = [_Resistor(R=ac.ref("R"), T_ref=ac.ref("T_ref"),
                                   alpha=ac.ref("alpha")) for _ in self.phases()]

    def equations(self):
        return [[ac.connect(r.p, self.plug_p.pin[j]), ac.connect(r.n, self.plug_n.pin[j])]
                for j, r in enumerate(self.resistor)]


class Inductor(TwoPlug):
    """Ideal linear electrical inductors, one per phase (MSL Polyphase.Basic.Inductor)."""

    L = ac.Parameter(1.0, unit="H", description="inductance")

    def build(self):
        super().build()
        self.inductor = [_Inductor(L=ac.ref("L")) for _ in self.phases()]

    def equations(self):
        return [[ac.connect(c.p, self.plug_p.pin[j]), ac.connect(c.n, self.plug_n.pin[j])]
                for j, c in enumerate(self.inductor)]


class IdealDiode(TwoPlug):
    """Ideal diodes, one per phase (MSL Polyphase.Ideal.IdealDiode; each the analog
    IdealDiode, piecewise linear in its curve parameter, without the heat port)."""

    Ron = ac.Parameter(1e-5, unit="Ohm", min=0, description="closed diode resistance")
    Goff = ac.Parameter(1e-5, unit="S", min=0, description="opened diode conductance")
    Vknee = ac.Parameter(0.0, unit="V", min=0, description="threshold voltage")

    def build(self):
        super().build()
        self.idealDiode = [_IdealDiode(Ron=ac.ref("Ron"), Goff=ac.ref("Goff"),
                                       Vknee=ac.ref("Vknee")) for _ in self.phases()]

    def equations(self):
        return [[ac.connect(self.plug_p.pin[j], d.p), ac.connect(d.n, self.plug_n.pin[j])]
                for j, d in enumerate(self.idealDiode)]


class SineVoltage(TwoPlug):
    """Polyphase sine voltage source (MSL Polyphase.Sources.SineVoltage): m analog
    SineVoltage sources, v[k] = offset + V sin(2 pi f (time - startTime) + phase[k]),
    the phases by default -symmetricOrientation(m) (0, -2 pi/3, -4 pi/3 for m = 3)."""

    V = ac.Parameter(1.0, unit="V", description="amplitude of the sine waves")
    f = ac.Parameter(1.0, unit="Hz", description="frequency of the sine waves")
    offset = ac.Parameter(0.0, unit="V", description="voltage offset")
    startTime = ac.Parameter(0.0, unit="s", description="time offset")
    phase = ac.Parameter((), structural=True,
                         description="phases of the sine waves [rad] (default "
                                     "-symmetricOrientation(m))")

    def build(self):
        super().build()
        phases = [float(x) for x in self.phase] or \
            [-x for x in symmetricOrientation(int(self.m))]
        if len(phases) != int(self.m):
            raise ac.InvalidValue(f"SineVoltage: phase has {len(phases)} values for m = "
                                  f"{int(self.m)} phases")
        self.sineVoltage = [_SineVoltage(V=ac.ref("V"), f=ac.ref("f"), phase=p,
                                         offset=ac.ref("offset"),
                                         startTime=ac.ref("startTime")) for p in phases]

    def equations(self):
        return [[ac.connect(s.p, self.plug_p.pin[j]), ac.connect(s.n, self.plug_n.pin[j])]
                for j, s in enumerate(self.sineVoltage)]


class CurrentSensor(TwoPlug):
    """Polyphase current sensor (MSL Polyphase.Sensors.CurrentSensor): the current of
    each phase from plug_p to plug_n as the output ``i[k]``."""

    def build(self):
        super().build()
        self.currentSensor = [_CurrentSensor() for _ in self.phases()]
        self.i = [RealOutput() for _ in self.phases()]

    def equations(self):
        return [[ac.connect(self.plug_p.pin[j], s.p), ac.connect(s.n, self.plug_n.pin[j]),
                 ac.connect(s.i, self.i[j])] for j, s in enumerate(self.currentSensor)]
